#pragma once
// The rig's frames in a plausible unit, for `mhd validate`: a rig is a few metres across,
// so a frame 755 m from its parent is millimetre values in a unit="m" scene, and frames
// all within a few millimetres of their parents are metre values in a unit="mm" one. A
// warning, not an error: such a scene loads, the device just is not where it was meant.

#include "diagnostics/diagnostic.h"
#include "scene/scene_description.h"

#include <optional>

namespace mhd::cli {

/// A frame farther than this from its parent: no lab rig spans it.
inline constexpr double kFarthestPlausibleFrame_m = 50.0;
/// Every offset frame nearer than this to its parent: the rig is 1000x too small.
inline constexpr double kNearestPlausibleRig_m = 0.005;

/// The warning, at the deciding <frame>'s line, or nothing for a plausible rig (or none).
[[nodiscard]] std::optional<Diagnostic> check_rig_scale(const SceneDescription& scene);

}  // namespace mhd::cli
