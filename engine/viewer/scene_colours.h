#pragma once
// Scene format v1 has no colours (materials are haptic only), so the viewer gives each
// material a colour: a fixed one for the shared materials (scenes/common/materials.xml),
// and for any other name a stable colour from a hash of the name, so the same material
// looks the same in every scene and run.

#include <Eigen/Core>

#include <string_view>

namespace mhd::viewer {

/// RGBA in [0, 1]. An empty name (an inline material) takes the object's name instead.
[[nodiscard]] Eigen::Vector4f material_colour(std::string_view material_name, std::string_view object_name);

}  // namespace mhd::viewer
