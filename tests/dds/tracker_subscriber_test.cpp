// The haptic server's end of the tracker link in one process, on a clock the test sets:
// an accepted sample that waits to be handed out is never handed out past max_age_s.

#include "dds_common/dds_topics.h"
#include "dds_common/tracker_subscriber.h"
#include "dds_test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <span>

namespace mhd::dds {
namespace {

using namespace std::chrono_literals;

constexpr std::uint32_t kRig = 4;
constexpr std::int64_t kMs = 1'000'000;

mhd_dds_TrackerSample sample(std::uint32_t sensor, std::uint64_t sequence, std::int64_t timestamp_ns) {
  mhd_dds_TrackerSample s{};
  s.rig_id = kRig;
  s.sensor_id = sensor;
  s.sequence_number = sequence;
  s.timestamp_ns = timestamp_ns;
  s.q_T_wxyz[0] = 1.0;
  return s;
}

/// A subscriber with a publisher beside it, matched: one sample of sensor 31 has gone
/// through and been handed out.
struct Link {
  Link()
      : domain(test::use_loopback_and_unique_domain(40)),
        pub_side(domain),
        sub_side(domain),
        subscriber(sub_side, limits()),
        publisher(pub_side, rig_partition(kRig)) {
    mhd_tracker_sample out[1];
    const auto end = std::chrono::steady_clock::now() + 5s;
    for (std::uint64_t seq = 1; std::chrono::steady_clock::now() < end; ++seq) {
      const std::int64_t now_ns = realtime_ns();
      publisher.write(sample(31, seq, now_ns));
      subscriber.wait(DDS_MSECS(20));
      if (subscriber.poll(out, 0.0, now_ns) == 1) return;
    }
    ADD_FAILURE() << "the publisher never matched";
  }
  static TrackerValidationLimits limits() {
    TrackerValidationLimits l;
    l.rig_id = kRig;
    l.max_age_s = 0.1;
    return l;
  }
  /// Polls with no room to hand anything out, at `now_ns`, until `accepted` samples
  /// in all were accepted (or 3 s passed): they then wait in the subscriber.
  void take_until_accepted(std::uint64_t accepted, std::int64_t now_ns) {
    const auto end = std::chrono::steady_clock::now() + 3s;
    while (subscriber.counts().accepted < accepted && std::chrono::steady_clock::now() < end) {
      subscriber.wait(DDS_MSECS(10));
      (void)subscriber.poll(std::span<mhd_tracker_sample>{}, 0.0, now_ns);
    }
    ASSERT_EQ(subscriber.counts().accepted, accepted);
  }

  std::uint32_t domain;
  Participant pub_side;
  Participant sub_side;
  TrackerSubscriber subscriber;
  Publisher<mhd_dds_TrackerSample> publisher;
};

TEST(TrackerSubscriber, ASampleThatWaitedPastMaxAgeIsDroppedAsStaleNotHandedOut) {
  Link link;
  const std::int64_t t0_ns = realtime_ns();
  for (std::uint32_t sensor = 0; sensor < 8; ++sensor) link.publisher.write(sample(sensor, 1, t0_ns));
  link.take_until_accepted(1 + 8, t0_ns + 10 * kMs);

  // Handed out in time: 50 ms old on the host clock.
  mhd_tracker_sample out[16];
  ASSERT_EQ(link.subscriber.poll(std::span(out, 3), 100.0, t0_ns + 50 * kMs), 3u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(out[i].timestamp_s, 100.0 - 0.05, 1e-9);
  EXPECT_EQ(link.subscriber.counts()[DropReason::Stale], 0u);

  // The other five waited until they were 150 ms old: none is handed out.
  EXPECT_EQ(link.subscriber.poll(out, 100.1, t0_ns + 150 * kMs), 0u);
  EXPECT_EQ(link.subscriber.counts()[DropReason::Stale], 5u);
  EXPECT_EQ(link.subscriber.counts().accepted, 1u + 3u);
  EXPECT_FALSE(link.subscriber.wait(0));

  // A fresh sample of the same sensors comes through again.
  link.publisher.write(sample(5, 2, t0_ns + 140 * kMs));
  link.take_until_accepted(1 + 3 + 1, t0_ns + 150 * kMs);
  ASSERT_EQ(link.subscriber.poll(out, 100.1, t0_ns + 150 * kMs), 1u);
  EXPECT_EQ(out[0].sensor_id, 5u);
  EXPECT_NEAR(out[0].timestamp_s, 100.1 - 0.01, 1e-9);
}

TEST(TrackerSubscriber, ASampleExactlyMaxAgeOldWhenHandedOutStillCounts) {
  Link link;
  const std::int64_t t0_ns = realtime_ns();
  link.publisher.write(sample(0, 1, t0_ns));
  link.publisher.write(sample(1, 1, t0_ns));
  link.take_until_accepted(1 + 2, t0_ns);
  mhd_tracker_sample out[4];
  ASSERT_EQ(link.subscriber.poll(out, 7.0, t0_ns + 100 * kMs), 2u);
  EXPECT_GE(out[0].timestamp_s, 7.0 - 0.1);
  EXPECT_EQ(link.subscriber.counts()[DropReason::Stale], 0u);
}

}  // namespace
}  // namespace mhd::dds
