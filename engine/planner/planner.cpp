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

std::unique_ptr<Planner> make_planner(PlannerKind kind, const PlannerSettings& settings) {
  switch (kind) {
    case PlannerKind::Seed: return std::make_unique<SeedPlanner>(settings);
    case PlannerKind::Predictive: return std::make_unique<PredictivePlanner>(settings);
  }
  return nullptr;
}

}  // namespace mhd
