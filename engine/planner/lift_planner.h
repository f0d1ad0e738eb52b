#pragma once
// The lift's planner (kinematics/rig.h, "lift"): the height that keeps the user's hand at
// the middle of the arm's vertical reach, followed within the lift's range, speed and
// acceleration. The follower is the time-optimal one for a bounded acceleration: it
// drives at up to max speed and brakes at max acceleration so that it stops on the target,
// never beyond it and never outside the range. A target that is not a finite number (no
// hand, or a stale one) brakes the lift to a stop where it is.
//
// step() is noexcept, allocation-free and deterministic; the planner holds no state.

#include "kinematics/rig.h"

namespace mhd {

/// The lift's height (0: the rig file's arm frame) and vertical speed, in SI units.
struct LiftState {
  double height_m = 0.0;
  double velocity_mps = 0.0;
};

class LiftPlanner {
 public:
  /// `lift`: the rig's range and limits (checked by Rig::from_scene).
  /// `reach_centre_above_phantom_m`: how far above the arm's frame P the middle of the
  /// arm's vertical reach is, along world up.
  LiftPlanner(const Lift& lift, double reach_centre_above_phantom_m) noexcept
      : lift_(lift), reach_centre_above_phantom_m_(reach_centre_above_phantom_m) {}

  /// The lift height that puts the middle of the arm's reach at the hand's height,
  /// `hand_y_W_m`, given the arm frame's height at lift 0, `phantom_y_W_m`; clamped to the
  /// range. NaN when either is not finite.
  [[nodiscard]] double target_for_hand(double hand_y_W_m, double phantom_y_W_m) const noexcept;

  /// The state `dt_s` later, following `target_height_m` (NaN: stop). A dt that is not a
  /// positive finite number changes nothing.
  [[nodiscard]] LiftState step(const LiftState& now, double target_height_m, double dt_s) const noexcept;

  [[nodiscard]] const Lift& lift() const noexcept { return lift_; }

 private:
  Lift lift_;
  double reach_centre_above_phantom_m_;
};

/// How far above the arm's frame P the middle of its usable workspace's vertical extent is,
/// along the base's up (world up): the reach centre a LiftPlanner keeps at the hand.
[[nodiscard]] double reach_centre_above_phantom_m(const Rig& rig) noexcept;

}  // namespace mhd
