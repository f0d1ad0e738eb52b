#pragma once
// A still rig state for looking at a scene without a running haptic server (`mhd viewer
// --demo-state`, the documentation's screenshot): the base where the scene's sim_omni3
// plugin puts it (x_m, z_m, heading_deg; else at the origin), the HIP and the proxy
// together, out of contact, 8 cm above and 15 cm in front (+z) of the centre of the arm's
// usable workspace (with rig frames; else of a point 0.5 m ahead of the base at 1 m), and
// the user's head 0.7 m further towards +z and 0.5 m higher, looking at the HIP.

#include "viewer/rig_state.h"
#include "viewer/stereo_viewer.h"

#include <optional>

namespace mhd::viewer {

/// `base`, when given, replaces the base pose taken from the scene.
[[nodiscard]] RigState demo_rig_state(const ViewerScene& scene, const std::optional<BasePose>& base = std::nullopt);

}  // namespace mhd::viewer
