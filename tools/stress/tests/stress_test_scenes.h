#pragma once
// Small scenes for the stress tool's tests: objects with the strokes' usual material,
// compiled without the mesh cache (nothing on disk is shared between tests).

#include "scene/scene_description.h"
#include "scene_compiler/compiled_scene.h"

#include <Eigen/Core>

#include <memory>
#include <string>

namespace mhd::stress::test {

/// `d` compiled with no cache; a failed compile is a test failure and returns null.
[[nodiscard]] std::unique_ptr<CompiledScene> compile_uncached(const SceneDescription& d);

/// An object of `shape` at p_W_m (no rotation) in a firm, damped, rubbing material:
/// 2000 N/m, 1 N s/m, friction 0.2 static and 0.15 dynamic.
[[nodiscard]] ObjectDescription firm_object(const std::string& name, ShapeSource shape, const Eigen::Vector3d& p_W_m);

}  // namespace mhd::stress::test
