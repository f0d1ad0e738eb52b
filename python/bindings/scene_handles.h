#pragma once
// What Python holds of a scene. A read scene and a compiled one are immutable and shared:
// a compiled scene keeps its description alive (the server needs both), and a Proxy keeps
// its compiled scene alive, whatever Python frees first.

#include "scene/scene_description.h"
#include "scene_compiler/compiled_scene.h"

#include <memory>

namespace mhd::python {

struct SceneHandle {
  std::shared_ptr<const SceneDescription> description;
};

struct CompiledSceneHandle {
  std::shared_ptr<const SceneDescription> description;
  std::shared_ptr<const CompiledScene> compiled;
};

}  // namespace mhd::python
