#include "stress_test_scenes.h"

#include "scene_compiler/scene_compiler.h"

#include <gtest/gtest.h>

#include <utility>

namespace mhd::stress::test {

std::unique_ptr<CompiledScene> compile_uncached(const SceneDescription& d) {
  CompileOptions options;
  options.use_cache = false;
  Result<std::unique_ptr<CompiledScene>> r = compile_scene(d, options);
  if (!r.ok()) {
    ADD_FAILURE() << r.error_text();
    return nullptr;
  }
  return std::move(r).value();
}

ObjectDescription firm_object(const std::string& name, ShapeSource shape, const Eigen::Vector3d& p_W_m) {
  ObjectDescription o;
  o.name = name;
  o.shape = std::move(shape);
  o.X_WO.translation() = p_W_m;
  o.material.stiffness_N_per_m = 2000.0;
  o.material.damping_Ns_per_m = 1.0;
  o.material.static_friction = 0.2;
  o.material.dynamic_friction = 0.15;
  return o;
}

}  // namespace mhd::stress::test
