#include "sharing/object_replica.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mhd {

ObjectReplica::ObjectReplica(const Pose& X_WO_0, const ReplicaSettings& settings) noexcept : settings_(settings) {
  state_.X_WO = X_WO_0;
}

Pose ObjectReplica::dead_reckoned(double t_s) const noexcept {
  if (!has_state_) return state_.X_WO;
  const double dt_s = std::clamp(t_s - state_.t_s, 0.0, settings_.max_extrapolation_s);
  Pose X = state_.X_WO;
  X.translation() += state_.twist_W.v_W_origin_mps * dt_s;
  const Eigen::Vector3d turn_W = state_.twist_W.omega_W_radps * dt_s;
  const double angle_rad = turn_W.norm();
  if (angle_rad > 0.0) X.linear() = Eigen::AngleAxisd(angle_rad, turn_W / angle_rad).toRotationMatrix() * X.linear();
  return X;
}

double ObjectReplica::blend_weight(double t_s) const noexcept {
  if (!(settings_.blend_s > 0.0)) return 0.0;
  return std::clamp(1.0 - (t_s - t_accept_s_) / settings_.blend_s, 0.0, 1.0);
}

Pose ObjectReplica::X_WO_at(double t_s) const noexcept {
  Pose X = dead_reckoned(t_s);
  const double w = blend_weight(t_s);
  if (w <= 0.0) return X;
  X.translation() += w * offset_p_W_m_;
  X.linear() = (Eigen::Quaterniond::Identity().slerp(w, offset_q_W_) * Eigen::Quaterniond(X.linear()))
                   .normalized()
                   .toRotationMatrix();
  return X;
}

ObjectTwist ObjectReplica::twist_at(double t_s) const noexcept {
  ObjectTwist twist;
  if (has_state_ && t_s - state_.t_s <= settings_.max_extrapolation_s) twist = state_.twist_W;
  if (blend_weight(t_s) > 0.0) twist.v_W_origin_mps -= offset_p_W_m_ / settings_.blend_s;
  return twist;
}

double ObjectReplica::age_s(double t_s) const noexcept {
  return has_state_ ? t_s - state_.t_s : std::numeric_limits<double>::infinity();
}

void ObjectReplica::accept(const SharedObjectState& state, double now_s) noexcept {
  const Pose before = X_WO_at(now_s);
  state_ = state;
  has_state_ = true;
  const Pose after = dead_reckoned(now_s);
  t_accept_s_ = now_s;
  offset_p_W_m_ = before.translation() - after.translation();
  offset_q_W_ = (Eigen::Quaterniond(before.linear()) * Eigen::Quaterniond(after.linear()).conjugate()).normalized();
}

}  // namespace mhd
