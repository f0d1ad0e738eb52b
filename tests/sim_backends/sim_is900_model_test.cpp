#include "sim_is900_model.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace mhd::sim_is900 {
namespace {

constexpr double kHalfTurn = std::numbers::pi;

WorldTruth truth_at(double base_x_m) {
  WorldTruth t;
  t.base_x_m = base_x_m;
  t.base_z_m = 2.0;
  t.base_heading_rad = 0.5;
  t.p_W_head = Eigen::Vector3d(0.3, 1.65, -0.2);
  t.q_W_head = Eigen::Quaterniond(Eigen::AngleAxisd(0.8, Eigen::Vector3d::UnitY()));
  return t;
}

/// Tracker frame = world, base sensor 0.7 m above the base's origin.
Is900Config world_frame() {
  Is900Config c;
  c.X_WT = Eigen::Isometry3d::Identity();
  c.X_BS = Eigen::Translation3d(0.0, 0.7, 0.0);
  return c;
}

Is900Config noiseless() {
  Is900Config c = world_frame();
  c.position_sigma_m = 0.0;
  c.angle_sigma_rad = 0.0;
  return c;
}

std::vector<mhd_tracker_sample> read_all(Is900Model& m) {
  std::vector<mhd_tracker_sample> out(4096);
  out.resize(m.read(out));
  return out;
}

Eigen::Vector3d position(const mhd_tracker_sample& s) { return {s.p_T_m[0], s.p_T_m[1], s.p_T_m[2]}; }
Eigen::Quaterniond rotation(const mhd_tracker_sample& s) {
  return {s.q_T_wxyz[0], s.q_T_wxyz[1], s.q_T_wxyz[2], s.q_T_wxyz[3]};
}

TEST(Is900Model, SamplesBothSensorsAt180HzWithSequenceNumbers) {
  Is900Config c = noiseless();
  c.buffer_capacity = 1024;  // a whole second unread
  Is900Model m(c);
  m.start(5.0, truth_at(1.0));
  m.simulate_until(6.0, truth_at(1.0));
  const auto samples = read_all(m);
  // Measured at 5 + k/180 for k = 0..180; readable 4 ms later: k = 0..179.
  ASSERT_EQ(samples.size(), 2u * 180u);
  std::map<std::uint32_t, std::vector<mhd_tracker_sample>> by_sensor;
  for (const auto& s : samples) by_sensor[s.sensor_id].push_back(s);
  ASSERT_EQ(by_sensor.size(), 2u);
  for (const auto& [id, list] : by_sensor) {
    ASSERT_EQ(list.size(), 180u);
    for (std::size_t k = 0; k < list.size(); ++k) {
      EXPECT_EQ(list[k].sequence, k);
      EXPECT_NEAR(list[k].timestamp_s, 5.0 + static_cast<double>(k) / 180.0, 1e-12);
    }
  }
  EXPECT_EQ(m.buffered(), 2u);  // k = 180, still in flight
}

TEST(Is900Model, ADropoutSilencesOneSensorForItsWindowOnly) {
  Is900Config c = noiseless();
  c.buffer_capacity = 1024;
  c.dropout_sensor_id = c.head_sensor_id;
  c.dropout_start_s = 0.25;
  c.dropout_duration_s = 0.5;
  Is900Model m(c);
  m.start(5.0, truth_at(1.0));
  m.simulate_until(6.0, truth_at(1.0));
  std::vector<double> head_t_s, base_t_s;
  for (const auto& s : read_all(m)) (s.sensor_id == c.head_sensor_id ? head_t_s : base_t_s).push_back(s.timestamp_s - 5.0);
  EXPECT_EQ(base_t_s.size(), 180u);  // the other sensor keeps its rate
  ASSERT_FALSE(head_t_s.empty());
  for (const double t : head_t_s) EXPECT_TRUE(t < 0.25 - 1e-9 || t >= 0.75 - 1e-9) << t;
  // 0.25 s before and 0.25 s after the window (k = 0..44 and 135..179).
  EXPECT_EQ(head_t_s.size(), 45u + 45u);
}

TEST(Is900Model, ASampleBecomesReadableFourMillisecondsAfterItsMeasurement) {
  Is900Model m(noiseless());
  m.start(0.0, truth_at(1.0));
  m.simulate_until(0.0039, truth_at(1.0));
  EXPECT_TRUE(read_all(m).empty());
  EXPECT_EQ(m.buffered(), 2u);
  m.simulate_until(0.004, truth_at(1.0));
  const auto samples = read_all(m);
  ASSERT_EQ(samples.size(), 2u);
  EXPECT_EQ(samples[0].timestamp_s, 0.0);  // the measurement time, not the arrival
  EXPECT_TRUE(read_all(m).empty());         // each sample is read once
}

TEST(Is900Model, MeasuresTheMountedBaseSensorAndTheHeadExactlyWithoutNoise) {
  Is900Config c = noiseless();
  c.X_BS = Eigen::Translation3d(0.1, 0.7, 0.0) * Eigen::AngleAxisd(kHalfTurn / 2, Eigen::Vector3d::UnitY());
  Is900Model m(c);
  m.start(0.0, truth_at(1.0));
  m.simulate_until(0.01, truth_at(1.0));
  const auto samples = read_all(m);
  ASSERT_GE(samples.size(), 2u);
  const mhd_tracker_sample& base = samples[0].sensor_id == 0 ? samples[0] : samples[1];
  const mhd_tracker_sample& head = samples[0].sensor_id == 1 ? samples[0] : samples[1];
  // Forward of the base at heading 0.5 is (cos 0.5, 0, -sin 0.5).
  EXPECT_TRUE(position(base).isApprox(Eigen::Vector3d(1.0 + 0.1 * std::cos(0.5), 0.7, 2.0 - 0.1 * std::sin(0.5)), 1e-12));
  EXPECT_TRUE(rotation(base).isApprox(Eigen::Quaterniond(Eigen::AngleAxisd(0.5 + kHalfTurn / 2, Eigen::Vector3d::UnitY())), 1e-12));
  EXPECT_TRUE(position(head).isApprox(truth_at(1.0).p_W_head, 1e-12));
  EXPECT_TRUE(rotation(head).isApprox(truth_at(1.0).q_W_head, 1e-12));
}

TEST(Is900Model, ReportsPosesInTheTrackerFrame) {
  Is900Config c = noiseless();
  // The paper's rig: the IS-900 frame 2.624 m up, axes turned.
  c.X_WT = Eigen::Translation3d(0.0, 2.624, 0.0) * Eigen::AngleAxisd(kHalfTurn / 2, Eigen::Vector3d::UnitZ());
  Is900Model m(c);
  m.start(0.0, truth_at(1.0));
  m.simulate_until(0.01, truth_at(1.0));
  const auto samples = read_all(m);
  for (const auto& s : samples) {
    if (s.sensor_id != 1) continue;
    Eigen::Isometry3d X_TS = Eigen::Isometry3d::Identity();
    X_TS.linear() = rotation(s).toRotationMatrix();
    X_TS.translation() = position(s);
    const Eigen::Isometry3d X_WS = c.X_WT * X_TS;
    EXPECT_TRUE(X_WS.translation().isApprox(truth_at(1.0).p_W_head, 1e-12));
    EXPECT_TRUE(Eigen::Quaterniond(X_WS.linear()).isApprox(truth_at(1.0).q_W_head, 1e-12));
  }
}

// scenes/rigs/pomhi.xml: with the base at the world origin, heading 0, the base sensor
// is at its nominal pose in the IS-900 frame, position (206, 0, 1443.2) mm, rpy (180, 0, 180) deg.
TEST(Is900Model, DefaultsFollowTheThesisRig) {
  Is900Config c;
  c.position_sigma_m = 0.0;
  c.angle_sigma_rad = 0.0;
  Is900Model m(c);
  WorldTruth truth;  // base at the origin, heading 0
  truth.p_W_head = Eigen::Vector3d(0.0, 1.65, 0.0);
  m.start(0.0, truth);
  m.simulate_until(0.01, truth);
  const auto samples = read_all(m);
  ASSERT_EQ(samples.size(), 4u);
  const mhd_tracker_sample& base = samples[0];
  ASSERT_EQ(base.sensor_id, 0u);
  EXPECT_TRUE(position(base).isApprox(Eigen::Vector3d(0.206, 0.0, 1.4432), 1e-12));
  const Eigen::Quaterniond nominal(Eigen::AngleAxisd(kHalfTurn, Eigen::Vector3d::UnitZ()) *
                                   Eigen::AngleAxisd(kHalfTurn, Eigen::Vector3d::UnitX()));
  EXPECT_LT(rotation(base).angularDistance(nominal), 1e-12);
  // The head, 1.65 m up, is 0.974 m below the ceiling station, along the IS-900's +z.
  EXPECT_LT((position(samples[1]) - Eigen::Vector3d(0.0, 0.0, 2.624 - 1.65)).norm(), 1e-12);
}

TEST(Is900Model, InterpolatesTheWorldBetweenCalls) {
  Is900Model m(noiseless());
  m.start(0.0, truth_at(0.0));
  m.simulate_until(1.0, truth_at(1.8));  // the base moved 1.8 m in x over 1 s
  for (const auto& s : read_all(m)) {
    if (s.sensor_id != 0) continue;
    EXPECT_NEAR(s.p_T_m[0], 1.8 * s.timestamp_s, 1e-12);
  }
}

TEST(Is900Model, NoiseHasTheConfiguredSpread) {
  const Is900Config c = world_frame();  // 2.5 mm, 0.35 deg
  Is900Model m(c);
  const WorldTruth truth = truth_at(1.0);
  m.start(0.0, truth);
  double position_squares = 0.0;
  Eigen::Vector3d position_sum = Eigen::Vector3d::Zero();
  double angle_squares = 0.0;
  int n = 0;
  std::vector<mhd_tracker_sample> out(512);
  for (int step = 1; step <= 60; ++step) {
    m.simulate_until(step * 0.5, truth);
    for (std::size_t i = 0, count = m.read(out); i < count; ++i) {
      if (out[i].sensor_id != 1) continue;
      const Eigen::Vector3d error = position(out[i]) - truth.p_W_head;
      position_sum += error;
      position_squares += error.squaredNorm();
      angle_squares += std::pow(rotation(out[i]).angularDistance(truth.q_W_head), 2);
      ++n;
    }
  }
  ASSERT_GT(n, 5000);
  EXPECT_NEAR(std::sqrt(position_squares / (3.0 * n)), 0.0025, 0.0025 * 0.05);
  EXPECT_LT((position_sum / n).norm(), 0.0025 * 0.1);
  EXPECT_NEAR(std::sqrt(angle_squares / (3.0 * n)), 0.35 * kHalfTurn / 180.0, 0.35 * kHalfTurn / 180.0 * 0.05);
}

TEST(Is900Model, AFullBufferDropsTheOldestAndCountsThem) {
  Is900Config c = noiseless();
  c.buffer_capacity = 10;
  Is900Model m(c);
  m.start(0.0, truth_at(1.0));
  m.simulate_until(1.0, truth_at(1.0));  // 181 measurements of 2 sensors
  EXPECT_EQ(m.dropped(), 362u - 10u);
  const auto samples = read_all(m);
  ASSERT_EQ(samples.size(), 8u);  // k = 176..179; k = 180 is in flight
  EXPECT_EQ(samples.front().sequence, 176u);
  EXPECT_EQ(samples.back().sequence, 179u);
}

TEST(Is900Model, TheSameSeedGivesTheSameSamples) {
  const auto run = [](std::uint64_t seed) {
    Is900Config c;
    c.seed = seed;
    Is900Model m(c);
    m.start(0.0, truth_at(1.0));
    m.simulate_until(0.5, truth_at(1.2));
    return read_all(m);
  };
  const auto a = run(3);
  const auto b = run(3);
  const auto other = run(4);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(position(a[i]), position(b[i]));
    EXPECT_EQ(rotation(a[i]).coeffs(), rotation(b[i]).coeffs());
  }
  EXPECT_NE(position(a[0]), position(other[0]));
}

TEST(Is900Model, RejectsABadDropoutWindow) {
  Is900Config c = noiseless();
  c.dropout_start_s = -1.0;
  EXPECT_THROW(Is900Model{c}, std::invalid_argument);
  c.dropout_start_s = 0.0;
  c.dropout_duration_s = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(Is900Model{c}, std::invalid_argument);
}

TEST(Is900Model, RejectsBadSettings) {
  Is900Config c;
  c.head_sensor_id = c.base_sensor_id;
  EXPECT_THROW(Is900Model{c}, std::invalid_argument);
  c = Is900Config{};
  c.buffer_capacity = 0;
  EXPECT_THROW(Is900Model{c}, std::invalid_argument);
}

}  // namespace
}  // namespace mhd::sim_is900
