#pragma once
// The mobile base's planar pose and velocity. The world is y-up (floor at y = 0); the
// base frame B lies on the floor under the robot: B's y is world up, its x the robot's
// forward axis and z = x cross y. Heading turns B about world +y, so at heading 0 B is
// aligned with the world. Rig and predictor share these types (docs/kinematics.md).

#include "geometry/pose.h"

#include <Eigen/Core>

namespace mhd {

/// Planar pose of the base frame B in the world: X_WB = [Ry(heading), (x, 0, z)].
struct BasePose {
  double x_m = 0.0;
  double z_m = 0.0;
  double heading_rad = 0.0;  ///< about world +y (counter-clockwise seen from above)
};

/// Velocity of the base in its own frame B: vx along B's x (forward), vz along B's z,
/// omega about +y. The commanded base velocity uses this frame.
struct BaseTwist {
  double vx_mps = 0.0;
  double vz_mps = 0.0;
  double omega_radps = 0.0;
};

/// Angle wrapped into (-pi, pi].
[[nodiscard]] double wrap_angle(double angle_rad) noexcept;

/// X_WB for a planar base pose.
[[nodiscard]] Pose pose_from_base(const BasePose& base) noexcept;

/// Planar projection of a base frame pose: position on the floor and the heading of B's x
/// axis projected onto the floor. Inverse of pose_from_base for level poses.
[[nodiscard]] BasePose base_from_pose(const Pose& X_WB) noexcept;

/// Pose reached after `dt_s` seconds (negative goes back) at a constant body twist: the
/// exact arc, not a straight-line step. The heading is not wrapped.
[[nodiscard]] BasePose integrate_twist(const BasePose& start, const BaseTwist& twist_B, double dt_s) noexcept;

/// A world-frame displacement (dx, dz) expressed in B's axes at `heading_rad`: (along x, along z).
[[nodiscard]] Eigen::Vector2d world_to_base_xz(double heading_rad, double dx_m, double dz_m) noexcept;

}  // namespace mhd
