#pragma once
// A rig's rendering of a shared object whose physics another rig (its authority) runs.
// The newest obeyed state arrives late by the network's delay; the replica hides that
// by dead reckoning (the state carried on by its own twist to the time rendered), for at
// most max_extrapolation_s: older data holds the object where it was last extrapolated,
// still, rather than carry it on for ever. A new state that disagrees with what is
// rendered is blended in over blend_s, so the object never jumps; the proxy is carried by
// whatever the rendered object does (MovingWorld), so a correction never pops through.
// Allocates nothing.

#include "sharing/shared_object_state.h"

namespace mhd {

struct ReplicaSettings {
  /// Dead reckoning's horizon: longer than any delay the link is allowed (the stale
  /// timeout), short enough that a lost authority leaves the object near the truth.
  double max_extrapolation_s = 0.1;
  /// Time over which a correction is spread (0: taken at once).
  double blend_s = 0.03;
};

class ObjectReplica {
 public:
  ObjectReplica(const Pose& X_WO_0, const ReplicaSettings& settings = {}) noexcept;

  /// Takes an obeyed state (ObjectAuthority::judge) that arrived at now_s.
  void accept(const SharedObjectState& state, double now_s) noexcept;

  /// The object as rendered at t_s (t_s no earlier than the last accept()).
  [[nodiscard]] Pose X_WO_at(double t_s) const noexcept;
  /// Its velocity as rendered at t_s: the state's, zero beyond the horizon, plus the
  /// blend's own linear rate.
  [[nodiscard]] ObjectTwist twist_at(double t_s) const noexcept;
  /// How old the state rendered at t_s is; infinite before the first.
  [[nodiscard]] double age_s(double t_s) const noexcept;
  [[nodiscard]] bool has_state() const noexcept { return has_state_; }

 private:
  [[nodiscard]] Pose dead_reckoned(double t_s) const noexcept;
  [[nodiscard]] double blend_weight(double t_s) const noexcept;

  ReplicaSettings settings_;
  SharedObjectState state_;
  bool has_state_ = false;
  double t_accept_s_ = 0.0;
  Eigen::Vector3d offset_p_W_m_ = Eigen::Vector3d::Zero();
  Eigen::Quaterniond offset_q_W_ = Eigen::Quaterniond::Identity();
};

}  // namespace mhd
