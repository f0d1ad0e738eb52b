#pragma once
// The base planner a scene asks for with <planner kind="seed|predictive"> and its params
// (engine/planner/planner_settings.h names them), wrapped as the server's BasePlanFn. The
// usable workspace defaults to the rig's; a scene without <planner> gets no planner (the
// base holds still).

#include "haptic_server/haptic_server.h"
#include "kinematics/rig.h"
#include "diagnostics/result.h"
#include "scene/scene_description.h"

#include <optional>

namespace mhd {

struct ScenePlanner {
  BasePlanFn plan;  ///< empty without <planner>
  double collision_radius_m = 0.0;  ///< robot + human radius, for the server's keep-out guard
};

/// The scene's planner, or every error in its <planner> block.
[[nodiscard]] Result<ScenePlanner> scene_planner(const SceneDescription& scene, const Rig& rig);

}  // namespace mhd
