// The io thread's per-sample checks alone: a good sample is accepted, and each bad kind
// (sensor unknown, time from the future, sequence not moving on, position implausible)
// gets its own verdict; a restarted tracker may number from 0 again.
#include "haptic_server/tracker_sample_filter.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

namespace {

using namespace mhd;

TrackerSampleFilterSettings settings() {
  TrackerSampleFilterSettings s;
  s.base_sensor_id = 0;
  s.head_sensor_id = 1;
  s.tracking_range_m = 50.0;
  return s;
}

TrackerSample sample(std::uint32_t sensor_id, std::uint64_t sequence, double timestamp_s,
                          double x_m = 1.0) {
  TrackerSample s{};
  s.sensor_id = sensor_id;
  s.sequence = sequence;
  s.timestamp_s = timestamp_s;
  s.p_T_m[0] = x_m;
  s.q_T_wxyz[0] = 1.0;
  return s;
}

TEST(TrackerSampleFilter, AcceptsGoodSamplesOfTheBaseAndTheHeadSensor) {
  TrackerSampleFilter filter(settings());
  EXPECT_EQ(filter.check(sample(0, 1, 10.0), 10.001), TrackerSampleVerdict::Accepted);
  EXPECT_EQ(filter.check(sample(1, 7, 10.0), 10.001), TrackerSampleVerdict::Accepted);
  EXPECT_EQ(filter.check(sample(0, 2, 10.001), 10.002), TrackerSampleVerdict::Accepted);
  EXPECT_EQ(filter.check(sample(1, 8, 10.001), 10.002), TrackerSampleVerdict::Accepted);
}

TEST(TrackerSampleFilter, RejectsASensorThatIsNeitherTheBaseNorTheHead) {
  TrackerSampleFilter filter(settings());
  EXPECT_EQ(filter.check(sample(2, 1, 10.0), 10.001), TrackerSampleVerdict::UnknownSensor);
  EXPECT_STREQ(to_string(TrackerSampleVerdict::UnknownSensor), "unknown sensor");
}

TEST(TrackerSampleFilter, TakesTheOtherRigsSensorsEachWithItsOwnSequence) {
  TrackerSampleFilterSettings with_others = settings();
  with_others.other_rigs.rigs[0] = OtherRigSensors{4, 5};
  with_others.other_rigs.rigs[1] = OtherRigSensors{9, 8};
  with_others.other_rigs.count = 2;
  TrackerSampleFilter filter(with_others);
  for (const std::uint32_t id : {4u, 5u, 9u, 8u}) {
    EXPECT_EQ(filter.check(sample(id, 3, 10.0), 10.001), TrackerSampleVerdict::Accepted) << id;
    EXPECT_EQ(filter.check(sample(id, 3, 10.001), 10.002), TrackerSampleVerdict::SequenceBackwards) << id;
  }
  EXPECT_EQ(filter.check(sample(0, 1, 10.0), 10.001), TrackerSampleVerdict::Accepted);  // its own still
  // Dual: a sensor no rig names is still unknown, and one past the declared count too.
  EXPECT_EQ(filter.check(sample(6, 1, 10.0), 10.001), TrackerSampleVerdict::UnknownSensor);
  with_others.other_rigs.count = 1;
  TrackerSampleFilter one_other(with_others);
  EXPECT_EQ(one_other.check(sample(9, 1, 10.0), 10.001), TrackerSampleVerdict::UnknownSensor);
  EXPECT_EQ(one_other.check(sample(5, 1, 10.0), 10.001), TrackerSampleVerdict::Accepted);
}

TEST(TrackerSampleFilter, RejectsATimeMoreThan10msAheadOfTheHostClock) {
  TrackerSampleFilter filter(settings());
  EXPECT_EQ(filter.check(sample(0, 1, 10.0105), 10.0), TrackerSampleVerdict::FromTheFuture);
  EXPECT_EQ(filter.check(sample(0, 2, 10.0095), 10.0), TrackerSampleVerdict::Accepted);  // within the slack
  EXPECT_STREQ(to_string(TrackerSampleVerdict::FromTheFuture), "from the future");
}

TEST(TrackerSampleFilter, RejectsASequenceThatDoesNotMoveOn) {
  TrackerSampleFilter filter(settings());
  ASSERT_EQ(filter.check(sample(0, 5, 10.0), 10.0), TrackerSampleVerdict::Accepted);
  EXPECT_EQ(filter.check(sample(0, 5, 10.001), 10.001), TrackerSampleVerdict::SequenceBackwards);  // repeated
  EXPECT_EQ(filter.check(sample(0, 4, 10.002), 10.002), TrackerSampleVerdict::SequenceBackwards);  // back
  EXPECT_EQ(filter.check(sample(0, 6, 10.003), 10.003), TrackerSampleVerdict::Accepted);
  // Per sensor: the head's numbering is its own.
  EXPECT_EQ(filter.check(sample(1, 1, 10.003), 10.003), TrackerSampleVerdict::Accepted);
  EXPECT_STREQ(to_string(TrackerSampleVerdict::SequenceBackwards), "sequence backwards");
}

TEST(TrackerSampleFilter, AcceptsASequenceStartingAgainAfterTheSensorWasSilentFor250ms) {
  TrackerSampleFilter filter(settings());
  ASSERT_EQ(filter.check(sample(0, 100, 10.0), 10.0), TrackerSampleVerdict::Accepted);
  EXPECT_EQ(filter.check(sample(0, 0, 10.2), 10.2), TrackerSampleVerdict::SequenceBackwards);  // silent 0.2 s
  EXPECT_EQ(filter.check(sample(0, 0, 10.26), 10.26), TrackerSampleVerdict::Accepted);         // silent 0.26 s
  EXPECT_EQ(filter.check(sample(0, 0, 10.27), 10.27), TrackerSampleVerdict::SequenceBackwards);
}

TEST(TrackerSampleFilter, APositionBeyondTheTrackingRangeOrNotFiniteIsImplausible) {
  TrackerSampleFilter filter(settings());
  EXPECT_EQ(filter.check(sample(0, 1, 10.0, 1e9), 10.0), TrackerSampleVerdict::ImplausiblePosition);
  EXPECT_EQ(filter.check(sample(1, 1, 10.0, std::numeric_limits<double>::quiet_NaN()), 10.0),
            TrackerSampleVerdict::ImplausiblePosition);
  EXPECT_EQ(filter.check(sample(0, 2, 10.0, 49.9), 10.0), TrackerSampleVerdict::Accepted);
  EXPECT_STREQ(to_string(TrackerSampleVerdict::ImplausiblePosition), "implausible position");
}

TEST(TrackerSampleFilter, ADroppedSampleIsNeverAFaultAndDoesNotMoveTheSequenceOn) {
  TrackerSampleFilter filter(settings());
  // Far away and unknown, or far away and from the future: dropped, not a fault.
  EXPECT_EQ(filter.check(sample(9, 1, 10.0, 1e9), 10.0), TrackerSampleVerdict::UnknownSensor);
  EXPECT_EQ(filter.check(sample(0, 1, 11.0, 1e9), 10.0), TrackerSampleVerdict::FromTheFuture);
  // The rejected first sample (sequence 1) started the sensor's memory; 1 again is not new.
  EXPECT_EQ(filter.check(sample(0, 1, 10.0), 10.0), TrackerSampleVerdict::SequenceBackwards);
  EXPECT_EQ(filter.check(sample(0, 2, 10.0), 10.0), TrackerSampleVerdict::Accepted);
  // An implausible sample does not move it on either.
  EXPECT_EQ(filter.check(sample(0, 3, 10.0, 1e9), 10.0), TrackerSampleVerdict::ImplausiblePosition);
  EXPECT_EQ(filter.check(sample(0, 3, 10.0), 10.0), TrackerSampleVerdict::Accepted);
}

}  // namespace
