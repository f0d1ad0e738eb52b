// Planar base poses: wrapping, the pose <-> X_WB round trip, exact arcs.

#include "kinematics/base_pose.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace mhd {
namespace {

constexpr double kHalfTurn_rad = std::numbers::pi;

TEST(BasePose, WrapsAnglesIntoMinusPiPi) {
  EXPECT_DOUBLE_EQ(wrap_angle(0.5), 0.5);
  EXPECT_DOUBLE_EQ(wrap_angle(kHalfTurn_rad), kHalfTurn_rad);
  EXPECT_DOUBLE_EQ(wrap_angle(-kHalfTurn_rad), kHalfTurn_rad);
  EXPECT_NEAR(wrap_angle(3 * kHalfTurn_rad + 0.25), -kHalfTurn_rad + 0.25, 1e-12);
  EXPECT_NEAR(wrap_angle(-7.0), -7.0 + 2 * kHalfTurn_rad, 1e-12);
}

TEST(BasePose, HeadingTurnsAboutWorldUp) {
  const Pose X = pose_from_base(BasePose{1.0, -2.0, kHalfTurn_rad / 2});
  // A quarter turn counter-clockwise seen from above takes B's x (forward) to world -z.
  EXPECT_LT((X.linear().col(0) - Eigen::Vector3d(0, 0, -1)).norm(), 1e-15);
  EXPECT_LT((X.translation() - Eigen::Vector3d(1, 0, -2)).norm(), 1e-15);
  const BasePose back = base_from_pose(X);
  EXPECT_DOUBLE_EQ(back.x_m, 1.0);
  EXPECT_DOUBLE_EQ(back.z_m, -2.0);
  EXPECT_NEAR(back.heading_rad, kHalfTurn_rad / 2, 1e-15);
}

TEST(BasePose, IntegratesAConstantTwistAlongItsArc) {
  const BasePose start{0.5, 0.25, 0.3};
  const BaseTwist twist{0.2, 0.05, 0.7};
  // Against many small Euler steps at the mid heading.
  BasePose stepped = start;
  constexpr int n = 100000;
  const double dt = 2.0 / n;
  for (int i = 0; i < n; ++i) stepped = integrate_twist(stepped, BaseTwist{twist.vx_mps, twist.vz_mps, 0.0}, dt),
                              stepped.heading_rad += twist.omega_radps * dt;
  const BasePose exact = integrate_twist(start, twist, 2.0);
  EXPECT_NEAR(exact.x_m, stepped.x_m, 1e-5);
  EXPECT_NEAR(exact.z_m, stepped.z_m, 1e-5);
  EXPECT_NEAR(exact.heading_rad, 0.3 + 1.4, 1e-15);
  // Backwards undoes forwards; no turn is a straight line.
  const BasePose back = integrate_twist(exact, twist, -2.0);
  EXPECT_NEAR(back.x_m, start.x_m, 1e-14);
  EXPECT_NEAR(back.z_m, start.z_m, 1e-14);
  const BasePose straight = integrate_twist(BasePose{}, BaseTwist{0.2, 0, 0}, 1.5);
  EXPECT_NEAR(straight.x_m, 0.3, 1e-15);
  EXPECT_EQ(straight.z_m, 0.0);
  // A full circle comes back.
  const BasePose circle = integrate_twist(start, BaseTwist{0.2, 0, 1.0}, 2 * kHalfTurn_rad);
  EXPECT_NEAR(circle.x_m, start.x_m, 1e-12);
  EXPECT_NEAR(circle.z_m, start.z_m, 1e-12);
}

TEST(BasePose, ExpressesWorldDisplacementsInTheBaseFrame) {
  const double heading = 0.8;
  const Pose X = pose_from_base(BasePose{0, 0, heading});
  const Eigen::Vector3d d_W(0.3, 0, -0.1);
  const Eigen::Vector3d d_B = X.linear().transpose() * d_W;
  const Eigen::Vector2d got = world_to_base_xz(heading, d_W.x(), d_W.z());
  EXPECT_NEAR(got.x(), d_B.x(), 1e-15);
  EXPECT_NEAR(got.y(), d_B.z(), 1e-15);
}

}  // namespace
}  // namespace mhd
