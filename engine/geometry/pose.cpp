#include "geometry/pose.h"

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
  Pose X = Pose::Identity();
  X.linear() = q.normalized().toRotationMatrix();
  X.translation() = p_m;
  return X;
}

}  // namespace mhd
