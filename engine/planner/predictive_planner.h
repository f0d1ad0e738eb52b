#pragma once
// MHD's planner. What it does differently from the seed (docs/planner.md compares them):
//  - catch goal: instead of the single target on the user -> hand ray, the goal is the
//    base pose (x, z, heading) that puts the HIP inside the usable workspace (shrunk by
//    catch_margin_m) soonest, given the linear and angular limits: for headings sampled
//    within what one second of turning reaches, the nearest base position for which the
//    HIP is in the box (a clamp in B), timed max(distance / v_max, turn / omega_max); ties
//    lean towards facing the user. Goals inside the safety band are skipped;
//  - prediction: user and hand are extrapolated by the tracked user velocity over
//    prediction_horizon_s (the shift capped so the thesis target stays outside the band), and
//    the planner also starts when the predicted HIP leaves the usable workspace;
//  - holonomic shortcuts: straight to the goal whenever that segment keeps the safety band
//    from the user; otherwise, towards the thesis target, the largest sub-target step in
//    [pi', angle] whose chord keeps the band (bisection), never less than pi';
//  - deadbeat motion: full speed until one period from the goal, then the exact remainder;
//    the turn rate is the heading error over one period (no deceleration intervals). It stops
//    once the HIP is inside the shrunk box.
// Escape, limits and the guard are the seed's.

#include "planner/planner.h"

namespace mhd {

class PredictivePlanner final : public Planner {
 public:
  explicit PredictivePlanner(const PlannerSettings& settings) : Planner(settings) {}
  [[nodiscard]] PlannerKind kind() const noexcept override { return PlannerKind::Predictive; }

 private:
  [[nodiscard]] PlannerOutput plan(const PlannerInput& input) noexcept override;
};

}  // namespace mhd
