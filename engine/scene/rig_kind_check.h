#pragma once
// What a rig kind allows (docs/desktop.md). A desktop rig is a device fixed in the world:
// no tracker, no base, no planner, and one rig frame, "device" with parent "world" (X_WD).
// A mobile rig (the default) needs a device and a tracker plugin to run; the scene reader
// checks only what a file can get wrong by itself (check_rig_kind), the haptic server
// also what running needs (check_rig_plugins_for_run), so a scene of objects alone stays valid.

#include "diagnostics/diagnostic.h"
#include "scene/scene_description.h"

#include <string_view>

namespace mhd {

/// "mobile" or "desktop".
[[nodiscard]] std::string_view to_string(RigKind kind) noexcept;

/// The frame of a desktop rig: the device frame D in the world.
inline constexpr std::string_view kDesktopDeviceFrame = "device";

/// A desktop scene's tracker or base plugin, planner, or a missing or misplaced "device"
/// frame, each at its own file:line.
[[nodiscard]] Diagnostics check_rig_kind(const SceneDescription& scene);

/// What running needs besides: one device plugin, and for a mobile rig a tracker plugin
/// (at the <plugins> element, else the scene file).
[[nodiscard]] Diagnostics check_rig_plugins_for_run(const SceneDescription& scene);

}  // namespace mhd
