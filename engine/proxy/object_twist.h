#pragma once
// How fast each object of a world moves this tick, for damping against a moving surface:
// a hand resting on a surface that moves with it feels no damping force.

#include <Eigen/Core>

namespace mhd {

/// An object's rigid velocity in the world frame: its origin's velocity and its angular
/// velocity (about the origin).
struct ObjectTwist {
  Eigen::Vector3d v_W_origin_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d omega_W_radps = Eigen::Vector3d::Zero();
};

/// Velocity of the object's material point at p_W, when its origin is at p_W_origin.
[[nodiscard]] inline Eigen::Vector3d point_velocity_W(const ObjectTwist& twist, const Eigen::Vector3d& p_W_origin,
                                                      const Eigen::Vector3d& p_W) noexcept {
  return twist.v_W_origin_mps + twist.omega_W_radps.cross(p_W - p_W_origin);
}

}  // namespace mhd
