// The tracker-sample checks of dds_common, without a network: each reason, their
// order, the restart rule, the counts and the conversions to and from the ABI.

#include "dds_common/dds_convert.h"
#include "dds_common/dds_entity.h"
#include "dds_common/sample_validation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

namespace mhd::dds {
namespace {

constexpr std::int64_t kNow = 1'700'000'000'000'000'000;
constexpr std::int64_t kMs = 1'000'000;

mhd_dds_TrackerSample good(std::uint64_t sequence, std::int64_t stamp_ns = kNow - 2 * kMs) {
  mhd_dds_TrackerSample s{};
  s.rig_id = 3;
  s.sensor_id = 1;
  s.sequence_number = sequence;
  s.timestamp_ns = stamp_ns;
  s.p_T_m[0] = 0.5;
  s.p_T_m[1] = -1.0;
  s.p_T_m[2] = 1.4;
  s.q_T_wxyz[0] = std::sqrt(0.5);
  s.q_T_wxyz[3] = std::sqrt(0.5);
  return s;
}

TrackerValidationLimits rig3() {
  TrackerValidationLimits l;
  l.rig_id = 3;
  return l;
}

TEST(TrackerSampleValidator, AcceptsAGoodSampleAndCountsIt) {
  TrackerSampleValidator v(rig3());
  EXPECT_EQ(v.check(good(0), kNow), std::nullopt);
  EXPECT_EQ(v.check(good(1), kNow), std::nullopt);
  EXPECT_EQ(v.counts().accepted, 2u);
  EXPECT_EQ(v.counts().dropped_total(), 0u);
  EXPECT_EQ(v.counts().summary(), "accepted 2, dropped 0");
}

TEST(TrackerSampleValidator, DropsEachKindOfBadSampleByItsReason) {
  TrackerSampleValidator v(rig3());
  auto other_rig = good(0);
  other_rig.rig_id = 4;
  EXPECT_EQ(v.check(other_rig, kNow), DropReason::UnknownRig);
  auto nan = good(0);
  nan.p_T_m[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(v.check(nan, kNow), DropReason::NonFinite);
  auto inf_q = good(0);
  inf_q.q_T_wxyz[2] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(v.check(inf_q, kNow), DropReason::NonFinite);
  auto far = good(0);
  far.p_T_m[2] = -20.5;
  EXPECT_EQ(v.check(far, kNow), DropReason::OutOfRange);
  auto sensor = good(0);
  sensor.sensor_id = 32;
  EXPECT_EQ(v.check(sensor, kNow), DropReason::OutOfRange);
  auto q = good(0);
  q.q_T_wxyz[0] = 0.5;
  EXPECT_EQ(v.check(q, kNow), DropReason::BadQuaternion);
  EXPECT_EQ(v.check(good(0, kNow - 150 * kMs), kNow), DropReason::Stale);
  EXPECT_EQ(v.check(good(0, kNow + 20 * kMs), kNow), DropReason::Future);
  EXPECT_EQ(v.counts().accepted, 0u);
  EXPECT_EQ(v.counts().dropped_total(), 8u);
  EXPECT_EQ(v.counts()[DropReason::NonFinite], 2u);
  EXPECT_EQ(v.counts().summary(),
            "accepted 0, dropped 8 (unknown_rig 1, non_finite 2, out_of_range 2, bad_quaternion 1, stale 1, future 1)");
}

TEST(TrackerSampleValidator, TimestampsAtTheEndsOfTheRangeAreStaleOrFutureWithoutOverflow) {
  // A peer may send any 64-bit stamp; now - stamp must not overflow (found by fuzzing).
  TrackerSampleValidator v(rig3());
  EXPECT_EQ(v.check(good(0, std::numeric_limits<std::int64_t>::min()), kNow), DropReason::Stale);
  EXPECT_EQ(v.check(good(0, std::numeric_limits<std::int64_t>::max()), -kNow), DropReason::Future);
  EXPECT_EQ(v.check(good(0, std::numeric_limits<std::int64_t>::max()), kNow), DropReason::Future);
  EXPECT_EQ(v.counts().dropped_total(), 3u);
}

TEST(TrackerSampleValidator, WithinTheLimitsIsAccepted) {
  TrackerSampleValidator v(rig3());
  auto edge = good(0, kNow - 99 * kMs);
  edge.p_T_m[0] = 20.0;
  edge.q_T_wxyz[0] *= 1.0009;
  EXPECT_EQ(v.check(edge, kNow), std::nullopt);
  EXPECT_EQ(v.check(good(1, kNow + 9 * kMs), kNow), std::nullopt);
}

TEST(TrackerSampleValidator, ASequenceGoingBackwardsOrRepeatedIsDroppedPerSensor) {
  TrackerSampleValidator v(rig3());
  ASSERT_EQ(v.check(good(10), kNow), std::nullopt);
  EXPECT_EQ(v.check(good(9), kNow + kMs), DropReason::SequenceBackwards);
  EXPECT_EQ(v.check(good(10), kNow + kMs), DropReason::SequenceBackwards);
  auto other_sensor = good(2);
  other_sensor.sensor_id = 0;
  EXPECT_EQ(v.check(other_sensor, kNow + kMs), std::nullopt);  // its own sequence
  EXPECT_EQ(v.check(good(12), kNow + 2 * kMs), std::nullopt);  // a gap is fine
  EXPECT_EQ(v.counts()[DropReason::SequenceBackwards], 2u);
}

TEST(TrackerSampleValidator, ASequenceStartsOverAfterASilenceLongerThanTheRestartTime) {
  TrackerSampleValidator v(rig3());
  ASSERT_EQ(v.check(good(500), kNow), std::nullopt);
  const std::int64_t later = kNow + 300 * kMs;  // > restart_after_s = 0.25 s
  EXPECT_EQ(v.check(good(0, later - 2 * kMs), later), std::nullopt);
  EXPECT_EQ(v.check(good(0, later - kMs), later + kMs), DropReason::SequenceBackwards);
  EXPECT_EQ(v.check(good(1, later), later + kMs), std::nullopt);
}

TEST(DdsConvert, HostAndRealtimeClocksMapBothWays) {
  const double host_now_s = 12.5;
  EXPECT_EQ(realtime_from_host(12.25, host_now_s, kNow), kNow - 250 * kMs);
  EXPECT_DOUBLE_EQ(host_from_realtime(kNow - 250 * kMs, host_now_s, kNow), 12.25);
}

TEST(DdsConvert, ATrackerSampleRoundTrips) {
  mhd_tracker_sample s{7, 42, 3.0, {1.0, 2.0, 3.0}, {0.0, 1.0, 0.0, 0.0}};
  const mhd_dds_TrackerSample d = to_dds(s, 9, kNow);
  EXPECT_EQ(d.rig_id, 9u);
  EXPECT_EQ(d.sensor_id, 7u);
  EXPECT_EQ(d.sequence_number, 42u);
  EXPECT_EQ(d.timestamp_ns, kNow);
  const mhd_tracker_sample back = from_dds(d, 3.5);
  EXPECT_EQ(back.sensor_id, 7u);
  EXPECT_EQ(back.sequence, 42u);
  EXPECT_EQ(back.timestamp_s, 3.5);
  EXPECT_EQ(back.p_T_m[2], 3.0);
  EXPECT_EQ(back.q_T_wxyz[1], 1.0);
}

TEST(DdsConvert, ADisplayFrameRoundTripsAsRigState) {
  mhd_display_frame f{};
  f.timestamp_s = 1.0;
  f.p_W_hip_m[1] = 1.1;
  f.p_W_proxy_m[1] = 1.05;
  f.force_W_N[1] = 2.5;
  f.in_contact = 1;
  f.base_x_m = 0.3;
  f.base_z_m = -0.2;
  f.base_heading_rad = 0.7;
  f.p_W_head_m[1] = 1.65;
  f.q_W_head_wxyz[0] = 1.0;
  const mhd_dds_RigState d = to_dds(f, 2, 17, kNow);
  EXPECT_EQ(d.rig_id, 2u);
  EXPECT_EQ(d.sequence_number, 17u);
  EXPECT_TRUE(d.in_contact);
  const mhd_display_frame back = from_dds(d, 1.0);
  EXPECT_EQ(back.force_W_N[1], 2.5);
  EXPECT_EQ(back.in_contact, 1);
  EXPECT_EQ(back.base_heading_rad, 0.7);
  EXPECT_EQ(back.p_W_head_m[1], 1.65);
  EXPECT_EQ(back.q_W_head_wxyz[0], 1.0);
}

TEST(DdsConfig, ARelativeConfigFileIsRelativeToTheScene) {
  EXPECT_EQ(config_file_uri("../config/dds.xml", "/work/mhd/scenes/lab.xml"), "file:///work/mhd/config/dds.xml");
  EXPECT_EQ(config_file_uri("/etc/mhd/dds.xml", "/work/mhd/scenes/lab.xml"), "file:///etc/mhd/dds.xml");
  EXPECT_EQ(config_file_uri("dds.xml", nullptr), "file://" + (std::filesystem::current_path() / "dds.xml").string());
}

}  // namespace
}  // namespace mhd::dds
