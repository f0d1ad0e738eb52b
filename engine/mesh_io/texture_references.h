#pragma once
// Texture paths named by a loaded file's materials. MHD never reads textures, so a
// missing one is fine; one that exists but is not a regular file (a FIFO, a device, a
// directory, a symlink loop) marks a hostile or broken file and is refused.

#include <filesystem>
#include <string>

struct aiScene;

namespace mhd {

/// "texture '<path>' <problem>" for the first such texture of `scene` (paths resolved
/// against `mesh_file`'s folder), else "".
[[nodiscard]] std::string texture_problem(const aiScene* scene, const std::filesystem::path& mesh_file);

}  // namespace mhd
