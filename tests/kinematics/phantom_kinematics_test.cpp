// PHANToM Premium 1.5 kinematics: the derived forward kinematics against the thesis's
// eq. 4.5 (and its typos), the analytic Jacobian against central differences, tau = J^T F
// against virtual work, the closed-form inverse kinematics, limits and workspace.

#include "kinematics/phantom_kinematics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace mhd {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

const PhantomModel kModel = phantom_premium_1_5();
const PhantomGeometry kGeometry = kModel.geometry;

Eigen::Vector3d random_angles(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  return Eigen::Vector3d(angle(rng), angle(rng), angle(rng));
}

// Uniform over the joint-limit box, rejecting the link-difference violations.
Eigen::Vector3d random_angles_within_limits(std::mt19937_64& rng) {
  const PhantomJointLimits& limits = kModel.limits;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (;;) {
    Eigen::Vector3d q;
    for (int i = 0; i < 3; ++i) q[i] = limits.lower_rad[i] + unit(rng) * (limits.upper_rad[i] - limits.lower_rad[i]);
    if (limits.contains(q)) return q;
  }
}

// Eq. 4.5 exactly as the thesis prints it (rotation part), lengths in metres.
Eigen::Matrix3d thesis_printed_rotation(const Eigen::Vector3d& q) {
  const double c1 = std::cos(q.x()), s1 = std::sin(q.x()), c3 = std::cos(q.z()), s3 = std::sin(q.z());
  Eigen::Matrix3d R;
  R << c1, -s1 * s3, -s1 * s3,  //
      0, c3, s3,                //
      s1, -c1 * s3, -c1 * c3;
  return R;
}

Eigen::Vector3d thesis_printed_translation(const Eigen::Vector3d& q, double l1, double l2) {
  const double c1 = std::cos(q.x()), s1 = std::sin(q.x()), c2 = std::cos(q.y()), s2 = std::sin(q.y());
  const double c3 = std::cos(q.z()), s3 = std::sin(q.z());
  return Eigen::Vector3d(s1 * (l1 * c2 + l2 * s3), l2 + l1 * s2 - l2 * c3, -l1 + c1 * (l1 * c2 + l2 * s3));
}

TEST(PhantomKinematics, ToolRotationIsARotationForAnyAngles) {
  std::mt19937_64 rng(1);
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Matrix3d R = phantom_tool_rotation(random_angles(rng));
    EXPECT_LT((R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), 1e-14);
    EXPECT_NEAR(R.determinant(), 1.0, 1e-14);
  }
}

TEST(PhantomKinematics, ThesisEquation45AsPrintedIsNotARotation) {
  // The typo in (1,3) alone already breaks orthogonality, and so does (3,1)'s sign.
  const Eigen::Vector3d q(0.4, 0.2, 0.7);
  const Eigen::Matrix3d printed = thesis_printed_rotation(q);
  EXPECT_GT((printed.transpose() * printed - Eigen::Matrix3d::Identity()).norm(), 0.1);
  // The entries the thesis prints right agree with the derived rotation...
  const Eigen::Matrix3d R = phantom_tool_rotation(q);
  for (auto [r, c] : {std::pair{0, 0}, {0, 1}, {1, 0}, {1, 1}, {1, 2}, {2, 1}}) {
    EXPECT_NEAR(R(r, c), printed(r, c), 1e-15) << "entry (" << r + 1 << "," << c + 1 << ")";
  }
  // ...and the three corrected ones are (1,3) = s1 c3, (3,1) = -s1, (3,3) = c1 c3.
  EXPECT_NEAR(R(0, 2), std::sin(q.x()) * std::cos(q.z()), 1e-15);
  EXPECT_NEAR(R(2, 0), -std::sin(q.x()), 1e-15);
  EXPECT_NEAR(R(2, 2), std::cos(q.x()) * std::cos(q.z()), 1e-15);
  // The translation column is printed right.
  std::mt19937_64 rng(2);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector3d qi = random_angles(rng);
    EXPECT_LT((phantom_tool_position(kGeometry, qi) - thesis_printed_translation(qi, 0.20955, 0.20955)).norm(), 1e-15);
  }
}

TEST(PhantomKinematics, ZeroAnglesPutTheToolAtTheOriginWithTheDeviceAxes) {
  const Pose X = phantom_tool_pose(kGeometry, Eigen::Vector3d::Zero());
  EXPECT_LT(X.translation().norm(), 1e-15);
  EXPECT_LT((X.linear() - Eigen::Matrix3d::Identity()).norm(), 1e-15);
  const double l = 0.20955;
  // theta3 = 90 deg: link 2 horizontal, towards the user.
  EXPECT_LT((phantom_tool_position(kGeometry, {0, 0, kPi / 2}) - Eigen::Vector3d(0, l, l)).norm(), 1e-15);
  // theta1 = 90 deg: the arm swung to the device's right (+x), about the base axis at z = -l1.
  EXPECT_LT((phantom_tool_position(kGeometry, {kPi / 2, 0, 0}) - Eigen::Vector3d(l, 0, -l)).norm(), 1e-15);
  // theta2 = 90 deg: link 1 straight up.
  EXPECT_LT((phantom_tool_position(kGeometry, {0, kPi / 2, 0}) - Eigen::Vector3d(0, l, -l)).norm(), 1e-15);
}

TEST(PhantomKinematics, ToolFrameYAxisRunsUpLinkTwoToTheElbow) {
  std::mt19937_64 rng(3);
  const double l1 = kGeometry.l1_m, l2 = kGeometry.l2_m;
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d q = random_angles(rng);
    const Eigen::Vector3d shoulder(0, l2, -l1);
    const Eigen::Vector3d elbow =
        shoulder + l1 * Eigen::Vector3d(std::sin(q.x()) * std::cos(q.y()), std::sin(q.y()),
                                        std::cos(q.x()) * std::cos(q.y()));
    const Pose X = phantom_tool_pose(kGeometry, q);
    EXPECT_LT(((elbow - X.translation()) / l2 - X.linear().col(1)).norm(), 1e-14);
    // x is the elbow's axis: horizontal, perpendicular to the arm's plane.
    EXPECT_NEAR(X.linear().col(0).y(), 0.0, 1e-15);
  }
}

TEST(PhantomKinematics, JacobianMatchesCentralDifferences) {
  std::mt19937_64 rng(4);
  constexpr double h = 1e-6;
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector3d q = random_angles(rng);
    const Eigen::Matrix3d J = phantom_position_jacobian(kGeometry, q);
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d dq = h * Eigen::Vector3d::Unit(j);
      const Eigen::Vector3d numeric =
          (phantom_tool_position(kGeometry, q + dq) - phantom_tool_position(kGeometry, q - dq)) / (2 * h);
      EXPECT_LT((J.col(j) - numeric).norm(), 1e-9) << "column " << j << " at " << q.transpose();
    }
  }
}

TEST(PhantomKinematics, TorquesDoTheSameVirtualWorkAsTheForce) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector3d q = random_angles_within_limits(rng);
    const Eigen::Vector3d force_N(3 * normal(rng), 3 * normal(rng), 3 * normal(rng));
    const Eigen::Vector3d tau_Nm = phantom_joint_torques(kGeometry, q, force_N);
    const Eigen::Vector3d dq = 1e-6 * Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
    const Eigen::Vector3d dp = phantom_tool_position(kGeometry, q + dq) - phantom_tool_position(kGeometry, q - dq);
    // F . dp == tau . dq (both displacements over 2 dq).
    EXPECT_NEAR(force_N.dot(dp), tau_Nm.dot(2 * dq), 1e-14);
  }
  // Pushing the tool straight down at home loads only joint 2 (link 1 is horizontal):
  // tau2 = l1 F, the lever of the vertical force about the shoulder.
  const Eigen::Vector3d tau = phantom_joint_torques(kGeometry, Eigen::Vector3d::Zero(), {0, -1, 0});
  EXPECT_LT((tau - Eigen::Vector3d(0, -kGeometry.l1_m, 0)).norm(), 1e-15);
}

TEST(PhantomKinematics, InverseKinematicsInvertsForwardKinematicsWithinLimits) {
  std::mt19937_64 rng(6);
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d q = random_angles_within_limits(rng);
    const PhantomIkSolution ik = phantom_inverse_kinematics(kModel, phantom_tool_position(kGeometry, q));
    ASSERT_TRUE(ik.ok()) << to_string(ik.status) << " at " << q.transpose();
    EXPECT_LT((ik.q_rad - q).norm(), 1e-9) << q.transpose();
  }
}

TEST(PhantomKinematics, InverseKinematicsReportsTargetsItCannotReach) {
  const double l = kGeometry.l1_m;
  // Beyond both links from the shoulder at (0, l2, -l1).
  EXPECT_EQ(phantom_inverse_kinematics(kModel, {0, l, -l + 2 * l + 1e-6}).status, PhantomIkStatus::OutOfReach);
  EXPECT_EQ(phantom_inverse_kinematics(kModel, {0.5, 0.5, 0.5}).status, PhantomIkStatus::OutOfReach);
  // On theta1's axis.
  EXPECT_EQ(phantom_inverse_kinematics(kModel, {0, 0.1, -l}).status, PhantomIkStatus::OnBaseAxis);
  EXPECT_EQ(phantom_inverse_kinematics(kModel, {std::nan(""), 0, 0}).status, PhantomIkStatus::OutOfReach);
  // Behind the device: reachable by the linkage but theta1 = 180 deg is past its limit.
  const Eigen::Vector3d behind(0.0, 0.0, -2 * l);
  const PhantomIkSolution ik = phantom_inverse_kinematics(kModel, behind);
  EXPECT_EQ(ik.status, PhantomIkStatus::OutsideJointLimits);
  EXPECT_LT((phantom_tool_position(kGeometry, ik.q_rad) - behind).norm(), 1e-12);
  // Fully stretched: the edge of the reach is still solved.
  const PhantomIkSolution stretched = phantom_inverse_kinematics(kModel, {0, l, -l + 2 * l});
  EXPECT_EQ(stretched.status, PhantomIkStatus::OutsideJointLimits);  // links aligned: past 70 deg
  EXPECT_NEAR(stretched.q_rad.z() - stretched.q_rad.y(), kPi / 2, 1e-6);
  EXPECT_EQ(to_string(PhantomIkStatus::OnBaseAxis), "on the base axis");
}

TEST(PhantomKinematics, PremiumWorkspaceBoxIsReachableWithinTheJointLimits) {
  const WorkspaceBox& box = kModel.workspace;
  EXPECT_LT((box.size_m() - Eigen::Vector3d(0.381, 0.267, 0.191)).norm(), 1e-12);
  const WorkspaceBox usable = kModel.usable_workspace();
  EXPECT_LT((usable.size_m() - Eigen::Vector3d(0.321, 0.207, 0.131)).norm(), 1e-12);
  EXPECT_TRUE(box.contains(usable.min_P_m) && box.contains(usable.max_P_m));
  EXPECT_TRUE(box.contains(Eigen::Vector3d::Zero()));  // home, where the joints read 0
  EXPECT_TRUE(kModel.limits.contains(Eigen::Vector3d::Zero()));
  constexpr int n = 12;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      for (int k = 0; k <= n; ++k) {
        const Eigen::Vector3d f(double(i) / n, double(j) / n, double(k) / n);
        const Eigen::Vector3d p = box.min_P_m + f.cwiseProduct(box.size_m());
        const PhantomIkSolution ik = phantom_inverse_kinematics(kModel, p);
        ASSERT_TRUE(ik.ok()) << to_string(ik.status) << " at " << p.transpose() << " (q "
                             << ik.q_rad.transpose() / kDeg << " deg)";
        EXPECT_LT((phantom_tool_position(kGeometry, ik.q_rad) - p).norm(), 1e-12);
      }
    }
  }
}

TEST(PhantomKinematics, JointLimitsIncludeTheLinkDifference) {
  const PhantomJointLimits& limits = kModel.limits;
  EXPECT_TRUE(limits.contains({0, 30 * kDeg, 30 * kDeg}));
  EXPECT_TRUE(limits.contains({0, 10 * kDeg, 74 * kDeg}));    // theta3 near its limit...
  EXPECT_FALSE(limits.contains({0, -20 * kDeg, 72 * kDeg}));  // ...but theta3 - theta2 = 92 deg is not
  EXPECT_FALSE(limits.contains({66 * kDeg, 0, 0}));
}

}  // namespace
}  // namespace mhd
