#pragma once
// What moves a scene's objects between the moving-object stress's ticks, and carries the
// proxy with them, as the haptic tick does. Today one kind: scripted motions through
// MovingWorld (ScriptedMover). Pushed bodies (issue 17 item 2) plug in here: a mover that
// steps the dynamics with the proxy's last force and carries the proxy the same way;
// moving_stress_run.cpp makes its mover in one place (make_mover).

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
};

/// Scripted motions (ObjectMotion): exactly MovingWorld, as the haptic tick runs it.
class ScriptedMover final : public StressMover {
 public:
  ScriptedMover(const CollisionWorld& world, std::vector<std::optional<ObjectMotion>> motions)
      : moving_(world, std::move(motions)) {}
  [[nodiscard]] const CollisionWorld& world() const override { return moving_.world(); }
  [[nodiscard]] std::span<const ObjectTwist> twists() const override { return moving_.twists(); }
  void restart(double t_s) override { moving_.place(t_s); }
  CarryOutput advance(double t_s, ProxyState& proxy, double skin_m, const ProxyOutput& /*last*/) override {
    return moving_.advance(t_s, proxy, skin_m);
  }

 private:
  MovingWorld moving_;
};

}  // namespace mhd::stress
