// dds_test_lossy_publisher --domain-id D --rig-id R --count N: publishes the scripted
// bad stream of lossy_stream.h (lost, reordered, delayed and corrupt samples) at
// 500 Hz as a tracker server would, once a reader has matched.

#include "dds_common/dds_topics.h"
#include "lossy_stream.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <string>
#include <thread>

namespace {

using mhd::dds::test::LossyKind;

mhd_dds_TrackerSample make(std::uint64_t i, std::uint32_t rig_id) {
  mhd_dds_TrackerSample s{};
  s.rig_id = rig_id;
  s.sensor_id = 0;
  s.sequence_number = i;
  s.timestamp_ns = mhd::dds::realtime_ns();
  s.p_T_m[0] = mhd::dds::test::lossy_x_m(i);
  s.p_T_m[1] = 1.0;
  s.q_T_wxyz[0] = 1.0;
  switch (mhd::dds::test::lossy_kind(i)) {
    case LossyKind::Delayed: s.timestamp_ns -= 300'000'000; break;
    case LossyKind::NonFinite: s.p_T_m[1] = std::numeric_limits<double>::quiet_NaN(); break;
    case LossyKind::OutOfRange: s.p_T_m[2] = 1000.0; break;
    case LossyKind::BadQuaternion: s.q_T_wxyz[0] = 2.0; break;
    case LossyKind::Future: s.timestamp_ns += 1'000'000'000; break;
    case LossyKind::OtherRig: s.rig_id = rig_id + 1; break;
    default: break;
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  std::uint32_t domain_id = 0;
  std::uint32_t rig_id = 0;
  std::uint64_t count = 200;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    const unsigned long long v = std::strtoull(argv[i + 1], nullptr, 10);
    if (flag == "--domain-id") domain_id = static_cast<std::uint32_t>(v);
    else if (flag == "--rig-id") rig_id = static_cast<std::uint32_t>(v);
    else if (flag == "--count") count = v;
  }
  try {
    const mhd::dds::Participant participant(domain_id);
    mhd::dds::Publisher<mhd_dds_TrackerSample> publisher(participant, mhd::dds::rig_partition(rig_id));
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (publisher.writer().matched_readers() == 0) {
      if (std::chrono::steady_clock::now() > give_up) {
        std::fprintf(stderr, "dds_test_lossy_publisher: no reader matched in 10 s\n");
        return 1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));  // the reader's side matches too
    for (std::uint64_t i = 0; i < count; ++i) {
      const LossyKind kind = mhd::dds::test::lossy_kind(i);
      if (kind == LossyKind::Lost) continue;
      if (kind == LossyKind::SwappedLate) {
        if (i + 1 < count) publisher.write(make(i + 1, rig_id));
        publisher.write(make(i, rig_id));
        ++i;  // i + 1 is sent
      } else {
        publisher.write(make(i, rig_id));
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dds_test_lossy_publisher: %s\n", e.what());
    return 1;
  }
}
