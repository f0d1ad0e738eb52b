// A stand-in for the haptic server's dds_state plugin in the viewer's process test:
//   viewer_dds_test_publisher DOMAIN RIG SECONDS
// waits (up to 30 s) for a reader of mhd_rig_state, then publishes one still rig state
// (head at 1.6 m looking along -z, HIP 0.5 m ahead at (0.05, 1.55, -0.5)) at 100 Hz for
// SECONDS and exits 0: a publisher that vanishes. Exit 1 when no reader came.

#include "dds_common/dds_convert.h"
#include "dds_common/dds_topics.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <thread>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s DOMAIN RIG SECONDS\n", argv[0]);
    return 2;
  }
  const auto domain = static_cast<dds_domainid_t>(std::strtoul(argv[1], nullptr, 10));
  const auto rig = static_cast<std::uint32_t>(std::strtoul(argv[2], nullptr, 10));
  const double seconds = std::strtod(argv[3], nullptr);
  mhd::dds::Participant participant(domain);
  mhd::dds::Publisher<mhd_dds_RigState> publisher(participant, mhd::dds::rig_partition(rig));
  const auto wait_end = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (publisher.writer().matched_readers() == 0) {
    if (std::chrono::steady_clock::now() > wait_end) {
      std::fprintf(stderr, "no reader of mhd_rig_state in 30 s\n");
      return 1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  mhd_display_frame f{};
  f.p_W_hip_m[0] = 0.05;
  f.p_W_hip_m[1] = 1.55;
  f.p_W_hip_m[2] = -0.5;
  f.p_W_proxy_m[0] = 0.05;
  f.p_W_proxy_m[1] = 1.55;
  f.p_W_proxy_m[2] = -0.5;
  f.base_z_m = -1.5;
  f.p_W_head_m[1] = 1.6;
  // Heading +90 deg about y: the head's x (gaze) along world -z.
  f.q_W_head_wxyz[0] = std::sqrt(0.5);
  f.q_W_head_wxyz[2] = std::sqrt(0.5);
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  std::uint64_t sequence = 0;
  while (std::chrono::steady_clock::now() < end) {
    publisher.write(mhd::dds::to_dds(f, rig, sequence++, mhd::dds::realtime_ns()));
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  std::printf("published %llu rig states\n", static_cast<unsigned long long>(sequence));
  return 0;
}
