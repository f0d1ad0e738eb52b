// mhd-dds-latency-bench: tracker sample published -> received and validated in another
// process, over Cyclone DDS on this host (use CYCLONEDDS_URI=file://config/cyclonedds-loopback.xml).
// The parent publishes like the tracker server; a forked child takes the samples as the
// `dds` tracker plugin does (TrackerSubscriber), woken by a waitset, and prints the
// median and p99 of receive time - publish time (CLOCK_REALTIME, same host).
//
// With --security DIR (tools/dds_security/make_rig_security.sh DIR 7) both ends run
// under DDS Security: the parent as DIR/identities/tracker-rig7, the child as
// DIR/identities/haptic-rig7 (authenticated, access-controlled, payload encrypted).
//
// With --poll-us P the child instead polls every P microseconds, as the haptic loop
// reads the `dds` tracker (1000 at 1 kHz): the figure then includes the wait for the
// next poll.
//
//   mhd-dds-latency-bench [--samples N] [--rate-hz R] [--domain-id D] [--poll-us P] [--security DIR]

#include "dds_common/tracker_subscriber.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace {

struct Options {
  std::size_t samples = 3000;
  double rate_hz = 1000.0;
  dds_domainid_t domain_id = 77;
  long poll_us = 0;  ///< 0: woken by a waitset
  std::string security_dir;  ///< make_rig_security.sh's output; empty: unsecured
};

/// The identity folder of `name` under --security, or none (unsecured).
std::optional<std::filesystem::path> identity(const Options& o, const char* name) {
  if (o.security_dir.empty()) return std::nullopt;
  return std::filesystem::path(o.security_dir) / "identities" / name;
}

constexpr std::uint32_t kRig = 7;

int subscriber(const Options& o) {
  using namespace mhd::dds;
  const Participant participant(o.domain_id, {}, identity(o, "haptic-rig7"));
  TrackerValidationLimits limits;
  limits.rig_id = kRig;
  TrackerSubscriber sub(participant, limits);
  std::vector<double> latency_us;
  latency_us.reserve(o.samples);
  std::vector<mhd_tracker_sample> out(64);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  std::uint64_t last_sequence = 0;
  while (last_sequence + 1 < o.samples && std::chrono::steady_clock::now() < give_up) {
    if (o.poll_us > 0) {
      std::this_thread::sleep_for(std::chrono::microseconds(o.poll_us));
    } else if (!sub.wait(DDS_MSECS(200))) {
      continue;
    }
    const std::int64_t now_ns = realtime_ns();
    const std::size_t n = sub.poll(out, 0.0, now_ns);
    for (std::size_t i = 0; i < n; ++i) {
      // timestamp_s is on a host clock whose "now" is 0: -age.
      latency_us.push_back(-out[i].timestamp_s * 1e6);
      last_sequence = out[i].sequence;
    }
  }
  if (latency_us.empty()) {
    std::fprintf(stderr, "mhd-dds-latency-bench: no sample arrived (discovery failed?)\n");
    return 1;
  }
  std::sort(latency_us.begin(), latency_us.end());
  const auto at = [&](double q) {
    return latency_us[std::min(latency_us.size() - 1, static_cast<std::size_t>(q * static_cast<double>(latency_us.size())))];
  };
  std::printf("tracker sample publish -> validated in another process (loopback, %s), %zu of %zu samples at %.0f Hz, %s\n",
              participant.secured() ? "DDS Security" : "unsecured", latency_us.size(), o.samples, o.rate_hz,
              o.poll_us > 0 ? ("polled every " + std::to_string(o.poll_us) + " us").c_str() : "waitset");
  std::printf("  median %.1f us   p99 %.1f us   max %.1f us   (%s)\n", at(0.5), at(0.99), latency_us.back(),
              sub.counts().summary().c_str());
  return 0;
}

int publisher(const Options& o) {
  using namespace mhd::dds;
  const Participant participant(o.domain_id, {}, identity(o, "tracker-rig7"));
  Publisher<mhd_dds_TrackerSample> pub(participant, rig_partition(kRig));
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (pub.writer().matched_readers() == 0 && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // let the reader's side match too
  const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(1.0 / o.rate_hz));
  auto next = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < o.samples; ++i) {
    mhd_dds_TrackerSample s{};
    s.rig_id = kRig;
    s.sensor_id = 0;
    s.sequence_number = i;
    s.p_T_m[1] = 1.0;
    s.q_T_wxyz[0] = 1.0;
    s.timestamp_ns = realtime_ns();
    pub.write(s);
    next += period;
    std::this_thread::sleep_until(next);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--samples") o.samples = std::strtoull(argv[i + 1], nullptr, 10);
    else if (flag == "--rate-hz") o.rate_hz = std::strtod(argv[i + 1], nullptr);
    else if (flag == "--domain-id") o.domain_id = static_cast<dds_domainid_t>(std::strtoul(argv[i + 1], nullptr, 10));
    else if (flag == "--poll-us") o.poll_us = std::strtol(argv[i + 1], nullptr, 10);
    else if (flag == "--security") o.security_dir = argv[i + 1];
    else {
      std::fprintf(stderr, "usage: mhd-dds-latency-bench [--samples N] [--rate-hz R] [--domain-id D] [--poll-us P] [--security DIR]\n");
      return 2;
    }
  }
  if (o.samples < 2 || !(o.rate_hz > 0.0) || o.domain_id > 232 || o.poll_us < 0) {
    std::fprintf(stderr, "mhd-dds-latency-bench: need --samples >= 2, --rate-hz > 0, --domain-id <= 232, --poll-us >= 0\n");
    return 2;
  }
  std::fflush(stdout);
  const pid_t child = fork();
  if (child < 0) {
    std::perror("fork");
    return 1;
  }
  try {
    if (child == 0) {
      const int rc = subscriber(o);
      std::fflush(stdout);
      std::_Exit(rc);
    }
    const int rc = publisher(o);
    int status = 0;
    waitpid(child, &status, 0);
    return rc != 0 ? rc : (WIFEXITED(status) ? WEXITSTATUS(status) : 1);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mhd-dds-latency-bench: %s\n", e.what());
    return 1;
  }
}
