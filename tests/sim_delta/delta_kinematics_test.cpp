#include "delta_kinematics.h"
#include "delta_workspace.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace mhd::sim_delta {
namespace {

std::vector<Eigen::Vector3d> grid(const DeltaWorkspaceBox& box, int n) {
  std::vector<Eigen::Vector3d> points;
  const Eigen::Vector3d step = box.size_m() / (n - 1);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) points.push_back(box.min_D_m + step.cwiseProduct(Eigen::Vector3d(i, j, k)));
  return points;
}

TEST(DeltaKinematics, ForwardOfInverseIsTheIdentityOverTheWorkspace) {
  const DeltaGeometry g;
  const DeltaJointLimits limits;
  for (const Eigen::Vector3d& p : grid(DeltaWorkspaceBox{}, 15)) {
    const std::optional<Eigen::Vector3d> q = delta_inverse_kinematics(g, limits, p);
    ASSERT_TRUE(q) << p.transpose();
    EXPECT_TRUE(limits.contains(*q));
    const std::optional<Eigen::Vector3d> back = delta_forward_kinematics(g, *q);
    ASSERT_TRUE(back) << p.transpose();
    EXPECT_LT((*back - p).norm(), 1e-12) << p.transpose();
  }
}

TEST(DeltaKinematics, InverseOfForwardRecoversTheAngles) {
  const DeltaGeometry g;
  const DeltaJointLimits limits;
  for (int k = 0; k < 40; ++k) {
    const Eigen::Vector3d q(0.1 + 0.5 * std::sin(k), 0.3 + 0.4 * std::cos(2.0 * k), 0.2 + 0.5 * std::sin(3.0 * k + 1.0));
    const std::optional<Eigen::Vector3d> p = delta_forward_kinematics(g, q);
    ASSERT_TRUE(p) << q.transpose();
    const std::optional<Eigen::Vector3d> back = delta_inverse_kinematics(g, limits, *p);
    ASSERT_TRUE(back) << q.transpose();
    EXPECT_LT((*back - q).norm(), 1e-9) << q.transpose();
  }
}

TEST(DeltaKinematics, TheEffectorStaysOnTheAxisWhenTheArmsMoveAlike) {
  const DeltaGeometry g;
  double previous_z = 0.0;
  for (double theta = -0.5; theta <= 1.2; theta += 0.1) {
    const std::optional<Eigen::Vector3d> p = delta_forward_kinematics(g, Eigen::Vector3d::Constant(theta));
    ASSERT_TRUE(p);
    EXPECT_LT(p->head<2>().norm(), 1e-12);
    // Each forearm then closes the triangle (a cos t + R - r, a sin t) to (0, z) with length b.
    const double radial = g.upper_arm_m * std::cos(theta) + g.base_radius_m - g.effector_radius_m;
    EXPECT_NEAR(std::hypot(radial, p->z() - g.upper_arm_m * std::sin(theta)), g.forearm_m, 1e-12);
    EXPECT_GT(p->z(), previous_z);  // raising the arms towards +z pushes the effector out
    previous_z = p->z();
  }
}

TEST(DeltaKinematics, TheJacobianMatchesFiniteDifferences) {
  const DeltaGeometry g;
  const DeltaJointLimits limits;
  const double h = 1e-6;
  for (const Eigen::Vector3d& p : grid(DeltaWorkspaceBox{}, 5)) {
    const Eigen::Vector3d q = *delta_inverse_kinematics(g, limits, p);
    const std::optional<Eigen::Matrix3d> J = delta_jacobian(g, q);
    ASSERT_TRUE(J);
    Eigen::Matrix3d numeric;
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d dq = h * Eigen::Vector3d::Unit(j);
      numeric.col(j) = (*delta_forward_kinematics(g, q + dq) - *delta_forward_kinematics(g, q - dq)) / (2.0 * h);
    }
    EXPECT_LT((*J - numeric).norm(), 1e-7 * J->norm()) << p.transpose();
  }
}

TEST(DeltaKinematics, MotorTorquesDoTheVirtualWorkOfTheForce) {
  const DeltaGeometry g;
  const DeltaJointLimits limits;
  int k = 0;
  for (const Eigen::Vector3d& p : grid(DeltaWorkspaceBox{}, 4)) {
    ++k;
    const Eigen::Vector3d q = *delta_inverse_kinematics(g, limits, p);
    const Eigen::Matrix3d J = *delta_jacobian(g, q);
    const Eigen::Vector3d F_N(4.0 * std::sin(k), 3.0 * std::cos(2.0 * k), -5.0 + std::sin(3.0 * k));
    const Eigen::Vector3d tau = delta_motor_torques_Nm(J, F_N);
    // A small real motion (forward kinematics, not J) does the same work on both sides.
    const Eigen::Vector3d dq = 1e-6 * Eigen::Vector3d(std::cos(k), std::sin(5.0 * k), 0.5 - std::cos(7.0 * k));
    const Eigen::Vector3d dp = *delta_forward_kinematics(g, q + 0.5 * dq) - *delta_forward_kinematics(g, q - 0.5 * dq);
    EXPECT_NEAR(tau.dot(dq), F_N.dot(dp), 1e-9 * F_N.norm() * dp.norm() + 1e-15) << p.transpose();
    // And the torques make that force again.
    const std::optional<Eigen::Vector3d> F_back = delta_tool_force_N(J, tau);
    ASSERT_TRUE(F_back);
    EXPECT_LT((*F_back - F_N).norm(), 1e-9 * F_N.norm());
  }
}

TEST(DeltaKinematics, UnreachablePointsHaveNoSolutionAndNeverNaN) {
  const DeltaGeometry g;
  const DeltaJointLimits limits;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(delta_inverse_kinematics(g, limits, Eigen::Vector3d(0.0, 0.0, 1.0)));   // beyond a + b
  EXPECT_FALSE(delta_inverse_kinematics(g, limits, Eigen::Vector3d(0.0, 0.0, 0.0)));   // in the base
  EXPECT_FALSE(delta_inverse_kinematics(g, limits, Eigen::Vector3d(0.3, 0.0, 0.1)));   // far off the axis
  EXPECT_FALSE(delta_inverse_kinematics(g, limits, Eigen::Vector3d(0.0, 0.0, -0.1)));  // behind the base
  EXPECT_FALSE(delta_inverse_kinematics(g, limits, Eigen::Vector3d(nan, 0.0, 0.1)));
  EXPECT_FALSE(delta_inverse_kinematics(g, limits, Eigen::Vector3d(0.0, inf, 0.1)));
  // Reachable by the arms, but only past the upper stop: refused too.
  const Eigen::Vector3d deep(0.0, 0.0, 0.16);
  DeltaJointLimits wide;
  wide.max_rad = 3.0;
  const std::optional<Eigen::Vector3d> q_wide = delta_inverse_kinematics(g, wide, deep);
  ASSERT_TRUE(q_wide);
  EXPECT_GT(q_wide->maxCoeff(), limits.max_rad);
  EXPECT_FALSE(delta_inverse_kinematics(g, limits, deep));
  // A sweep through and around the reach: every answer is absent or finite within the limits.
  for (double x = -0.3; x <= 0.3; x += 0.02)
    for (double y = -0.3; y <= 0.3; y += 0.02)
      for (double z = -0.3; z <= 0.3; z += 0.02) {
        const std::optional<Eigen::Vector3d> q = delta_inverse_kinematics(g, limits, Eigen::Vector3d(x, y, z));
        if (q) {
          EXPECT_TRUE(q->allFinite());
          EXPECT_TRUE(limits.contains(*q));
        }
      }
  // Forearms too short to meet: no forward solution and no Jacobian.
  DeltaGeometry short_forearms;
  short_forearms.forearm_m = 0.01;
  EXPECT_FALSE(delta_forward_kinematics(short_forearms, Eigen::Vector3d::Zero()));
  EXPECT_FALSE(delta_jacobian(short_forearms, Eigen::Vector3d::Zero()));
  EXPECT_FALSE(delta_forward_kinematics(g, Eigen::Vector3d(nan, 0.0, 0.0)));
  // A singular Jacobian gives no force.
  EXPECT_FALSE(delta_tool_force_N(Eigen::Matrix3d::Zero(), Eigen::Vector3d(1.0, 0.0, 0.0)));
}

}  // namespace
}  // namespace mhd::sim_delta
