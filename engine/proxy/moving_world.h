#pragma once
// A scene's collision world whose objects follow their scripted motions: the haptic
// thread's own copy of the world (shapes shared, poses its own), moved once per tick
// before the proxy steps, the proxy carried by what moved (carry_proxy).

#include "geometry/object_motion.h"
#include "proxy/proxy_carry.h"

#include <optional>
#include <span>
#include <vector>

namespace mhd {

class MovingWorld {
 public:
  /// Copies `world` (its shapes are shared, not copied); motions[i] moves object i, none
  /// leaves it where it is. Throws std::invalid_argument unless there is one entry per object.
  MovingWorld(const CollisionWorld& world, std::vector<std::optional<ObjectMotion>> motions);

  [[nodiscard]] bool moves() const noexcept { return moving_count_ > 0; }
  [[nodiscard]] const CollisionWorld& world() const noexcept { return world_; }
  /// Each object's velocity at the last advance() or place(); empty when nothing moves
  /// (step_proxy then damps against still surfaces at no cost).
  [[nodiscard]] std::span<const ObjectTwist> twists() const noexcept {
    return moves() ? std::span<const ObjectTwist>(twists_) : std::span<const ObjectTwist>();
  }

  /// Puts every moving object at its pose at t_s, no proxy involved (start-up, seeking).
  void place(double t_s) noexcept;

  /// Moves every moving object from its last pose to its pose at t_s and carries the
  /// proxy with what moved. Allocates nothing.
  CarryOutput advance(double t_s, ProxyState& proxy, double skin_m) noexcept;

 private:
  CollisionWorld world_;
  std::vector<std::optional<ObjectMotion>> motions_;
  std::vector<Pose> X_WO_before_;
  std::vector<ObjectTwist> twists_;
  int moving_count_ = 0;
};

}  // namespace mhd
