#pragma once
// The pushed-body mover of the moving-object stress: the stressed object
// is a rigid body (RigidBodyWorld, through MovingWorld exactly as the haptic tick drives
// it), thrown at each proxy reset with a random twist and pushed every tick by the
// reaction to the force the proxy gave the hand on the tick before
// (MovingWorld::apply_reaction, then MovingWorld::advance, which carries the proxy). The
// scene's other objects are its static colliders. Gravity acts only on an object its scene
// makes pushable (<dynamics>: the scene gives it something to rest on); any other object
// floats, since falling it would leave the strokes' reach within half a second.
// The strokes follow the body as a hand would (X_WO_at): a hand-held frame that tracks
// the body's pose but moves at most at the hand's top speed and rate. Riding the body
// exactly, a stroke inside it would push it on with a constant force for ever (a
// floating 0.2 kg box reached 18 m/s); a hand cannot keep up with that, so the body
// outruns it and the push ends, as it would.

#include "scene_compiler/compiled_scene.h"
#include "stress/stress_mover.h"

#include <memory>
#include <numbers>
#include <vector>

namespace mhd::stress {

struct PushedBodyParams {
  /// The body's mass and friction when its scene gives it no <dynamics>. 1 kg: the hand's
  /// few newtons move it visibly within a stroke; a floating 0.2 kg body is knocked out of
  /// reach by the first fast stroke (contact on 3 % of the ticks, against 11 % at 1 kg).
  double mass_kg = 1.0;
  double friction = 0.5;
  /// The hand-held frame's top speed and rate (see above); run_range sets them to the
  /// strokes' top speed and the drawn motions' top rate.
  double hand_speed_mps = 1.5;
  double hand_rate_radps = std::numbers::pi;
};

class PushedMover final : public StressMover {
 public:
  /// `object` of `scene` becomes a body thrown with throw_W (its origin's velocity and its
  /// angular velocity) at each restart; dt_s is the tick the stress advances by.
  /// Throws std::invalid_argument if params give an invalid mass or friction.
  PushedMover(const CompiledScene& scene, int object, const ObjectTwist& throw_W, const PushedBodyParams& params,
              double dt_s);
  [[nodiscard]] const CollisionWorld& world() const override { return moving_->world(); }
  [[nodiscard]] std::span<const ObjectTwist> twists() const override { return moving_->twists(); }
  /// The body back at its start pose, thrown again; t_s becomes its clock's zero.
  void restart(double t_s) override;
  /// Pushes the body with the reaction to last.force_W (the proxy as it ended the tick
  /// before), then steps it to t_s and carries the proxy.
  CarryOutput advance(double t_s, ProxyState& proxy, double skin_m, const ProxyOutput& last) override;
  /// The hand-held frame at the tick nearest t_s since the last restart (the body's start
  /// pose before): where the body was, as far as a hand could follow it.
  [[nodiscard]] Pose X_WO_at(double t_s) const override;

 private:
  const CompiledScene& scene_;
  int object_;
  ObjectTwist throw_W_;
  double hand_speed_mps_;
  double hand_rate_radps_;
  std::vector<std::optional<ObjectDynamics>> dynamics_;
  RigidBodySettings physics_;
  double dt_s_;
  double t0_s_ = 0.0;
  std::unique_ptr<MovingWorld> moving_;
  std::vector<Pose> X_WH_ticks_;  // [k]: the hand-held frame at t0_s_ + k dt_s
};

}  // namespace mhd::stress
