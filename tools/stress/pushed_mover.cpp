#include "stress/pushed_mover.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace mhd::stress {

PushedMover::PushedMover(const CompiledScene& scene, int object, const ObjectTwist& throw_W,
                         const PushedBodyParams& params, double dt_s)
    : scene_(scene),
      object_(object),
      throw_W_(throw_W),
      hand_speed_mps_(params.hand_speed_mps),
      hand_rate_radps_(params.hand_rate_radps),
      dynamics_(scene.dynamics),
      dt_s_(dt_s) {
  const auto o = static_cast<std::size_t>(object);
  dynamics_.resize(static_cast<std::size_t>(scene.world.object_count()));
  const bool scene_pushable = dynamics_[o].has_value();
  // Only the stressed object moves: every other object is a still collider.
  for (std::size_t i = 0; i < dynamics_.size(); ++i) {
    if (i != o) dynamics_[i].reset();
  }
  if (!scene_pushable) {
    dynamics_[o] = ObjectDynamics{params.mass_kg, params.friction};
    physics_.gravity_W_mps2.setZero();
  }
  restart(0.0);
}

void PushedMover::restart(double t_s) {
  // A fresh world puts the body back at its start at rest, its physics clock at zero.
  moving_ = std::make_unique<MovingWorld>(
      scene_.world, std::vector<std::optional<ObjectMotion>>(static_cast<std::size_t>(scene_.world.object_count())),
      dynamics_, physics_);
  moving_->set_body_velocity(object_, throw_W_);
  t0_s_ = t_s;
  X_WH_ticks_.clear();
  X_WH_ticks_.push_back(moving_->world().pose(object_));
}

CarryOutput PushedMover::advance(double t_s, ProxyState& proxy, double skin_m, const ProxyOutput& last) {
  // As the haptic tick: the reaction to the force the hand was sent, then the step.
  moving_->apply_reaction(proxy, last.force_W);
  const CarryOutput carry = moving_->advance(t_s - t0_s_, proxy, skin_m);
  // The hand-held frame steps toward the body, by at most a hand's speed and rate.
  const Pose& X_WH = X_WH_ticks_.back();
  const Pose& X_WO = moving_->world().pose(object_);
  Eigen::Vector3d d_W = X_WO.translation() - X_WH.translation();
  const double step_m = hand_speed_mps_ * dt_s_;
  if (d_W.norm() > step_m) d_W *= step_m / d_W.norm();
  Eigen::AngleAxisd turn(X_WO.linear() * X_WH.linear().transpose());
  turn.angle() = std::min(turn.angle(), hand_rate_radps_ * dt_s_);
  Pose X_WH_next = Pose::Identity();
  X_WH_next.linear() = turn.toRotationMatrix() * X_WH.linear();
  X_WH_next.translation() = X_WH.translation() + d_W;
  X_WH_ticks_.push_back(X_WH_next);
  return carry;
}

Pose PushedMover::X_WO_at(double t_s) const {
  const double k = std::round((t_s - t0_s_) / dt_s_);
  const auto last = static_cast<double>(X_WH_ticks_.size() - 1);
  return X_WH_ticks_[static_cast<std::size_t>(std::clamp(k, 0.0, last))];
}

}  // namespace mhd::stress
