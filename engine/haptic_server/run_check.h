#pragma once
// Everything `mhd run` refuses in a scene before it opens a plugin: the <server> settings,
// the rig, the simulated user, the rig's kind and plugins, one plugin of each driven kind,
// and the scene's planner. `mhd validate` calls the same function, so the two never
// disagree on a scene.

#include "diagnostics/diagnostic.h"
#include "plugin_host/plugin_search_path.h"
#include "scene/scene_description.h"

namespace mhd {

/// The settings every scene is judged by, run or not: <server>, <simulated_user>, and
/// <sharing> with its link plugin.
[[nodiscard]] Diagnostics check_scene_settings(const SceneDescription& scene);

/// What `mhd validate` and Python's `mhd.validate` judge before any mesh loads: the
/// settings (check_scene_settings); when they pass, each <plugin> found in `search`, of
/// its kind, and given only parameters its declarations allow, each problem at the
/// <plugin>'s line. Nothing is opened, so no hardware moves.
[[nodiscard]] Diagnostics check_scene_for_validate(const SceneDescription& scene, const PluginSearchPath& search);

/// Every problem, each at its file:line; empty when the scene can be run. With
/// `custom_planner`, the caller plans the base itself and the scene's planner is not built.
[[nodiscard]] Diagnostics check_scene_for_run(const SceneDescription& scene, bool custom_planner = false);

}  // namespace mhd
