#pragma once
// Rigid poses. Names follow the X_AB convention: X_WO is the pose of frame O in
// frame W, so p_W = X_WO * p_O.

#include <Eigen/Geometry>

namespace mhd {

using Pose = Eigen::Isometry3d;

/// Rotation from roll, pitch, yaw in radians: R = Rz(yaw) * Ry(pitch) * Rx(roll)
/// (rotations about the fixed x, then y, then z axes).
[[nodiscard]] Eigen::Matrix3d rotation_from_rpy(const Eigen::Vector3d& rpy_rad);

/// Pose from a translation and roll/pitch/yaw in radians.
[[nodiscard]] Pose pose_from_xyz_rpy(const Eigen::Vector3d& p_m, const Eigen::Vector3d& rpy_rad);

/// Pose from a translation and a quaternion; the quaternion is normalised first.
/// Precondition: q has non-zero norm.
[[nodiscard]] Pose pose_from_xyz_quaternion(const Eigen::Vector3d& p_m, const Eigen::Quaterniond& q);

}  // namespace mhd
