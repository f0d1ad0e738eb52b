#include "haptic_server/scene_planner.h"

#include "planner/floor_view.h"
#include "planner/planner.h"
#include "planner/planner_settings.h"

#include <algorithm>
#include <cstdint>
#include <memory>

namespace mhd {

Result<ScenePlanner> scene_planner(const SceneDescription& scene, const Rig& rig,
                                   const std::optional<WorkspaceBox>& usable_P) {
  if (!scene.planner) return ScenePlanner{};
  Diagnostics errors;
  const ParamBlock& block = *scene.planner;
  PlannerKind kind = PlannerKind::Seed;
  if (!parse_planner_kind(block.kind, kind)) {
    errors.push_back({block.where, "unknown planner kind '" + block.kind + "' (expected seed or predictive)"});
  }
  PlannerSettings defaults;
  defaults.usable_B = usable_P ? usable_box_in_base(rig, *usable_P) : usable_box_in_base(rig);
  const Result<PlannerSettings, std::vector<std::string>> parsed = planner_settings_from_map(block.params, defaults);
  if (!parsed.ok()) {
    for (const std::string& e : parsed.error()) {
      // The message names the setting; point at its line when it has one.
      SourceLocation where = block.where;
      for (const auto& [name, line] : block.param_where) {
        if (e.find("'" + name + "'") != std::string::npos) where = line;
      }
      errors.push_back({where, e});
    }
  }
  if (!errors.empty()) return errors;

  std::shared_ptr<Planner> planner = make_planner(kind, *parsed);
  ScenePlanner out;
  out.collision_radius_m = parsed->collision_radius_m();
  out.usable_B = parsed->usable_B;
  out.plan = [planner, settings = *parsed](const BasePlanInput& in) {
    if (!in.hip_valid || !in.user_known || !in.fresh()) return BaseTwist{};  // nothing fresh to follow: hold still
    PlannerInput p;
    p.time_s = in.t_s;
    p.base = in.base;
    p.user_W = in.user_xz_W_m;
    p.user_heading_rad = in.user_heading_rad;
    p.user_velocity_W = in.user_velocity_W_mps;
    p.p_W_hip = in.p_W_hip;
    const FloorKeepOuts floor = floor_keep_outs(in.floor, in.t_s, in.floor_timeout_s, settings);
    p.keep_outs = floor.keep_outs;
    p.keep_outs_current = floor.current;
    return planner->update(p).twist_B;
  };
  return out;
}

std::optional<WorkspaceBox> usable_device_workspace(const DeviceInfo& info, double margin_m) {
  std::optional<WorkspaceBox> largest;
  const std::uint32_t count = std::min<std::uint32_t>(info.workspace_box_count, static_cast<std::uint32_t>(DeviceInfo::kMaxWorkspaceBoxes));
  for (std::uint32_t i = 0; i < count; ++i) {
    const WorkspaceBoxD& b = info.workspace[i];
    const WorkspaceBox box{Eigen::Vector3d(b.min_m[0], b.min_m[1], b.min_m[2]),
                           Eigen::Vector3d(b.max_m[0], b.max_m[1], b.max_m[2])};
    if (!largest || box.size_m().prod() > largest->size_m().prod()) largest = box;
  }
  if (!largest) return std::nullopt;
  const WorkspaceBox usable = largest->shrunk(margin_m);
  if (!(usable.min_P_m.array() < usable.max_P_m.array()).all()) return std::nullopt;
  return usable;
}

}  // namespace mhd
