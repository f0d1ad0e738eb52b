#pragma once
// A scene's collision world whose objects follow their scripted motions or are pushed
// (rigid bodies, RigidBodyWorld): the haptic thread's own copy of the world (shapes
// shared, poses its own), moved once per tick before the proxy steps, the proxy carried
// by what moved (carry_proxy). After the step, apply_reaction() pushes the touched bodies
// with the force the hand felt; they move by it from the next tick on.

#include "dynamics/rigid_body_world.h"
#include "geometry/object_dynamics.h"
#include "geometry/object_motion.h"
#include "proxy/proxy_carry.h"

#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace mhd {

class MovingWorld {
 public:
  /// Copies `world` (its shapes are shared, not copied); motions[i] moves object i, none
  /// leaves it where it is. Throws std::invalid_argument unless there is one entry per object.
  MovingWorld(const CollisionWorld& world, std::vector<std::optional<ObjectMotion>> motions);
  /// Also makes each object with dynamics[i] a pushable body (none: scripted or still).
  /// Throws std::invalid_argument unless dynamics has one entry per object (or none at
  /// all), no object has both a motion and dynamics, and each body's dynamics is valid.
  MovingWorld(const CollisionWorld& world, std::vector<std::optional<ObjectMotion>> motions,
              std::span<const std::optional<ObjectDynamics>> dynamics, const RigidBodySettings& physics = {});

  /// Also makes each object with driven[i] one whose pose is set from outside
  /// (drive(): a replica of an object another rig simulates); it is left out of the
  /// bodies' physics. Throws std::invalid_argument unless driven has one entry per object
  /// and no driven object has a motion or dynamics.
  MovingWorld(const CollisionWorld& world, std::vector<std::optional<ObjectMotion>> motions,
              std::span<const std::optional<ObjectDynamics>> dynamics, std::span<const bool> driven,
              const RigidBodySettings& physics = {});

  [[nodiscard]] bool moves() const noexcept { return moving_count_ > 0 || physics_ != nullptr; }
  /// The pushable bodies' physics; null when the world has none.
  [[nodiscard]] const RigidBodyWorld* physics() const noexcept { return physics_.get(); }
  [[nodiscard]] const CollisionWorld& world() const noexcept { return world_; }
  /// Each object's velocity at the last advance() or place(); empty when nothing moves
  /// (step_proxy then damps against still surfaces at no cost).
  [[nodiscard]] std::span<const ObjectTwist> twists() const noexcept {
    return moves() ? std::span<const ObjectTwist>(twists_) : std::span<const ObjectTwist>();
  }

  /// Puts every scripted object at its pose at t_s, no proxy involved (start-up, seeking).
  /// Bodies stay where their physics has them.
  void place(double t_s) noexcept;

  /// Moves every scripted object from its last pose to its pose at t_s, steps the bodies'
  /// physics to t_s, and carries the proxy with what moved. Allocates nothing (once the
  /// bodies' contacts have been met: RigidBodyWorld::advance).
  CarryOutput advance(double t_s, ProxyState& proxy, double skin_m) noexcept;

  /// Sets pushable body `object`'s velocity now (RigidBodyWorld::set_velocity); its twist
  /// shows from the next advance(). No-op for scripted or still objects.
  void set_body_velocity(int object, const ObjectTwist& twist_W) noexcept;

  /// Where driven object `object` is to be, and how fast it moves, from the next place()
  /// or advance() on. No-op for other objects. Allocates nothing.
  void drive(int object, const Pose& X_WO, const ObjectTwist& twist_W) noexcept;

  /// Adds another rig's push (f_W_N at p_W_m) to what body `object` holds, until the next
  /// apply_reaction(). No-op for objects that are not bodies. Allocates nothing.
  void add_push(int object, const Eigen::Vector3d& f_W_N, const Eigen::Vector3d& p_W_m) noexcept;

  /// The hand felt force_W_N (the force on it) with the proxy at proxy's end of tick: the
  /// bodies of its constraint planes get the reaction, at the proxy (contact_reactions),
  /// held until the next call; every other body none. Allocates nothing.
  void apply_reaction(const ProxyState& proxy, const Eigen::Vector3d& force_W_N) noexcept;

 private:
  CollisionWorld world_;
  std::vector<std::optional<ObjectMotion>> motions_;
  std::vector<Pose> X_WO_before_;
  std::vector<ObjectTwist> twists_;
  std::vector<char> driven_;           // [i]: object i is posed by drive()
  std::vector<Pose> X_WO_driven_;
  std::vector<ObjectTwist> twists_driven_;
  int moving_count_ = 0;
  std::unique_ptr<RigidBodyWorld> physics_;  // null without bodies
};

}  // namespace mhd
