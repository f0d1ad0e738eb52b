#include "planner/planner.h"

#include "planner/planner_geometry.h"

#include "planner/predictive_planner.h"
#include "planner/seed_planner.h"

namespace mhd {

std::string_view to_string(PlannerCase c) noexcept {
  switch (c) {
    case PlannerCase::Idle: return "idle";
    case PlannerCase::Escape: return "escape";
    case PlannerCase::Straight: return "straight";
    case PlannerCase::SubTarget: return "sub-target";
    case PlannerCase::Stopping: return "stopping";
    case PlannerCase::Held: return "held";
  }
  return "?";
}

PlanarStart planar_start(const PlannerInput& in, const PlannerSettings& settings) noexcept {
  PlanarStart start;
  start.base_W = Eigen::Vector2d(in.base.x_m, in.base.z_m);
  start.hand_W = Eigen::Vector2d(in.p_W_hip.x(), in.p_W_hip.z());
  const Eigen::Vector2d hip_B = planner_geometry::hip_in_base(in.base, in.p_W_hip);
  start.out.hip_in_usable = settings.usable_B.contains(hip_B.x(), hip_B.y());
  return start;
}

PlannerOutput Planner::update(const PlannerInput& input) noexcept {
  if (input.keep_outs_current) return plan(input);
  active_ = false;
  PlannerOutput out = planar_start(input, settings_).out;
  out.status = PlannerCase::Held;
  out.goal_W = Eigen::Vector2d(input.base.x_m, input.base.z_m);
  out.target_W = out.goal_W;
  out.goal_heading_rad = input.base.heading_rad;
  return out;
}

std::unique_ptr<Planner> make_planner(PlannerKind kind, const PlannerSettings& settings) {
  switch (kind) {
    case PlannerKind::Seed: return std::make_unique<SeedPlanner>(settings);
    case PlannerKind::Predictive: return std::make_unique<PredictivePlanner>(settings);
  }
  return nullptr;
}

}  // namespace mhd
