#pragma once
// Pushable objects simulated as rigid bodies (Bullet's btDiscreteDynamicsWorld) on a
// fixed physics step of their own, decoupled from the haptic rate: advance(t_s) takes
// as many whole physics steps as fit up to t_s (bounded per call) and renders each
// body's pose at t_s by extrapolating its last state with its velocity. Still objects
// (a floor, a table) are static colliders; objects with a scripted motion are not in the
// dynamics world. Forces (the proxy's reaction) are held from apply_force() to the next
// one and integrated as impulses, whatever the haptic rate. World is y-up by default.

#include "collision/collision_world.h"
#include "geometry/object_dynamics.h"
#include "geometry/pose.h"

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <span>

namespace mhd {

struct RigidBodySettings {
  /// The physics step. 1 ms: Bullet's friction and contact stay exact to well under a
  /// millimetre for hand-sized boxes, and a box pushed through a 1 kN/m coupling spring
  /// (omega h < 0.1 for m >= 0.1 kg) is far inside semi-implicit Euler's stable range.
  double step_s = 1e-3;
  /// Most physics steps one advance() may take: the haptic tick's work stays bounded;
  /// beyond it the physics clock slips (runs slow) rather than catching up.
  int max_steps_per_advance = 4;
  Eigen::Vector3d gravity_W_mps2 = Eigen::Vector3d(0.0, -9.81, 0.0);
};

class RigidBodyWorld {
 public:
  /// dynamics[i] makes object i of `world` a body (its pose now is its pose at t = 0);
  /// none: a static collider, unless static_object[i] is false (a scripted object, left
  /// out). Throws std::invalid_argument unless both spans have one entry per object, each
  /// mass is positive and finite and each friction finite and >= 0.
  RigidBodyWorld(const CollisionWorld& world, std::span<const std::optional<ObjectDynamics>> dynamics,
                 std::span<const bool> static_object, const RigidBodySettings& settings = {});
  ~RigidBodyWorld();
  RigidBodyWorld(const RigidBodyWorld&) = delete;
  RigidBodyWorld& operator=(const RigidBodyWorld&) = delete;

  [[nodiscard]] bool is_body(int object) const noexcept;
  [[nodiscard]] const RigidBodySettings& settings() const noexcept;

  /// Holds the force f_W_N acting at the point p_W_m on `object` (a body; others are
  /// ignored) until the next apply_force() or clear_forces(). Allocates nothing.
  void apply_force(int object, const Eigen::Vector3d& f_W_N, const Eigen::Vector3d& p_W_m) noexcept;
  /// Adds f_W_N at p_W_m to what `object` holds (another hand's push on it), until the
  /// next apply_force() or clear_forces(). Allocates nothing.
  void add_force(int object, const Eigen::Vector3d& f_W_N, const Eigen::Vector3d& p_W_m) noexcept;
  /// No force on any body from now on.
  void clear_forces() noexcept;
  /// Sets a body's velocity now (a body thrown or caught): its origin's v_W_origin_mps and
  /// its angular velocity omega_W_radps, as v_W_origin_mps() and omega_W_radps() return
  /// them from now on. Non-finite values and non-bodies are ignored. Allocates nothing.
  void set_velocity(int object, const Eigen::Vector3d& v_W_origin_mps, const Eigen::Vector3d& omega_W_radps) noexcept;

  /// Steps the physics up to t_s (at most max_steps_per_advance steps) and renders every
  /// body's pose and velocity at t_s. Earlier t_s than the last: nothing moves. Returns
  /// the physics steps taken. Allocates nothing once its contacts have been met once
  /// (Bullet keeps its arrays' capacity).
  int advance(double t_s) noexcept;

  /// Pose of a body's object at the last advance() (or its initial pose).
  [[nodiscard]] Pose X_WO(int object) const noexcept;
  /// Velocity of the object's origin, and its angular velocity (world frame).
  [[nodiscard]] Eigen::Vector3d v_W_origin_mps(int object) const noexcept;
  [[nodiscard]] Eigen::Vector3d omega_W_radps(int object) const noexcept;
  /// Time the physics has been stepped to.
  [[nodiscard]] double physics_time_s() const noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mhd
