// Each case of Table 3.1 (as reconstructed in docs/planner.md) on numbers worked by hand.
// Common setup unless a test says otherwise: default settings (d' = 0.45 + 0.225 = 0.675 m,
// collision radius 0.225 + 0.25 = 0.475 m, pi' = 30 deg, 0.5 m/s, 40 deg/s, deceleration
// interval 0.2 m, device facing B's +z); the user at the origin.

#include "planner/planner.h"
#include "planner/planner_geometry.h"
#include "planner/predictive_planner.h"
#include "planner/seed_planner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace mhd {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;
constexpr double kTol = 1e-9;

PlannerInput input(double base_x, double base_z, double heading, double hand_x, double hand_z,
                   double user_x = 0.0, double user_z = 0.0, double user_heading = 0.0) {
  PlannerInput in;
  in.base = BasePose{base_x, base_z, heading};
  in.user_W = Eigen::Vector2d(user_x, user_z);
  in.user_heading_rad = user_heading;
  in.p_W_hip = Eigen::Vector3d(hand_x, 1.1, hand_z);
  return in;
}

TEST(PlannerGeometry, FacingHeadingPointsTheDeviceAxisAtTheUser) {
  // Base at (0.675, 0), user at the origin: the device axis (B's +z) must point along -x.
  // B's +z at heading h is (sin h, cos h) in (x, z): h = -90 deg gives (-1, 0).
  EXPECT_NEAR(planner_geometry::facing_heading({0.675, 0.0}, {0.0, 0.0}, -kPi / 2), -kPi / 2, kTol);
  // Base at (0, -0.675): B's +z must point along +z: heading 0.
  EXPECT_NEAR(planner_geometry::facing_heading({0.0, -0.675}, {0.0, 0.0}, -kPi / 2), 0.0, kTol);
}

TEST(PlannerGeometry, TargetIsOnTheUserHandRayAtDPrime) {
  const Eigen::Vector2d t = planner_geometry::follow_target({1.0, 2.0}, {1.3, 2.4}, 0.0, 0.675);
  EXPECT_NEAR(t.x(), 1.0 + 0.675 * 0.6, kTol);
  EXPECT_NEAR(t.y(), 2.0 + 0.675 * 0.8, kTol);
  // Hand on the user's axis: along the user's facing, heading 90 deg = world -z.
  const Eigen::Vector2d f = planner_geometry::follow_target({0.0, 0.0}, {0.0, 0.0}, kPi / 2, 0.675);
  EXPECT_NEAR(f.x(), 0.0, kTol);
  EXPECT_NEAR(f.y(), -0.675, kTol);
}

TEST(PlannerGeometry, SegmentDistance) {
  EXPECT_NEAR(planner_geometry::segment_distance({0.0, -0.9}, {0.675, 0.0}, {0.0, 0.0}), 0.54, kTol);
  EXPECT_NEAR(planner_geometry::segment_distance({1.0, 0.0}, {2.0, 0.0}, {0.0, 0.0}), 1.0, kTol);
}

TEST(SeedPlanner, IdleWhileTheHipIsInTheUsableWorkspace) {
  // Base at the target (0.675, 0) facing the user; the hand at (0.45, 0) is 0.225 m along
  // B's +z: inside z in [0.1603, 0.2913].
  SeedPlanner planner{PlannerSettings{}};
  const PlannerOutput out = planner.update(input(0.675, 0.0, -kPi / 2, 0.45, 0.0));
  EXPECT_EQ(out.status, PlannerCase::Idle);
  EXPECT_TRUE(out.hip_in_usable);
  EXPECT_EQ(out.twist_B.vx_mps, 0.0);
  EXPECT_EQ(out.twist_B.vz_mps, 0.0);
  EXPECT_EQ(out.twist_B.omega_radps, 0.0);
  EXPECT_FALSE(planner.active());
}

TEST(SeedPlanner, StraightAtFullSpeedOutsideTheDecelerationInterval) {
  // The user stepped back to (-0.2, 0): hand (0.25, 0) is 0.425 m along B's +z, outside.
  // Target (0.475, 0), angle 0 < pi': straight, distance 0.2 m = the interval: 0.5 m/s
  // along world -x, which is B's +z at heading -90 deg.
  SeedPlanner planner{PlannerSettings{}};
  const PlannerOutput out = planner.update(input(0.675, 0.0, -kPi / 2, 0.25, 0.0, -0.2, 0.0));
  EXPECT_EQ(out.status, PlannerCase::Straight);
  EXPECT_FALSE(out.hip_in_usable);
  EXPECT_NEAR(out.target_W.x(), 0.475, kTol);
  EXPECT_NEAR(out.goal_W.x(), 0.475, kTol);
  EXPECT_NEAR(out.twist_B.vx_mps, 0.0, kTol);
  EXPECT_NEAR(out.twist_B.vz_mps, 0.5, kTol);
  EXPECT_NEAR(out.twist_B.omega_radps, 0.0, kTol);
}

TEST(SeedPlanner, StraightSlowsInProportionInsideTheDecelerationInterval) {
  // User at (-0.1, 0), hand (0.35, 0) (0.325 m along +z: outside). Target (0.575, 0) is
  // 0.1 m away: 0.5 * 0.1 / 0.2 = 0.25 m/s.
  SeedPlanner planner{PlannerSettings{}};
  const PlannerOutput out = planner.update(input(0.675, 0.0, -kPi / 2, 0.35, 0.0, -0.1, 0.0));
  EXPECT_EQ(out.status, PlannerCase::Straight);
  EXPECT_NEAR(out.twist_B.vz_mps, 0.25, kTol);
  EXPECT_NEAR(out.twist_B.vx_mps, 0.0, kTol);
}

TEST(SeedPlanner, StraightJustBelowPiPrime) {
  // Base on the circle at 29 deg from the target (seen from the user): still straight.
  const double a = 29.0 * kDeg;
  const Eigen::Vector2d base = 0.675 * planner_geometry::direction(-a);
  SeedPlanner planner{PlannerSettings{}};
  const double heading = planner_geometry::facing_heading(base, {0.0, 0.0}, -kPi / 2);
  const PlannerOutput out = planner.update(input(base.x(), base.y(), heading, 0.45, 0.0));
  EXPECT_EQ(out.status, PlannerCase::Straight);
  EXPECT_NEAR(out.goal_W.x(), 0.675, kTol);
  EXPECT_NEAR(out.goal_W.y(), 0.0, kTol);
}

TEST(SeedPlanner, SubTargetAdvancesByPiPrimeOnTheCircle) {
  // Base at (0, -0.675) facing the user (heading 0); target (0.675, 0) is 90 deg away.
  // Sub-target: the base's direction (heading 90 deg) turned by -30 deg: heading 60 deg,
  // (cos 60, -sin 60) * 0.675 = (0.3375, -0.58457). Chord 2 * 0.675 * sin 15 = 0.3494 m
  // > 0.2 m: full speed along the chord, at 15 deg to the tangent: world velocity
  // 0.5 (cos 15, sin 15) = (0.48296, 0.12941), and B = W at heading 0.
  SeedPlanner planner{PlannerSettings{}};
  const PlannerOutput out = planner.update(input(0.0, -0.675, 0.0, 0.45, 0.0));
  EXPECT_EQ(out.status, PlannerCase::SubTarget);
  EXPECT_NEAR(out.goal_W.x(), 0.3375, 1e-9);
  EXPECT_NEAR(out.goal_W.y(), -0.675 * std::sqrt(3.0) / 2.0, 1e-9);
  EXPECT_NEAR(out.twist_B.vx_mps, 0.5 * std::cos(15.0 * kDeg), 1e-9);
  EXPECT_NEAR(out.twist_B.vz_mps, 0.5 * std::sin(15.0 * kDeg), 1e-9);
  EXPECT_NEAR(out.twist_B.omega_radps, 0.0, kTol);
}

TEST(SeedPlanner, SubTargetTurnsTheOtherWayWhenTheTargetIsOnTheOtherSide) {
  // Mirror image: base at (0, +0.675), target (0.675, 0): sub-target (0.3375, +0.58457).
  SeedPlanner planner{PlannerSettings{}};
  const PlannerOutput out = planner.update(input(0.0, 0.675, kPi, 0.45, 0.0));
  EXPECT_EQ(out.status, PlannerCase::SubTarget);
  EXPECT_NEAR(out.goal_W.x(), 0.3375, 1e-9);
  EXPECT_NEAR(out.goal_W.y(), 0.675 * std::sqrt(3.0) / 2.0, 1e-9);
}

TEST(SeedPlanner, EscapeMovesStraightAwayAtFullSpeed) {
  // Base at (0.24, 0.32): d = 0.4 < 0.475. Goal 0.675 (0.6, 0.8) = (0.405, 0.54); the
  // velocity 0.5 m/s along (0.6, 0.8). Facing the user, that is B's -z: (0, -0.5).
  SeedPlanner planner{PlannerSettings{}};
  const double heading = planner_geometry::facing_heading({0.24, 0.32}, {0.0, 0.0}, -kPi / 2);
  const PlannerOutput out = planner.update(input(0.24, 0.32, heading, 0.45, 0.0));
  EXPECT_EQ(out.status, PlannerCase::Escape);
  EXPECT_NEAR(out.goal_W.x(), 0.405, 1e-9);
  EXPECT_NEAR(out.goal_W.y(), 0.54, 1e-9);
  EXPECT_NEAR(out.twist_B.vx_mps, 0.0, 1e-9);
  EXPECT_NEAR(out.twist_B.vz_mps, -0.5, 1e-9);
  EXPECT_FALSE(out.guard_active);
}

TEST(SeedPlanner, StopIntervalStopsTheBaseThenGoesIdle) {
  SeedPlanner planner{PlannerSettings{}};
  // Start moving (hand outside).
  ASSERT_EQ(planner.update(input(0.675, 0.0, -kPi / 2, 0.25, 0.0, -0.2, 0.0)).status, PlannerCase::Straight);
  // 35 mm from the target (0.675, 0), facing the user: stop.
  const PlannerOutput stop = planner.update(input(0.64, 0.0, -kPi / 2, 0.45, 0.0));
  EXPECT_EQ(stop.status, PlannerCase::Stopping);
  EXPECT_EQ(stop.twist_B.vx_mps, 0.0);
  EXPECT_EQ(stop.twist_B.vz_mps, 0.0);
  EXPECT_EQ(stop.twist_B.omega_radps, 0.0);
  EXPECT_FALSE(planner.active());
  EXPECT_EQ(planner.update(input(0.64, 0.0, -kPi / 2, 0.45, 0.0)).status, PlannerCase::Idle);
}

TEST(SeedPlanner, TurnRateSaturatesThenFallsInProportion) {
  // At the target but heading 0 instead of -90 deg: the hand is at B x = -0.225, outside.
  // Error -90 deg > 20 deg: -40 deg/s; the base stays (stopping) until it faces the user.
  SeedPlanner planner{PlannerSettings{}};
  const PlannerOutput out = planner.update(input(0.675, 0.0, 0.0, 0.45, 0.0));
  EXPECT_EQ(out.status, PlannerCase::Stopping);
  EXPECT_NEAR(out.twist_B.omega_radps, -40.0 * kDeg, kTol);
  EXPECT_TRUE(planner.active());
  // Error -10 deg: 40 * 10 / 20 = -20 deg/s.
  const PlannerOutput near = planner.update(input(0.675, 0.0, -80.0 * kDeg, 0.45, 0.0));
  EXPECT_NEAR(near.twist_B.omega_radps, -20.0 * kDeg, kTol);
}

TEST(SeedPlanner, GuardRemovesMotionTowardsTheUserInsideTheBand) {
  // Base at (0.5, 0): within the band (0.525 m), outside the cylinder (0.475 m). Of
  // (-0.3, 0.4) the radial part -0.3 points at the user and goes; (0, 0.4) stays.
  Eigen::Vector2d v(-0.3, 0.4);
  EXPECT_TRUE(planner_geometry::guard_velocity({0.5, 0.0}, {0.0, 0.0}, 0.525, 0.1, 0.0, v));
  EXPECT_NEAR(v.x(), 0.0, kTol);
  EXPECT_NEAR(v.y(), 0.4, kTol);
  Eigen::Vector2d away(0.3, 0.4);
  EXPECT_FALSE(planner_geometry::guard_velocity({0.5, 0.0}, {0.0, 0.0}, 0.525, 0.1, 0.0, away));
  // Turning at 0.7 rad/s sweeps the velocity by +-0.035 rad over the 0.1 s period: a
  // tangential 0.5 m/s gets a radial part 0.5 tan(0.035) before scaling back to 0.5 m/s.
  Eigen::Vector2d tangential(0.0, 0.5);
  EXPECT_TRUE(planner_geometry::guard_velocity({0.5, 0.0}, {0.0, 0.0}, 0.525, 0.1, 0.7, tangential));
  EXPECT_NEAR(tangential.x(), 0.5 * std::sin(std::atan(std::tan(0.035))), 1e-12);
  EXPECT_NEAR(tangential.norm(), 0.5, 1e-12);
  // Far outside the band and staying outside after one period: untouched.
  Eigen::Vector2d far(-0.3, 0.0);
  EXPECT_FALSE(planner_geometry::guard_velocity({1.0, 0.0}, {0.0, 0.0}, 0.525, 0.1, 0.0, far));
}

// The HIP in B at a goal pose of the predictive planner.
Eigen::Vector2d hip_at_goal(const PlannerOutput& out, const PlannerInput& in) {
  return planner_geometry::hip_in_base(BasePose{out.goal_W.x(), out.goal_W.y(), out.goal_heading_rad}, in.p_W_hip);
}

// The usable workspace shrunk by the default catch margin (25 mm).
bool in_catch_box(const Eigen::Vector2d& p) {
  return p.x() >= -0.1621 + 0.025 - 1e-9 && p.x() <= 0.1589 - 0.025 + 1e-9 && p.y() >= 0.1603 + 0.025 - 1e-9 &&
         p.y() <= 0.2913 - 0.025 + 1e-9;
}

TEST(PredictivePlanner, CatchGoalIsTheNearestPoseWithTheHipInside) {
  // The seed's 0.1 m step back: the HIP is 0.325 m along B's +z. The nearest catch pose
  // at the current heading is 0.325 - (0.2913 - 0.025) = 0.0587 m nearer the user; turning
  // by the first sampled step (40/12 deg) shortens that to 0.325 cos(3.33 deg) - 0.2663 =
  // 0.0582 m (0.1163 s against 0.1174 s), so the goal is at most 0.0587 m away, puts the
  // HIP on the box's far edge, and the base moves at full speed (0.0587 m > one period).
  PredictivePlanner planner{PlannerSettings{}};
  const PlannerInput in = input(0.675, 0.0, -kPi / 2, 0.35, 0.0, -0.1, 0.0);
  const PlannerOutput out = planner.update(in);
  EXPECT_EQ(out.status, PlannerCase::Straight);
  const double dist = (out.goal_W - Eigen::Vector2d(0.675, 0.0)).norm();
  EXPECT_LE(dist, 0.0587 + 1e-4);
  EXPECT_GE(dist, 0.0582 - 1e-4);
  const Eigen::Vector2d hip = hip_at_goal(out, in);
  EXPECT_TRUE(in_catch_box(hip)) << hip.transpose();
  EXPECT_NEAR(hip.y(), 0.2913 - 0.025, 1e-9);
  EXPECT_NEAR(std::hypot(out.twist_B.vx_mps, out.twist_B.vz_mps), 0.5, kTol);
  // The seed goes to the target 0.1 m away at 0.25 m/s.
  SeedPlanner seed{PlannerSettings{}};
  EXPECT_NEAR((seed.update(in).goal_W - Eigen::Vector2d(0.675, 0.0)).norm(), 0.1, kTol);
}

TEST(PredictivePlanner, GoesStraightWheneverTheChordClearsTheUser) {
  // Base at (0, -0.9), hand at (0.45, 0): 90 deg from the target seen from the user, so the
  // seed takes a sub-target; a catch goal with a clear chord exists.
  SeedPlanner seed{PlannerSettings{}};
  PredictivePlanner predictive{PlannerSettings{}};
  const PlannerInput in = input(0.0, -0.9, 0.0, 0.45, 0.0);
  EXPECT_EQ(seed.update(in).status, PlannerCase::SubTarget);
  const PlannerOutput out = predictive.update(in);
  EXPECT_EQ(out.status, PlannerCase::Straight);
  EXPECT_TRUE(in_catch_box(hip_at_goal(out, in)));
  EXPECT_GE(planner_geometry::segment_distance({0.0, -0.9}, out.goal_W, {0.0, 0.0}), 0.525 - 1e-9);
  EXPECT_NEAR(std::hypot(out.twist_B.vx_mps, out.twist_B.vz_mps), 0.5, kTol);
}

TEST(PredictivePlanner, TakesTheLargestClearSubTargetStep) {
  // Base at (-0.675, 0) on the far side of the user (facing +x: heading 90 deg), hand at
  // (0.45, 0): every catch pose is within the band or behind the user, and so is the target.
  // A chord of angle a on the circle of radius 0.675 passes 0.675 cos(a/2) from the user; it
  // keeps 0.525 m up to a = 2 acos(0.525 / 0.675) = 77.885 deg (the seed: 30 deg). The
  // target is 180 deg away, wrapped to +180: the step turns by +a.
  PredictivePlanner planner{PlannerSettings{}};
  const PlannerOutput out = planner.update(input(-0.675, 0.0, kPi / 2, 0.45, 0.0));
  EXPECT_EQ(out.status, PlannerCase::SubTarget);
  const double a = 2.0 * std::acos(0.525 / 0.675);
  EXPECT_NEAR(a / kDeg, 77.885, 1e-3);
  const Eigen::Vector2d expected = 0.675 * planner_geometry::direction(kPi + a);  // (-0.1417, 0.6600)
  EXPECT_NEAR(expected.x(), -0.1417, 1e-4);
  EXPECT_NEAR(expected.y(), 0.6600, 1e-4);
  EXPECT_NEAR(out.goal_W.x(), expected.x(), 1e-4);
  EXPECT_NEAR(out.goal_W.y(), expected.y(), 1e-4);
  EXPECT_NEAR(std::hypot(out.twist_B.vx_mps, out.twist_B.vz_mps), 0.5, kTol);
  SeedPlanner seed{PlannerSettings{}};
  const PlannerOutput seed_out = seed.update(input(-0.675, 0.0, kPi / 2, 0.45, 0.0));
  EXPECT_EQ(seed_out.status, PlannerCase::SubTarget);
  EXPECT_NEAR(seed_out.goal_W.x(), 0.675 * std::cos(kPi + 30.0 * kDeg), 1e-9);
}

TEST(PredictivePlanner, StopsOnceTheHipIsWellInside) {
  PredictivePlanner planner{PlannerSettings{}};
  ASSERT_EQ(planner.update(input(0.675, 0.0, -kPi / 2, 0.35, 0.0, -0.1, 0.0)).status, PlannerCase::Straight);
  // HIP 0.225 m along B's +z, x 0: inside the shrunk box.
  const PlannerOutput out = planner.update(input(0.575, 0.0, -kPi / 2, 0.35, 0.0, -0.1, 0.0));
  EXPECT_EQ(out.status, PlannerCase::Stopping);
  EXPECT_EQ(out.twist_B.vz_mps, 0.0);
  EXPECT_FALSE(planner.active());
}

TEST(PredictivePlanner, ExtrapolatesTheUserWithACappedShift) {
  // User walking at 1 m/s towards +x, hand at (0.45, 0): 0.3 s ahead is 0.3 m, capped at
  // d' - band = 0.675 - 0.525 = 0.15 m: target (0.825, 0). The current HIP is inside the
  // usable workspace but the predicted one (0.15 m nearer the base) is not: it moves.
  PredictivePlanner planner{PlannerSettings{}};
  PlannerInput in = input(0.675, 0.0, -kPi / 2, 0.45, 0.0);
  in.user_velocity_W = Eigen::Vector2d(1.0, 0.0);
  const PlannerOutput out = planner.update(in);
  EXPECT_TRUE(out.hip_in_usable);
  EXPECT_EQ(out.status, PlannerCase::Straight);
  EXPECT_NEAR(out.target_W.x(), 0.825, kTol);
  EXPECT_LT(out.twist_B.vz_mps, 0.0);  // away from the user: B's -z
  // The seed does not look ahead: idle.
  SeedPlanner seed{PlannerSettings{}};
  EXPECT_EQ(seed.update(in).status, PlannerCase::Idle);
}

TEST(PredictivePlanner, EscapeAsTheSeed) {
  PredictivePlanner planner{PlannerSettings{}};
  const double heading = planner_geometry::facing_heading({0.24, 0.32}, {0.0, 0.0}, -kPi / 2);
  const PlannerOutput out = planner.update(input(0.24, 0.32, heading, 0.45, 0.0));
  EXPECT_EQ(out.status, PlannerCase::Escape);
  EXPECT_NEAR(out.twist_B.vz_mps, -0.5, 1e-9);
}

TEST(Planner, FactoryMakesEachKind) {
  EXPECT_EQ(make_planner(PlannerKind::Seed, PlannerSettings{})->kind(), PlannerKind::Seed);
  EXPECT_EQ(make_planner(PlannerKind::Predictive, PlannerSettings{})->kind(), PlannerKind::Predictive);
  EXPECT_EQ(to_string(PlannerCase::SubTarget), "sub-target");
}

}  // namespace
}  // namespace mhd
