#include "mesh_io/texture_references.h"

#include "mesh_io/regular_file.h"

#include <assimp/material.h>
#include <assimp/scene.h>

#include <fmt/format.h>

namespace mhd {

std::string texture_problem(const aiScene* scene, const std::filesystem::path& mesh_file) {
  if (scene == nullptr) return {};
  for (unsigned m = 0; m < scene->mNumMaterials; ++m) {
    const aiMaterial* material = scene->mMaterials[m];
    if (material == nullptr) continue;
    for (int t = aiTextureType_NONE; t <= AI_TEXTURE_TYPE_MAX; ++t) {
      const auto type = static_cast<aiTextureType>(t);
      for (unsigned i = 0; i < material->GetTextureCount(type); ++i) {
        aiString name;
        if (material->GetTexture(type, i, &name) != aiReturn_SUCCESS || name.length == 0) continue;
        if (name.data[0] == '*') continue;  // embedded: no file
        std::filesystem::path path(name.C_Str());
        if (path.is_relative()) path = mesh_file.parent_path() / path;
        const std::string problem = regular_file_problem(path);
        if (!problem.empty() && problem != "file not found") {
          return fmt::format("texture '{}' {}", path.string(), problem);
        }
      }
    }
  }
  return {};
}

}  // namespace mhd
