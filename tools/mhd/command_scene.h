#pragma once
// A command's scene: read, then compiled, each step's diagnostics printed on stderr as
// every command prints them, the mesh loads' progress shown (load_progress.h).

#include "scene/scene_description.h"
#include "scene_compiler/compiled_scene.h"

#include <filesystem>
#include <memory>
#include <optional>

namespace mhd::cli {

/// The scene file read; nullopt when it has errors.
[[nodiscard]] std::optional<SceneDescription> read_command_scene(const std::filesystem::path& file);

/// The scene compiled (with the BVH cache unless `use_cache` is false); null when it has errors.
[[nodiscard]] std::unique_ptr<CompiledScene> compile_command_scene(const SceneDescription& scene, bool use_cache = true);

}  // namespace mhd::cli
