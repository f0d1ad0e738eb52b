#pragma once
// What moves a scene's objects between the moving-object stress's ticks, and carries the
// proxy with them, as the haptic tick does: scripted motions through MovingWorld
// (ScriptedMover), or the stressed object as a body pushed by the proxy's force
// (PushedMover, pushed_mover.h). moving_stress_run.cpp makes its mover in one place
// (make_mover).

#include "proxy/moving_world.h"

#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace mhd::stress {

class StressMover {
 public:
  virtual ~StressMover() = default;
  /// The world in its current poses (the proxy steps in it).
  [[nodiscard]] virtual const CollisionWorld& world() const = 0;
  /// Each object's velocity now (empty: nothing moves).
  [[nodiscard]] virtual std::span<const ObjectTwist> twists() const = 0;
  /// Puts the objects at their poses at t_s with no proxy involved (a proxy reset follows).
  virtual void restart(double t_s) = 0;
  /// Moves the objects to t_s and carries the proxy. `last` is the proxy's output of the
  /// tick before (its force acts on pushed bodies).
  virtual CarryOutput advance(double t_s, ProxyState& proxy, double skin_m, const ProxyOutput& last) = 0;
  /// The stressed object's pose at t_s, for t_s from the last restart up to the last
  /// advance (the strokes follow it).
  [[nodiscard]] virtual Pose X_WO_at(double t_s) const = 0;
};

/// Scripted motions (ObjectMotion): exactly MovingWorld, as the haptic tick runs it.
class ScriptedMover final : public StressMover {
 public:
  /// motions[object] is the stressed object's.
  ScriptedMover(const CollisionWorld& world, std::vector<std::optional<ObjectMotion>> motions, int object)
      : motion_(motions.at(static_cast<std::size_t>(object)).value()), moving_(world, std::move(motions)) {}
  [[nodiscard]] const CollisionWorld& world() const override { return moving_.world(); }
  [[nodiscard]] std::span<const ObjectTwist> twists() const override { return moving_.twists(); }
  void restart(double t_s) override { moving_.place(t_s); }
  CarryOutput advance(double t_s, ProxyState& proxy, double skin_m, const ProxyOutput& /*last*/) override {
    return moving_.advance(t_s, proxy, skin_m);
  }
  [[nodiscard]] Pose X_WO_at(double t_s) const override { return motion_.X_WO_at(t_s); }

 private:
  ObjectMotion motion_;
  MovingWorld moving_;
};

}  // namespace mhd::stress
