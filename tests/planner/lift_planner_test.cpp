// The lift's planner: never outside the lift's range, speed or acceleration, whatever the
// targets and steps; on a target it stops there without overshoot; with no target it
// brakes to a stop; and on a user who crouches to 0.3 m and reaches to 1.9 m it keeps the
// hand within the arm's vertical reach, which a fixed arm does not.
#include "planner/lift_planner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

namespace mhd {
namespace {

constexpr Lift kLift{.min_m = -0.75, .max_m = 0.95, .max_speed_mps = 0.5, .max_acceleration_mps2 = 1.0};
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(LiftPlanner, NeverLeavesItsRangeSpeedOrAccelerationOnAnyTargetsAndSteps) {
  const LiftPlanner planner(kLift, 0.13);
  std::mt19937 rng(20261129);
  std::uniform_real_distribution<double> target(-2.0, 2.0);
  std::uniform_real_distribution<double> dt(0.0005, 0.02);
  std::uniform_int_distribution<int> kind(0, 9);
  LiftState s;
  double t = 0.0;
  double target_m = 0.0;
  for (int i = 0; i < 200'000; ++i) {
    if (i % 500 == 0) {  // a new target every few seconds, some of them no number at all
      const int k = kind(rng);
      target_m = k == 0 ? kNaN : k == 1 ? kInf : k == 2 ? -kInf : target(rng);
    }
    const double dt_s = dt(rng);
    const LiftState next = planner.step(s, target_m, dt_s);
    ASSERT_GE(next.height_m, kLift.min_m) << "step " << i;
    ASSERT_LE(next.height_m, kLift.max_m) << "step " << i;
    ASSERT_LE(std::abs(next.velocity_mps), kLift.max_speed_mps + 1e-12) << "step " << i;
    ASSERT_LE(std::abs(next.velocity_mps - s.velocity_mps), kLift.max_acceleration_mps2 * dt_s + 1e-12)
        << "step " << i << " at " << t << " s";
    s = next;
    t += dt_s;
  }
}

TEST(LiftPlanner, ReachesATargetStopsThereAndNeverOvershoots) {
  const LiftPlanner planner(kLift, 0.13);
  for (const double target_m : {0.5, -0.6, 0.01, 0.95}) {
    LiftState s;
    double beyond_m = 0.0;
    double t_s = 0.0;
    for (; t_s < 10.0; t_s += 0.001) {
      s = planner.step(s, target_m, 0.001);
      beyond_m = std::max(beyond_m, (s.height_m - target_m) * std::copysign(1.0, target_m));
      if (std::abs(s.height_m - target_m) < 1e-9 && s.velocity_mps == 0.0) break;
    }
    EXPECT_NEAR(s.height_m, target_m, 1e-9);
    EXPECT_EQ(s.velocity_mps, 0.0);
    EXPECT_LE(beyond_m, 1e-12) << target_m;
    // The time-optimal move: accelerate, cruise, brake (a triangle when the move is short).
    const double d = std::abs(target_m);
    const double v = kLift.max_speed_mps;
    const double a = kLift.max_acceleration_mps2;
    const double optimal_s = d >= v * v / a ? d / v + v / a : 2.0 * std::sqrt(d / a);
    EXPECT_LT(t_s, optimal_s + 0.05) << target_m;
    EXPECT_GT(t_s, optimal_s - 0.01) << target_m;
  }
}

TEST(LiftPlanner, WithNoTargetItBrakesToAStopAndComesBackWithOne) {
  const LiftPlanner planner(kLift, 0.13);
  LiftState s{.height_m = 0.0, .velocity_mps = 0.5};
  double t_s = 0.0;
  while (s.velocity_mps != 0.0 && t_s < 5.0) {
    s = planner.step(s, kNaN, 0.001);
    t_s += 0.001;
  }
  EXPECT_EQ(s.velocity_mps, 0.0);
  EXPECT_NEAR(t_s, 0.5 / kLift.max_acceleration_mps2, 0.002);
  const double stopped_at_m = s.height_m;
  s = planner.step(s, kNaN, 0.001);
  EXPECT_EQ(s.height_m, stopped_at_m);
  s = planner.step(s, 0.9, 0.001);  // a target again: it moves
  EXPECT_GT(s.velocity_mps, 0.0);
}

TEST(LiftPlanner, AStepThatIsNoPositiveNumberChangesNothing) {
  const LiftPlanner planner(kLift, 0.13);
  const LiftState s{.height_m = 0.2, .velocity_mps = -0.1};
  for (const double dt_s : {0.0, -0.001, kNaN, kInf}) {
    const LiftState next = planner.step(s, 0.5, dt_s);
    EXPECT_EQ(next.height_m, s.height_m) << dt_s;
    EXPECT_EQ(next.velocity_mps, s.velocity_mps) << dt_s;
  }
}

TEST(LiftPlanner, TheTargetPutsTheReachsMiddleAtTheHandWithinTheRange) {
  const LiftPlanner planner(kLift, 0.13);
  // Arm frame at 0.87 m with the lift at 0: the reach's middle is at 1.0 m.
  EXPECT_DOUBLE_EQ(planner.target_for_hand(1.0, 0.87), 0.0);
  EXPECT_DOUBLE_EQ(planner.target_for_hand(1.5, 0.87), 0.5);
  EXPECT_DOUBLE_EQ(planner.target_for_hand(3.0, 0.87), kLift.max_m);
  EXPECT_DOUBLE_EQ(planner.target_for_hand(-1.0, 0.87), kLift.min_m);
  EXPECT_TRUE(std::isnan(planner.target_for_hand(kNaN, 0.87)));
  EXPECT_TRUE(std::isnan(planner.target_for_hand(1.0, kInf)));
}

/// The share of 1 ms ticks whose hand is within `half_reach_m` of the reach's middle, for a
/// user who crouches to 0.3 m and reaches to 1.9 m and back at 0.3 m/s, holding 1 s at
/// each end, twice; with the lift planned, or held at 0.
double share_within_reach(bool lifted, double half_reach_m) {
  const LiftPlanner planner(kLift, 0.13);
  constexpr double kPhantomAtZero_m = 0.87;
  LiftState s;
  int within = 0;
  int ticks = 0;
  double hand_m = 1.0;
  double direction = -1.0;
  double hold_s = 0.0;
  for (double t_s = 0.0; t_s < 24.0; t_s += 0.001, ++ticks) {
    if (hold_s > 0.0) {
      hold_s -= 0.001;
    } else {
      hand_m += direction * 0.3 * 0.001;
      if (hand_m <= 0.3 || hand_m >= 1.9) {
        hand_m = std::clamp(hand_m, 0.3, 1.9);
        direction = -direction;
        hold_s = 1.0;
      }
    }
    if (lifted) s = planner.step(s, planner.target_for_hand(hand_m, kPhantomAtZero_m), 0.001);
    const double middle_m = kPhantomAtZero_m + s.height_m + 0.13;
    within += std::abs(hand_m - middle_m) <= half_reach_m ? 1 : 0;
  }
  return static_cast<double>(within) / ticks;
}

TEST(LiftPlanner, KeepsACrouchingAndReachingHandWithinTheArmsReachWhereAFixedArmCannot) {
  // A PHANToM Premium 1.5's vertical reach: 0.267 m, so 0.13 m either side of its middle.
  const double lifted = share_within_reach(true, 0.13);
  const double fixed = share_within_reach(false, 0.13);
  EXPECT_GE(lifted, 0.95);
  EXPECT_LT(fixed, 0.3);
  std::printf("hand within the arm's vertical reach: %.1f %% with the lift, %.1f %% without\n", 100.0 * lifted,
              100.0 * fixed);
}

}  // namespace
}  // namespace mhd
