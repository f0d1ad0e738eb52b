#pragma once
// Where a command may write: only a new file or over a regular file, never over a device,
// a FIFO or a folder (a rename would replace /dev/full with a CSV), and never over a file
// the command reads (a recording named like its scene would overwrite the scene).

#include "scene/scene_description.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace mhd::cli {

/// Why `output` must not be written, or nothing when it may. `inputs` are the files the
/// command reads.
[[nodiscard]] std::optional<std::string> output_path_problem(const std::filesystem::path& output,
                                                             const std::vector<std::filesystem::path>& inputs);

/// The files a scene command reads: the scene file and its mesh files.
[[nodiscard]] std::vector<std::filesystem::path> scene_inputs(const SceneDescription& scene);

}  // namespace mhd::cli
