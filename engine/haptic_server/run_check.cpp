#include "haptic_server/run_check.h"

#include "haptic_server/scene_planner.h"
#include "haptic_server/server_settings.h"
#include "kinematics/rig.h"
#include "plugin_host/isolated_load.h"
#include "plugin_host/plugin_kind.h"
#include "plugin_host/scene_plugin_check.h"
#include "scene/rig_kind_check.h"
#include "simulation_config/simulated_user_params.h"

#include <string>

namespace mhd {

namespace {

/// The rig's problems as diagnostics, at their lines (the scene file's when they have none).
Diagnostics rig_problems(const SceneDescription& scene) {
  Diagnostics errors;
  const Result<Rig, std::vector<RigError>> rig = Rig::from_scene(scene);
  if (rig.ok()) return errors;
  for (const RigError& e : rig.error()) {
    errors.push_back({e.where.file.empty() ? SourceLocation{scene.file.string(), 0} : e.where, e.message});
  }
  return errors;
}

// Shared objects need a link to the other rigs, and a link has nothing to carry
// without them; the server drives one link.
Diagnostics link_problems(const SceneDescription& scene) {
  Diagnostics errors;
  const PluginDescription* link = nullptr;
  for (const PluginDescription& p : scene.plugins) {
    if (p.kind != PluginKind::Link) continue;
    if (link != nullptr) {
      errors.push_back({p.where, "a second link plugin '" + p.name + "' (the server drives one; the first is at line " +
                                     std::to_string(link->where.line) + ")"});
      continue;
    }
    link = &p;
  }
  if (scene.sharing && link == nullptr) {
    errors.push_back({scene.sharing->where, "<sharing> needs a <plugin kind=\"link\"> to carry the shared objects' "
                                            "states and pushes to the other rigs (e.g. dds_link)"});
  }
  if (!scene.sharing && link != nullptr) {
    errors.push_back({link->where, "link plugin '" + link->name + "' has nothing to carry: the scene shares no "
                                   "object (<sharing>)"});
  }
  return errors;
}

}  // namespace

Diagnostics check_scene_settings(const SceneDescription& scene) {
  Diagnostics errors = server_settings_from(scene).diagnostics();
  // A lift is judged against the rig that carries it (its axis must be vertical), so a
  // scene with one has its rig checked here, by validate too; run checks every rig.
  if (scene.rig_lift) {
    const Diagnostics rig = rig_problems(scene);
    errors.insert(errors.end(), rig.begin(), rig.end());
  }
  // The simulated plugins run the scene's <simulated_user> (libs/sim_world); its
  // errors still refuse the run here, at their lines, before any plugin opens.
  if (scene.simulated_user) {
    auto u = simulation::simulated_user_config_from(*scene.simulated_user);
    if (!u.ok()) errors.insert(errors.end(), u.error().begin(), u.error().end());
  }
  const Diagnostics link = link_problems(scene);
  errors.insert(errors.end(), link.begin(), link.end());
  return errors;
}

Diagnostics check_scene_for_validate(const SceneDescription& scene, const PluginSearchPath& search) {
  Diagnostics errors = check_scene_settings(scene);
  // Settings first, alone: a scene whose settings are wrong is not worth loading plugins for.
  if (!errors.empty()) return errors;
  for (const PluginDescription& plugin : scene.plugins) {
    // In a child process: looking at a plugin must not let its library crash or end this one.
    if (const Status<PluginError> s = check_scene_plugin_isolated(search, plugin); !s) {
      errors.push_back({plugin.where, s.error().to_string()});
    }
  }
  return errors;
}

Diagnostics check_scene_for_run(const SceneDescription& scene, bool custom_planner) {
  Diagnostics errors = check_scene_settings(scene);
  const auto add = [&errors](const Diagnostics& more) { errors.insert(errors.end(), more.begin(), more.end()); };
  if (!scene.rig_lift) add(rig_problems(scene));  // with a lift, check_scene_settings did
  const Result<Rig, std::vector<RigError>> rig = Rig::from_scene(scene);

  // One device, one tracker, at most one base (and one link: check_scene_settings).
  const PluginDescription* device = nullptr;
  const PluginDescription* tracker = nullptr;
  const PluginDescription* base = nullptr;
  for (const PluginDescription& p : scene.plugins) {
    const PluginDescription** slot = p.kind == PluginKind::Device    ? &device
                                     : p.kind == PluginKind::Tracker ? &tracker
                                     : p.kind == PluginKind::Base    ? &base
                                                                     : nullptr;
    if (slot == nullptr) continue;
    if (*slot != nullptr) {
      errors.push_back({p.where, "a second " + std::string(to_string(p.kind)) + " plugin '" + p.name +
                                     "' (the server drives one; the first is at line " +
                                     std::to_string((*slot)->where.line) + ")"});
    } else {
      *slot = &p;
    }
  }
  // The reader checked a file's rig kind; a description built in code is checked here.
  add(check_rig_kind(scene));
  add(check_rig_plugins_for_run(scene));
  if (rig.ok() && scene.rig_kind.kind != RigKind::Desktop && !custom_planner) {
    Result<ScenePlanner> made = scene_planner(scene, *rig);
    if (!made.ok()) add(made.error());
  }
  return errors;
}

}  // namespace mhd
