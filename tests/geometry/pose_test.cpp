// Poses from quaternions whatever their scale: the scene file may give any four numbers.
#include "geometry/pose.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using mhd::pose_from_xyz_quaternion;

void expect_rotation(const mhd::Pose& X) {
  const Eigen::Matrix3d R = X.linear();
  EXPECT_TRUE((R.transpose() * R).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
  EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
}

TEST(Pose, AQuaternionOfHugeComponentsIsStillItsRotation) {
  // 90 degrees about x, scaled so far that the squared norm overflows.
  const mhd::Pose X = pose_from_xyz_quaternion(Eigen::Vector3d::Zero(), Eigen::Quaterniond(1e300, 1e300, 0, 0));
  expect_rotation(X);
  EXPECT_TRUE((X.linear() * Eigen::Vector3d::UnitY()).isApprox(Eigen::Vector3d::UnitZ(), 1e-12));
}

TEST(Pose, AQuaternionOfTinyComponentsIsARotation) {
  // Squared norm subnormal: normalising directly is off unit by about 1e-5.
  const mhd::Pose X = pose_from_xyz_quaternion(Eigen::Vector3d(1, 2, 3), Eigen::Quaterniond(1e-160, 1e-160, 0, 0));
  expect_rotation(X);
  EXPECT_TRUE((X.linear() * Eigen::Vector3d::UnitY()).isApprox(Eigen::Vector3d::UnitZ(), 1e-12));
  EXPECT_EQ(X.translation(), Eigen::Vector3d(1, 2, 3));
}

}  // namespace
