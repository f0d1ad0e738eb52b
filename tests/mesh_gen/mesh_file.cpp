#include "mesh_file.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace mhd::mesh_gen::test {

TriangleMesh read_mesh_file(const std::filesystem::path& file, double to_m) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(file.string(), 0);
  TriangleMesh mesh;
  if (scene == nullptr) {
    ADD_FAILURE() << file << ": " << importer.GetErrorString();
    return mesh;
  }
  // Weld by exact position: assimp's JoinIdenticalVertices keeps STL's per-face normals apart.
  std::map<std::array<ai_real, 3>, std::uint32_t> index_of;
  for (unsigned int m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& in = *scene->mMeshes[m];
    std::vector<std::uint32_t> welded(in.mNumVertices);
    for (unsigned int i = 0; i < in.mNumVertices; ++i) {
      const aiVector3D& p = in.mVertices[i];
      const auto [it, inserted] =
          index_of.try_emplace({p.x, p.y, p.z}, static_cast<std::uint32_t>(mesh.vertices_m.size()));
      if (inserted) mesh.vertices_m.emplace_back(Eigen::Vector3d(p.x, p.y, p.z) * to_m);
      welded[i] = it->second;
    }
    for (unsigned int f = 0; f < in.mNumFaces; ++f) {
      const aiFace& face = in.mFaces[f];
      if (face.mNumIndices == 3) {
        mesh.triangles.push_back({welded[face.mIndices[0]], welded[face.mIndices[1]], welded[face.mIndices[2]]});
      }
    }
  }
  return mesh;
}

}  // namespace mhd::mesh_gen::test
