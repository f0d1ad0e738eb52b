#pragma once
// Reads scene XML (format v1, docs/scene-format.md) into a SceneDescription.
// Every problem is reported with file:line; a scene with any error is not returned,
// so nothing is ever half-loaded.

#include "diagnostics/result.h"
#include "scene/scene_description.h"

#include <filesystem>
#include <optional>
#include <string_view>

namespace mhd {

/// Reads a scene file and its includes: the scene, or every problem found in it, in
/// file order (never half a scene). Mesh files are checked to exist and be
/// readable, not loaded.
[[nodiscard]] Result<SceneDescription> read_scene_file(const std::filesystem::path& file);

/// Reads scene XML from memory; relative paths resolve against `file`'s folder and
/// diagnostics name `file`.
[[nodiscard]] Result<SceneDescription> read_scene_string(std::string_view xml, const std::filesystem::path& file);

}  // namespace mhd
