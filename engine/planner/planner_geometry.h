#pragma once
// Geometry shared by the planners (all planar: 2-vectors are world (x, z)). Free functions
// so that each step of Table 3.1 can be tested on its own numbers.

#include "kinematics/base_pose.h"
#include "planner/planner_settings.h"

#include <Eigen/Core>

namespace mhd::planner_geometry {

/// World (x, z) direction of a heading: (cos h, -sin h).
[[nodiscard]] Eigen::Vector2d direction(double heading_rad) noexcept;
/// Heading of a world (x, z) direction: atan2(-z, x).
[[nodiscard]] double heading_of(const Eigen::Vector2d& d) noexcept;

/// Target position (ch. 3.3): on the ray from the user through the hand, at `distance_m`
/// from the user. A hand on the user's axis (closer than 1 mm) uses the user's facing.
[[nodiscard]] Eigen::Vector2d follow_target(const Eigen::Vector2d& user, const Eigen::Vector2d& hand,
                                            double user_heading_rad, double distance_m) noexcept;

/// Heading that points the device (at `facing_angle_rad` in B) from `base` at `user`
/// (eq. 3.1, see docs/planner.md).
[[nodiscard]] double facing_heading(const Eigen::Vector2d& base, const Eigen::Vector2d& user,
                                    double facing_angle_rad) noexcept;

/// Signed angle (rad, (-pi, pi]) from direction a to direction b about +y, i.e. the heading
/// convention: heading_of(b) - heading_of(a), wrapped.
[[nodiscard]] double signed_angle(const Eigen::Vector2d& a, const Eigen::Vector2d& b) noexcept;

/// Point on the circle of radius `radius_m` around `center`, at the direction of `from`
/// turned by `angle_rad` (heading sense).
[[nodiscard]] Eigen::Vector2d point_on_circle(const Eigen::Vector2d& center, const Eigen::Vector2d& from,
                                              double angle_rad, double radius_m) noexcept;

/// Smallest distance from point c to the segment [a, b].
[[nodiscard]] double segment_distance(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                      const Eigen::Vector2d& c) noexcept;

/// The HIP in B, planar (x, z).
[[nodiscard]] Eigen::Vector2d hip_in_base(const BasePose& base, const Eigen::Vector3d& p_W_hip) noexcept;

/// When the base is, or after one period would be, nearer the user than `band_m`: makes
/// sure no direction the velocity takes during the period points at the user. Turning at
/// omega sweeps the world velocity over +-|omega| period / 2 around v_W (body_twist
/// decomposes at the mid heading), so the radial part must be at least
/// |tangential part| tan(|omega| period / 2); a smaller one is raised to that (the
/// tangential part kept, the speed never above the original). Returns true when it changed v_W.
bool guard_velocity(const Eigen::Vector2d& base, const Eigen::Vector2d& user, double band_m, double period_s,
                    double omega_radps, Eigen::Vector2d& v_W) noexcept;

/// The body twist that moves the base by v_W * period in a straight chord while turning at
/// omega: decomposed at the mid-period heading, so the arc's chord points along v_W.
/// Also clamps |v| and |omega| to the limits (guards against rounding).
[[nodiscard]] BaseTwist body_twist(double heading_rad, const Eigen::Vector2d& v_W, double omega_radps,
                                   const PlannerSettings& settings) noexcept;

}  // namespace mhd::planner_geometry
