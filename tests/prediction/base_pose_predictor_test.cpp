// Base pose prediction: the per-tick leap of the predicted base (and of a point 0.5 m
// ahead of it, like the HIP) against sample-and-hold, tracking error, out-of-order and
// stale samples, resets, extrapolation limit, heading wrap.

#include "prediction/base_pose_predictor.h"

#include "base_motion_simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

namespace mhd {
namespace {

using test::BaseMotionResult;
using test::BaseMotionScenario;
using test::run_base_motion;

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kLeapLimit_m = 0.05e-3;

BaseMotionScenario straight() { return BaseMotionScenario{}; }

BaseMotionScenario turning() {
  BaseMotionScenario s;
  s.twist_B = BaseTwist{0.2, 0.0, 40.0 * kDeg};
  return s;
}

// The IS-900's worst figures: 3 mm, 0.5 degrees.
BaseMotionScenario worst_noise(BaseMotionScenario s) {
  s.position_noise_m = 0.003;
  s.heading_noise_rad = 0.5 * kDeg;
  return s;
}

void report(const char* name, const BaseMotionResult& r) {
  std::printf("[ figures  ] %s\n%s\n", name, r.summary().c_str());
}

void expect_smooth_and_tracking(const BaseMotionResult& r, double max_error_m) {
  EXPECT_LE(r.predicted_base.max_leap_m, kLeapLimit_m);
  EXPECT_LE(r.predicted_point.max_leap_m, kLeapLimit_m);
  EXPECT_LE(r.predicted_base.max_error_m, max_error_m);
  EXPECT_LE(r.predicted_point.max_error_m, max_error_m);
  // Sample and hold leaps by the base's travel per sample (2 mm) plus the noise.
  EXPECT_GE(r.held_base.max_leap_m, 1.5e-3);
  EXPECT_EQ(r.resets, 1u);  // the first sample only
}

TEST(BasePosePredictor, StraightAt20cmPerSecondLeapsLessThan50Microns) {
  const BaseMotionResult r = run_base_motion(straight());
  report("straight 0.2 m/s, 2.5 mm / 0.4 deg noise", r);
  expect_smooth_and_tracking(r, 3e-3);
}

TEST(BasePosePredictor, TurningAt40DegPerSecondLeapsLessThan50Microns) {
  const BaseMotionResult r = run_base_motion(turning());
  report("turning 0.2 m/s + 40 deg/s, 2.5 mm / 0.4 deg noise", r);
  expect_smooth_and_tracking(r, 3e-3);
}

TEST(BasePosePredictor, WorstTrackerNoiseStillLeapsLessThan50Microns) {
  for (const auto& [name, scenario] : {std::pair{"straight, 3 mm / 0.5 deg noise", worst_noise(straight())},
                                       std::pair{"turning, 3 mm / 0.5 deg noise", worst_noise(turning())}}) {
    SCOPED_TRACE(name);
    const BaseMotionResult r = run_base_motion(scenario);
    report(name, r);
    expect_smooth_and_tracking(r, 4e-3);
  }
}

TEST(BasePosePredictor, WithoutCommandsStillLeapsLessThan50Microns) {
  for (BaseMotionScenario scenario : {straight(), turning()}) {
    scenario.send_commands = false;
    const BaseMotionResult r = run_base_motion(scenario);
    report(scenario.twist_B.omega_radps == 0 ? "straight, no commands" : "turning, no commands", r);
    expect_smooth_and_tracking(r, 4e-3);
  }
}

TEST(BasePosePredictor, ManySeedsStayWithinTheLeapLimit) {
  double worst_leap = 0.0;
  for (std::uint64_t seed = 2; seed < 12; ++seed) {
    for (BaseMotionScenario scenario : {straight(), turning()}) {
      scenario.seed = seed;
      scenario.duration_s = 5.0;
      const BaseMotionResult r = run_base_motion(scenario);
      worst_leap = std::max({worst_leap, r.predicted_base.max_leap_m, r.predicted_point.max_leap_m});
    }
  }
  std::printf("[ figures  ] worst predicted leap over 20 runs: %.4f mm\n", worst_leap * 1e3);
  EXPECT_LE(worst_leap, kLeapLimit_m);
}

TEST(BasePosePredictor, NoiselessStraightMotionIsPredictedExactly) {
  BaseMotionScenario scenario = straight();
  scenario.position_noise_m = 0;
  scenario.heading_noise_rad = 0;
  scenario.late_probability = 0;
  scenario.drop_probability = 0;
  const BaseMotionResult r = run_base_motion(scenario);
  report("straight, no noise", r);
  EXPECT_LT(r.predicted_base.max_error_m, 1e-6);
  EXPECT_LT(r.predicted_base.max_leap_m, 1e-7);
  // Sample and hold, by contrast, leaps by the 2 mm the base travels between samples.
  EXPECT_NEAR(r.held_base.max_leap_m, 0.2 * 0.01 - 0.2 * 0.001, 1e-4);
}

TEST(BasePosePredictor, IgnoresOutOfOrderDuplicateAndInvalidSamples) {
  BasePosePredictor p;
  EXPECT_EQ(p.add_measurement(1.00, {0, 0, 0}), BaseSampleStatus::Reset);
  EXPECT_EQ(p.add_measurement(1.01, {0.002, 0, 0}), BaseSampleStatus::Accepted);
  EXPECT_EQ(p.add_measurement(1.005, {5, 5, 1}), BaseSampleStatus::OutOfOrder);
  EXPECT_EQ(p.add_measurement(1.01, {5, 5, 1}), BaseSampleStatus::OutOfOrder);
  EXPECT_EQ(p.add_measurement(1.02, {std::numeric_limits<double>::quiet_NaN(), 0, 0}), BaseSampleStatus::Invalid);
  EXPECT_EQ(p.add_measurement(std::numeric_limits<double>::infinity(), {0, 0, 0}), BaseSampleStatus::Invalid);
  EXPECT_EQ(p.accepted_count(), 2u);
  EXPECT_EQ(p.ignored_count(), 4u);
  const BasePose out = p.predict(1.01);
  EXPECT_NEAR(out.x_m, 0.002, 1e-12);  // the ignored (5, 5) never got in
  EXPECT_NEAR(out.z_m, 0.0, 1e-12);
  EXPECT_EQ(to_string(BaseSampleStatus::OutOfOrder), "out of order");
}

TEST(BasePosePredictor, ReportsTheAgeOfItsData) {
  BasePosePredictor p;
  EXPECT_FALSE(p.has_estimate());
  EXPECT_TRUE(std::isinf(p.age_s(0.0)));
  EXPECT_TRUE(p.is_stale(0.0, 1.0));
  EXPECT_EQ(p.predict(0.0).x_m, 0.0);
  p.add_measurement(2.0, {1, 2, 0.5});
  EXPECT_TRUE(p.has_estimate());
  EXPECT_NEAR(p.age_s(2.03), 0.03, 1e-12);
  EXPECT_FALSE(p.is_stale(2.03, 0.05));
  EXPECT_TRUE(p.is_stale(2.06, 0.05));
  // Latency the tracker's clock does not cover counts in the age.
  BasePosePredictorSettings settings;
  settings.latency_s = 0.004;
  BasePosePredictor late(settings);
  late.add_measurement(2.0, {1, 2, 0.5});
  EXPECT_NEAR(late.age_s(2.0), 0.004, 1e-12);
}

TEST(BasePosePredictor, FirstSampleIsTakenAsIsAndAJumpRestarts) {
  BasePosePredictor p;
  p.add_measurement(0.0, {1, 2, 0.3});
  const BasePose first = p.predict(0.0);
  EXPECT_DOUBLE_EQ(first.x_m, 1);
  EXPECT_DOUBLE_EQ(first.z_m, 2);
  EXPECT_DOUBLE_EQ(first.heading_rad, 0.3);
  p.add_measurement(0.01, {1, 2, 0.3});
  // A teleport (the base relocated, the tracker re-homed) is not smoothed over.
  EXPECT_EQ(p.add_measurement(0.02, {3, 2, 0.3}), BaseSampleStatus::Reset);
  EXPECT_DOUBLE_EQ(p.predict(0.021).x_m, 3);
  EXPECT_EQ(p.reset_count(), 2u);
  // So is a sample after a long silence.
  EXPECT_EQ(p.add_measurement(5.0, {3.1, 2, 0.3}), BaseSampleStatus::Reset);
}

TEST(BasePosePredictor, CorrectsSmoothlyInsteadOfJumping) {
  BasePosePredictor p;
  for (int k = 0; k <= 100; ++k) p.add_measurement(0.01 * k, {0, 0, 0});
  BasePose previous = p.predict(1.0);
  // The base is found 20 mm off (within the reset distance): the output moves over in
  // steps of hundredths of a millimetre (the correction plus the estimator's transient
  // velocity), where sample and hold would leap the 20 mm at once.
  double max_step = 0;
  for (int i = 1; i <= 3000; ++i) {
    const double t = 1.0 + 0.001 * i;
    if (i % 10 == 0) p.add_measurement(t, {0.02, 0, 0});
    const BasePose out = p.predict(t);
    max_step = std::max(max_step, std::abs(out.x_m - previous.x_m));
    previous = out;
  }
  EXPECT_NEAR(previous.x_m, 0.02, 1e-4);
  std::printf("[ figures  ] 20 mm correction: largest step %.4f mm per tick\n", max_step * 1e3);
  EXPECT_LE(max_step, 0.1e-3);
}

TEST(BasePosePredictor, HoldsThePoseWhenSamplesStop) {
  BasePosePredictor p;
  for (int k = 0; k <= 200; ++k) p.add_measurement(0.01 * k, {0.2 * 0.01 * k, 0, 0});
  const BasePose at_horizon = p.predict(2.0 + p.settings().max_extrapolation_s);
  const BasePose later = p.predict(3.0);
  EXPECT_NEAR(at_horizon.x_m, 0.2 * (2.0 + p.settings().max_extrapolation_s), 1e-3);
  EXPECT_NEAR(later.x_m, at_horizon.x_m, 1e-5);
  EXPECT_TRUE(p.is_stale(3.0, 0.1));
}

TEST(BasePosePredictor, TurnsThroughPlusMinusPiContinuously) {
  BaseMotionScenario scenario = turning();
  scenario.start.heading_rad = std::numbers::pi - 0.5;  // crosses +-pi after ~0.7 s
  scenario.warmup_s = 0.3;
  const BaseMotionResult r = run_base_motion(scenario);
  EXPECT_LE(r.predicted_point.max_leap_m, kLeapLimit_m);
  EXPECT_EQ(r.resets, 1u);
}

TEST(BasePosePredictor, UsesTheCommandWhileItIsFresh) {
  BasePosePredictorSettings settings;
  BasePosePredictor p(settings);
  p.add_command(0.0, {0.2, 0.0, 0.0});
  p.add_measurement(0.0, {0, 0, 0});
  EXPECT_DOUBLE_EQ(p.estimated_twist().vx_mps, 0.2);  // a restart starts from the command
  EXPECT_FALSE(p.add_command(-1.0, {1, 1, 1}));          // older than the latest command
  EXPECT_FALSE(p.add_command(1.0, {std::numeric_limits<double>::quiet_NaN(), 0, 0}));
  BasePosePredictor no_command(settings);
  no_command.add_measurement(0.0, {0, 0, 0});
  EXPECT_DOUBLE_EQ(no_command.estimated_twist().vx_mps, 0.0);
}

}  // namespace
}  // namespace mhd
