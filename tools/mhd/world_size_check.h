#pragma once
// The size of a compiled scene's objects, for `mhd validate`: each object's extents in
// metres, and a warning when the whole world has an implausible size, the sign of a unit
// mistake (metre values in a unit="mm" scene shrink it 1000x; millimetre values in metres
// grow it 1000x). A warning, not an error: such a scene loads, it just is not what was meant.

#include "diagnostics/diagnostic.h"
#include "scene/scene_description.h"
#include "scene_compiler/compiled_scene.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace mhd::cli {

/// All objects smaller than this (their largest extent): the world is too small to touch.
inline constexpr double kSmallestPlausibleWorld_m = 0.01;
/// All objects larger than this (their largest extent): no lab holds such a world.
inline constexpr double kLargestPlausibleObject_m = 1000.0;

struct ObjectExtents {
  std::string name;
  SourceLocation where;
  Eigen::Vector3d size_m = Eigen::Vector3d::Zero();  ///< in the object's own frame
};

struct WorldSize {
  std::vector<ObjectExtents> objects;  ///< in the scene's order
  std::optional<Diagnostic> warning;   ///< implausible world size, at the deciding object's line
};

/// Extents from the compiled shapes (meshes already scaled to metres).
[[nodiscard]] WorldSize check_world_size(const SceneDescription& description, const CompiledScene& scene);

}  // namespace mhd::cli
