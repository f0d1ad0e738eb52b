#include "safety/force_safety.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using mhd::ForceSafety;
using mhd::ForceSafetyInput;
using mhd::ForceSafetySettings;

constexpr double kDt = 0.001;

ForceSafetySettings settings() {
  ForceSafetySettings s;
  s.max_force_N = 8.5;
  s.tracker_timeout_s = 0.05;
  s.tracker_fade_s = 0.02;
  s.hip_jump_m = 0.01;
  s.fade_in_s = 0.1;
  return s;
}

ForceSafetyInput input(const Eigen::Vector3d& force, double age_s = 0.005,
                       const Eigen::Vector3d& hip = Eigen::Vector3d(0, 1, 0)) {
  ForceSafetyInput in;
  in.dt_s = kDt;
  in.force_W_N = force;
  in.p_W_hip = hip;
  in.tracker_age_s = age_s;
  return in;
}

/// Runs enough fresh ticks for the fade-in to finish.
void settle(ForceSafety& safety, const Eigen::Vector3d& force) {
  for (int i = 0; i < 200; ++i) (void)safety.apply(input(force));
}

TEST(ForceSafety, StartsAtZeroAndFadesInLinearlyOverFadeInTime) {
  ForceSafety safety(settings());
  const Eigen::Vector3d f(0, 4, 0);
  const auto first = safety.apply(input(f));
  EXPECT_NEAR(first.gain, kDt / 0.1, 1e-12);
  for (int i = 1; i < 50; ++i) (void)safety.apply(input(f));
  const auto half = safety.apply(input(f));  // tick 51
  EXPECT_NEAR(half.gain, 51 * kDt / 0.1, 1e-9);
  EXPECT_NEAR(half.force_W_N.y(), 4.0 * half.gain, 1e-12);
  settle(safety, f);
  EXPECT_DOUBLE_EQ(safety.apply(input(f)).gain, 1.0);
}

TEST(ForceSafety, ClampsToTheDeviceLimitKeepingDirection) {
  ForceSafety safety(settings());
  settle(safety, Eigen::Vector3d(0, 1, 0));
  const auto out = safety.apply(input(Eigen::Vector3d(30, 40, 0)));  // 50 N
  EXPECT_TRUE(out.clamped);
  EXPECT_NEAR(out.force_W_N.norm(), 8.5, 1e-12);
  EXPECT_NEAR(out.force_W_N.x() / out.force_W_N.y(), 0.75, 1e-12);
  EXPECT_EQ(safety.counters().clamped_ticks, 1u);
}

TEST(ForceSafety, NonFiniteForceOrHipGivesZeroAndFadesBackIn) {
  ForceSafety safety(settings());
  settle(safety, Eigen::Vector3d(0, 3, 0));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto bad = safety.apply(input(Eigen::Vector3d(nan, 3, 0)));
  EXPECT_TRUE(bad.fault);
  EXPECT_EQ(bad.force_W_N, Eigen::Vector3d::Zero());
  const auto bad_hip = safety.apply(input(Eigen::Vector3d(0, 3, 0), 0.005, Eigen::Vector3d(0, nan, 0)));
  EXPECT_TRUE(bad_hip.fault);
  EXPECT_EQ(bad_hip.force_W_N, Eigen::Vector3d::Zero());
  const auto back = safety.apply(input(Eigen::Vector3d(0, 3, 0)));
  EXPECT_FALSE(back.fault);
  EXPECT_NEAR(back.gain, kDt / 0.1, 1e-12);  // no step back to full force
  EXPECT_EQ(safety.counters().fault_ticks, 2u);
}

TEST(ForceSafety, StaleTrackingFadesToExactlyZeroAtTheTimeout) {
  ForceSafety safety(settings());
  const Eigen::Vector3d f(0, 5, 0);
  settle(safety, f);
  EXPECT_DOUBLE_EQ(safety.apply(input(f, 0.030)).gain, 1.0);          // fade starts at 30 ms
  EXPECT_NEAR(safety.apply(input(f, 0.040)).gain, 0.5, 1e-9);         // half way
  EXPECT_NEAR(safety.apply(input(f, 0.049)).gain, 0.05, 1e-9);
  const auto stale = safety.apply(input(f, 0.050));
  EXPECT_TRUE(stale.stale);
  EXPECT_EQ(stale.force_W_N, Eigen::Vector3d::Zero());
  const auto never = safety.apply(input(f, std::numeric_limits<double>::infinity()));
  EXPECT_TRUE(never.stale);
  EXPECT_EQ(never.force_W_N, Eigen::Vector3d::Zero());
  // Fresh again: fades in, never jumps back.
  EXPECT_NEAR(safety.apply(input(f)).gain, kDt / 0.1, 1e-12);
}

TEST(ForceSafety, ALateSampleBringsTheFadedForceBackNoFasterThanItFaded) {
  ForceSafety safety(settings());
  const Eigen::Vector3d f(0, 5, 0);
  settle(safety, f);
  EXPECT_NEAR(safety.apply(input(f, 0.045)).gain, 0.25, 1e-9);  // tracking 45 ms old
  // A late sample makes the pose young again: the gain climbs at 1 / tracker_fade_s
  // (0.05 per 1 ms tick), not back to 1 in one tick.
  double previous = 0.25;
  for (int i = 1; i <= 15; ++i) {
    const double gain = safety.apply(input(f, 0.001)).gain;
    EXPECT_NEAR(gain, 0.25 + 0.05 * i, 1e-9) << "tick " << i;
    EXPECT_LE(gain - previous, 0.05 + 1e-12);
    previous = gain;
  }
  EXPECT_DOUBLE_EQ(safety.apply(input(f, 0.001)).gain, 1.0);
  // Falling is never held back: an older pose lowers the gain at once.
  EXPECT_NEAR(safety.apply(input(f, 0.048)).gain, 0.1, 1e-9);
}

TEST(ForceSafety, AHipJumpKeepsThePreviousForceMagnitudeInsteadOfStepping) {
  ForceSafety safety(settings());
  const Eigen::Vector3d hip(0, 1, 0);
  for (int i = 0; i < 200; ++i) (void)safety.apply(input(Eigen::Vector3d(0, 2, 0), 0.005, hip));
  // The HIP leaps 3 cm into the surface: the proxy force would step from 2 N to 8 N.
  const auto jump = safety.apply(input(Eigen::Vector3d(0, 8, 0), 0.005, hip + Eigen::Vector3d(0, -0.03, 0)));
  EXPECT_TRUE(jump.jump);
  EXPECT_NEAR(jump.force_W_N.norm(), 2.0, 1e-9);  // neither 8 N nor cut to 0 N
  // Then the force rises at the fade-in rate, up to the full value.
  const auto next = safety.apply(input(Eigen::Vector3d(0, 8, 0), 0.005, hip + Eigen::Vector3d(0, -0.03, 0)));
  EXPECT_FALSE(next.jump);
  EXPECT_NEAR(next.gain, 0.25 + kDt / 0.1, 1e-9);
  EXPECT_EQ(safety.counters().jumps, 1u);
}

TEST(ForceSafety, ALateTickMayCarryTheHandFurtherWithoutCountingAJump) {
  ForceSafety safety(settings());
  const Eigen::Vector3d hip(0, 1, 0);
  for (int i = 0; i < 200; ++i) (void)safety.apply(input(Eigen::Vector3d(0, 2, 0), 0.005, hip));
  // 12 mm in a tick that came 12 ms late: 1 m/s, a hand's speed, not a glitch.
  ForceSafetyInput late = input(Eigen::Vector3d(0, 2, 0), 0.005, hip + Eigen::Vector3d(0.012, 0, 0));
  late.dt_s = 0.012;
  EXPECT_FALSE(safety.apply(late).jump);
  // The same step in a 1 ms tick is 12 m/s: a jump.
  EXPECT_TRUE(safety.apply(input(Eigen::Vector3d(0, 2, 0), 0.005, hip + Eigen::Vector3d(0.024, 0, 0))).jump);
}

TEST(ForceSafety, SmallHipMotionIsNotAJump) {
  ForceSafety safety(settings());
  Eigen::Vector3d hip(0, 1, 0);
  for (int i = 0; i < 300; ++i) {
    hip.x() += 0.002;  // 2 m/s: fast, but no jump
    EXPECT_FALSE(safety.apply(input(Eigen::Vector3d(0, 2, 0), 0.005, hip)).jump);
  }
}

}  // namespace
