#include "planner/planner.h"

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

std::unique_ptr<Planner> make_planner(PlannerKind kind, const PlannerSettings& settings) {
  switch (kind) {
    case PlannerKind::Seed: return std::make_unique<SeedPlanner>(settings);
    case PlannerKind::Predictive: return std::make_unique<PredictivePlanner>(settings);
  }
  return nullptr;
}

}  // namespace mhd
