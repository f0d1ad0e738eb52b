// mhd-dds-monitor: what one rig puts on a DDS domain, once a second. A check of the
// three processes (tracker server, haptic server, viewers) without a viewer:
//
//   mhd-dds-monitor [--rig-id ID] [--domain-id D] [--duration S]
//
// prints, per second, the tracker samples of the rig that pass validation (per sensor)
// and the drop counts so far, and the rig states received with the last one's hand,
// force and contact. Exit status 0, or 1 when nothing of the rig arrived at all.

#include "dds_common/dds_convert.h"
#include "dds_common/tracker_subscriber.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <optional>
#include <string>
#include <thread>

namespace {

struct Options {
  std::uint32_t rig_id = 0;
  dds_domainid_t domain_id = DDS_DOMAIN_DEFAULT;
  std::optional<double> duration_s;
};

int monitor(const Options& o) {
  using namespace mhd::dds;
  const Participant participant(o.domain_id);
  TrackerValidationLimits limits;
  limits.rig_id = o.rig_id;
  TrackerSubscriber tracker(participant, limits);
  Subscriber<mhd_dds_RigState> state(participant, rig_partition(o.rig_id));

  const auto start = std::chrono::steady_clock::now();
  auto next_print = start + std::chrono::seconds(1);
  std::map<std::uint32_t, std::uint64_t> per_sensor;
  std::uint64_t states = 0;
  std::uint64_t total = 0;
  std::optional<mhd_dds_RigState> last_state;
  mhd_tracker_sample buffer[64];
  for (;;) {
    const auto now = std::chrono::steady_clock::now();
    if (o.duration_s && now - start >= std::chrono::duration<double>(*o.duration_s)) break;
    for (std::size_t n; (n = tracker.poll(buffer, 0.0, realtime_ns())) > 0;) {
      for (std::size_t i = 0; i < n; ++i) ++per_sensor[buffer[i].sensor_id];
      total += n;
    }
    for (const mhd_dds_RigState& s : state.reader().take()) {
      if (s.rig_id != o.rig_id) continue;
      ++states;
      ++total;
      last_state = s;
    }
    if (now >= next_print) {
      std::string sensors;
      for (const auto& [id, count] : per_sensor) sensors += " sensor " + std::to_string(id) + ": " + std::to_string(count);
      std::printf("rig %u tracker/s:%s (%s)\n", static_cast<unsigned>(o.rig_id), sensors.empty() ? " none" : sensors.c_str(),
                  tracker.counts().summary().c_str());
      if (last_state) {
        const mhd_dds_RigState& s = *last_state;
        std::printf("rig %u state/s: %llu  hip %.3f %.3f %.3f m  force %.2f N  %s  base %.2f %.2f m %.0f deg\n",
                    static_cast<unsigned>(o.rig_id), static_cast<unsigned long long>(states), s.p_W_hip_m[0],
                    s.p_W_hip_m[1], s.p_W_hip_m[2], std::hypot(s.force_W_N[0], s.force_W_N[1], s.force_W_N[2]),
                    s.in_contact ? "contact" : "free", s.base_x_m, s.base_z_m, s.base_heading_rad * 180.0 / M_PI);
      } else {
        std::printf("rig %u state/s: 0\n", static_cast<unsigned>(o.rig_id));
      }
      std::fflush(stdout);
      per_sensor.clear();
      states = 0;
      next_print += std::chrono::seconds(1);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return total > 0 || tracker.counts().accepted > 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    char* end = nullptr;
    const double v = std::strtod(argv[i + 1], &end);
    if (end == argv[i + 1] || *end != '\0' || !(v >= 0.0)) {
      std::fprintf(stderr, "mhd-dds-monitor: %s needs a non-negative number, got '%s'\n", argv[i], argv[i + 1]);
      return 2;
    }
    if (flag == "--rig-id" && v <= 4294967295.0) o.rig_id = static_cast<std::uint32_t>(v);
    else if (flag == "--domain-id" && v <= 232.0) o.domain_id = static_cast<dds_domainid_t>(v);
    else if (flag == "--duration" && v > 0.0) o.duration_s = v;
    else {
      std::fprintf(stderr, "usage: mhd-dds-monitor [--rig-id ID] [--domain-id 0..232] [--duration S]\n");
      return 2;
    }
  }
  if (argc % 2 == 0) {
    std::fprintf(stderr, "usage: mhd-dds-monitor [--rig-id ID] [--domain-id 0..232] [--duration S]\n");
    return 2;
  }
  try {
    return monitor(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mhd-dds-monitor: error: %s\n", e.what());
    return 1;
  }
}
