// dds_server_step_publisher DOMAIN RIG COUNT RATE_HZ px py pz qw qx qy qz dx dy dz:
// for mhd-dds-force-latency-bench. Once a reader has matched, publishes COUNT tracker
// samples of sensor 0 at RATE_HZ (absolute deadlines), sample i at p + i * d with the
// orientation q, each stamped with dds_time() just before its write, so the stamp is
// the publish time.
#include "dds_common/dds_topics.h"

#include <time.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <thread>

int main(int argc, char** argv) {
  if (argc != 15) {
    std::fprintf(stderr, "usage: %s DOMAIN RIG COUNT RATE_HZ px py pz qw qx qy qz dx dy dz\n", argv[0]);
    return 2;
  }
  const auto domain = static_cast<std::uint32_t>(std::strtoul(argv[1], nullptr, 10));
  const auto rig = static_cast<std::uint32_t>(std::strtoul(argv[2], nullptr, 10));
  const unsigned long count = std::strtoul(argv[3], nullptr, 10);
  const double rate_hz = std::strtod(argv[4], nullptr);
  double v[10];
  for (int i = 0; i < 10; ++i) v[i] = std::strtod(argv[5 + i], nullptr);
  try {
    const mhd::dds::Participant participant(domain);
    mhd::dds::Publisher<mhd_dds_TrackerSample> publisher(participant, mhd::dds::rig_partition(rig));
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (publisher.writer().matched_readers() == 0) {
      if (std::chrono::steady_clock::now() > give_up) {
        std::fprintf(stderr, "dds_server_step_publisher: no reader matched in 10 s\n");
        return 1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the reader's side matches too
    const long period_ns = static_cast<long>(1e9 / rate_hz);
    timespec next{};
    clock_gettime(CLOCK_MONOTONIC, &next);
    for (unsigned long i = 0; i < count; ++i) {
      next.tv_nsec += period_ns;
      while (next.tv_nsec >= 1'000'000'000L) {
        next.tv_nsec -= 1'000'000'000L;
        ++next.tv_sec;
      }
      clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, nullptr);
      mhd_dds_TrackerSample s{};
      s.rig_id = rig;
      s.sensor_id = 0;
      s.sequence_number = i;
      const double k = static_cast<double>(i);
      for (int a = 0; a < 3; ++a) s.p_T_m[a] = v[a] + k * v[7 + a];
      for (int a = 0; a < 4; ++a) s.q_T_wxyz[a] = v[3 + a];
      s.timestamp_ns = mhd::dds::realtime_ns();
      publisher.write(s);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dds_server_step_publisher: %s\n", e.what());
    return 1;
  }
}
