#include "scene/rig_kind_check.h"

#include <string>

namespace mhd {
namespace {

std::string where_text(const SourceLocation& where) { return where.file + ":" + std::to_string(where.line); }

/// "the desktop rig (declared at file:line)".
std::string desktop_rig(const RigKindDeclaration& declared) {
  return "a desktop rig (declared at " + where_text(*declared.where) + ")";
}

}  // namespace

std::string_view to_string(RigKind kind) noexcept { return kind == RigKind::Desktop ? "desktop" : "mobile"; }

Diagnostics check_rig_kind(const SceneDescription& scene) {
  Diagnostics out;
  const RigKindDeclaration& declared = scene.rig_kind;
  if (declared.kind != RigKind::Desktop) return out;
  for (const PluginDescription& p : scene.plugins) {
    if (p.kind == PluginKind::Tracker || p.kind == PluginKind::Base) {
      const std::string kind = p.kind == PluginKind::Tracker ? "tracker" : "base";
      out.push_back({p.where, kind + " plugin '" + p.name + "' in " + desktop_rig(declared) +
                                  ": a desktop device is fixed in the world and has no " + kind +
                                  " (use <rig kind=\"mobile\">)"});
    }
  }
  if (scene.rig_lift) {
    out.push_back({scene.rig_lift->where, "<lift> in " + desktop_rig(declared) +
                                              ": a desktop device has no base to carry a lift (use <rig kind=\"mobile\">)"});
  }
  if (scene.planner) {
    out.push_back({scene.planner->where,
                   "<planner> in " + desktop_rig(declared) + ": there is no base to plan for (use <rig kind=\"mobile\">)"});
  }
  const FrameDescription* device = nullptr;
  for (const FrameDescription& f : scene.rig_frames) {
    if (f.name != kDesktopDeviceFrame) {
      out.push_back({f.where, "rig frame '" + f.name + "' in " + desktop_rig(declared) +
                                  ": its only frame is 'device' (parent 'world')"});
    } else if (f.parent != "world") {
      out.push_back({f.where, "rig frame 'device' of a desktop rig must have parent 'world', not '" + f.parent + "'"});
    } else {
      device = &f;
    }
  }
  if (device == nullptr) {
    out.push_back({*declared.where,
                   "a desktop rig needs the device's pose: <frame name=\"device\" parent=\"world\" .../>"});
  }
  return out;
}

Diagnostics check_rig_plugins_for_run(const SceneDescription& scene) {
  const SourceLocation where = scene.plugins_where.file.empty() ? SourceLocation{scene.file.string(), 0}
                                                                : scene.plugins_where;
  bool device = false;
  bool tracker = false;
  for (const PluginDescription& p : scene.plugins) {
    device = device || p.kind == PluginKind::Device;
    tracker = tracker || p.kind == PluginKind::Tracker;
  }
  Diagnostics out;
  if (!device) out.push_back({where, "the scene names no device plugin (<plugin kind=\"device\">)"});
  if (scene.rig_kind.kind == RigKind::Mobile && !tracker) {
    out.push_back({where, "the scene names no tracker plugin (<plugin kind=\"tracker\">), which a mobile rig needs "
                          "(a desk with the device alone: <rig kind=\"desktop\">, docs/desktop.md)"});
  }
  return out;
}

}  // namespace mhd
