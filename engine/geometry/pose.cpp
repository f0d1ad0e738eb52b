#include "geometry/pose.h"

#include <cmath>

namespace mhd {

Eigen::Matrix3d rotation_from_rpy(const Eigen::Vector3d& rpy_rad) {
  return (Eigen::AngleAxisd(rpy_rad.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy_rad.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy_rad.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Pose pose_from_xyz_rpy(const Eigen::Vector3d& p_m, const Eigen::Vector3d& rpy_rad) {
  Pose X = Pose::Identity();
  X.linear() = rotation_from_rpy(rpy_rad);
  X.translation() = p_m;
  return X;
}

Pose pose_from_xyz_quaternion(const Eigen::Vector3d& p_m, const Eigen::Quaterniond& q) {
  // Divide by the largest component before normalising: the squared norm of components
  // beyond ~1e154 overflows (normalized() then gives zeros, read as the identity) and of
  // components below ~1e-154 is subnormal (the result is off unit by up to 1e-5).
  const double largest = q.coeffs().cwiseAbs().maxCoeff();
  const Eigen::Quaterniond scaled(largest > 0.0 && std::isfinite(largest) ? Eigen::Vector4d(q.coeffs() / largest)
                                                                          : Eigen::Vector4d(q.coeffs()));
  Pose X = Pose::Identity();
  X.linear() = scaled.normalized().toRotationMatrix();
  X.translation() = p_m;
  return X;
}

}  // namespace mhd
