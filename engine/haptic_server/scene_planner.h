#pragma once
// The base planner a scene asks for with <planner kind="seed|predictive"> and its params
// (engine/planner/planner_settings.h names them), wrapped as the server's BasePlanFn. The
// usable workspace defaults to the rig's; a scene without <planner> gets no planner (the
// base holds still).

#include "haptic_server/haptic_server.h"
#include "kinematics/rig.h"
#include "planner/planner_settings.h"
#include "diagnostics/result.h"
#include "scene/scene_description.h"

#include "plugin_host/hardware_io.h"

#include <optional>

namespace mhd {

struct ScenePlanner {
  BasePlanFn plan;  ///< empty without <planner>
  double collision_radius_m = 0.0;  ///< robot + human radius, for the server's keep-out guard
  PlanarBox usable_B;               ///< where it keeps the HIP, base frame (with a plan)
};

/// The scene's planner, or every error in its <planner> block. It keeps the HIP in
/// `usable_P` (device frame) when given, else in the rig model's usable workspace.
[[nodiscard]] Result<ScenePlanner> scene_planner(const SceneDescription& scene, const Rig& rig,
                                                 const std::optional<WorkspaceBox>& usable_P = std::nullopt);

/// The usable workspace of a device from its own report: the largest of its workspace
/// boxes (a box inside the union, which may not be convex), moved in by `margin_m` on
/// every side. Null when it reports no box or the margin leaves nothing.
[[nodiscard]] std::optional<WorkspaceBox> usable_device_workspace(const DeviceInfo& info, double margin_m);

}  // namespace mhd
