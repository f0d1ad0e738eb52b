#pragma once
// Turns a SceneDescription into a CompiledScene: loads meshes (assimp), tessellates
// primitives, builds or fetches BVHs from the on-disk cache.

#include "diagnostics/result.h"
#include "scene/scene_description.h"
#include "scene_compiler/compiled_scene.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string_view>

namespace mhd {

struct CompileOptions {
  /// BVH cache folder; nullopt: $MHD_CACHE_DIR, else $XDG_CACHE_HOME/mhd, else ~/.cache/mhd.
  std::optional<std::filesystem::path> cache_dir;
  bool use_cache = true;
  /// Called with (what, fraction 0..1) while loading meshes over ~100k triangles.
  std::function<void(std::string_view, double)> progress;
};

/// The compiled scene (never null), or every object's problem (nothing half-loaded).
[[nodiscard]] Result<std::unique_ptr<CompiledScene>> compile_scene(const SceneDescription& description,
                                                                   const CompileOptions& options = {});

}  // namespace mhd
