// The planner's estimate of the user's walking, alone: the head's floor velocity, low-passed
// with a 0.2 s time constant (a steady walk is reached, a single jump is not passed on),
// and the head's heading on the floor.
#include "haptic_server/user_motion_estimate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using namespace mhd;

HeadState head_at(double t_s, double x_m, double z_m) {
  HeadState h;
  h.known = true;
  h.t_s = t_s;
  h.p_W_m = Eigen::Vector3d(x_m, 1.7, z_m);
  return h;
}

TEST(UserMotionEstimate, StartsStillAndStaysStillWithoutAHead) {
  UserMotionEstimate estimate;
  EXPECT_EQ(estimate.velocity_W_mps(), Eigen::Vector2d::Zero());
  estimate.update(HeadState{});
  estimate.update(head_at(1.0, 0.0, 0.0));  // one head: no velocity yet
  EXPECT_EQ(estimate.velocity_W_mps(), Eigen::Vector2d::Zero());
}

TEST(UserMotionEstimate, OneStepMovesTheVelocityByDtOverTauPlusDt) {
  UserMotionEstimate estimate;
  estimate.update(head_at(1.0, 0.0, 0.0));
  estimate.update(head_at(1.1, 0.1, -0.05));  // 1 m/s in x, -0.5 m/s in z over 0.1 s
  const double alpha = 0.1 / (0.2 + 0.1);
  EXPECT_NEAR(estimate.velocity_W_mps().x(), alpha * 1.0, 1e-12);
  EXPECT_NEAR(estimate.velocity_W_mps().y(), alpha * -0.5, 1e-12);
}

TEST(UserMotionEstimate, ASteadyWalkIsReachedAfterSeveralTimeConstants) {
  UserMotionEstimate estimate;
  for (int i = 0; i <= 200; ++i) estimate.update(head_at(i * 0.01, 0.8 * i * 0.01, 0.0));  // 2 s at 0.8 m/s
  EXPECT_NEAR(estimate.velocity_W_mps().x(), 0.8, 1e-3);
  EXPECT_NEAR(estimate.velocity_W_mps().y(), 0.0, 1e-12);
}

TEST(UserMotionEstimate, TheSameHeadAgainOrAnOlderOneChangesNothing) {
  UserMotionEstimate estimate;
  estimate.update(head_at(1.0, 0.0, 0.0));
  estimate.update(head_at(1.1, 0.1, 0.0));
  const Eigen::Vector2d v = estimate.velocity_W_mps();
  estimate.update(head_at(1.1, 0.1, 0.0));
  estimate.update(head_at(1.05, 5.0, 0.0));
  EXPECT_EQ(estimate.velocity_W_mps(), v);
}

TEST(UserMotionEstimate, HeadingIsTheLineOfSightOnTheFloor) {
  EXPECT_NEAR(planar_heading_rad(Eigen::Quaterniond::Identity()), 0.0, 1e-12);  // along +x
  const double a = 0.7;
  const Eigen::Quaterniond yaw(Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()));  // +x turns towards -z
  EXPECT_NEAR(planar_heading_rad(yaw), a, 1e-12);
  // Looking down a little does not change the heading.
  const Eigen::Quaterniond pitched = yaw * Eigen::Quaterniond(Eigen::AngleAxisd(-0.3, Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(planar_heading_rad(pitched), a, 1e-12);
  UserMotionEstimate estimate;
  HeadState h = head_at(1.0, 0.0, 0.0);
  h.q_W = Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitY()));
  estimate.update(h);
  EXPECT_NEAR(estimate.heading_rad(), std::numbers::pi / 2, 1e-12);
}

}  // namespace
