#include "mesh_gen/mesh_export.h"

#include <assimp/Exporter.hpp>
#include <assimp/material.h>
#include <assimp/mesh.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

namespace mhd::mesh_gen {
std::string mesh_file_format(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".ply") return "plyb";
  if (ext == ".obj") return "objnomtl";
  if (ext == ".stl") return "stlb";
  throw std::runtime_error("cannot write '" + file.string() + "': unknown extension (use .ply, .obj or .stl)");
}

void write_mesh_file(const TriangleMesh& mesh, const std::filesystem::path& file, double file_units_per_m) {
  const std::string format = mesh_file_format(file);
  if (mesh.vertices_m.size() > std::numeric_limits<unsigned int>::max() ||
      mesh.triangles.size() > std::numeric_limits<unsigned int>::max()) {
    throw std::runtime_error("cannot write '" + file.string() + "': mesh too large");
  }

  // aiScene's destructor frees everything hung off it, so build it with plain new[].
  auto scene = std::make_unique<aiScene>();
  scene->mRootNode = new aiNode();
  scene->mRootNode->mNumMeshes = 1;
  scene->mRootNode->mMeshes = new unsigned int[1]{0};
  scene->mNumMaterials = 1;
  scene->mMaterials = new aiMaterial*[1]{new aiMaterial()};
  scene->mNumMeshes = 1;
  scene->mMeshes = new aiMesh*[1]{new aiMesh()};

  aiMesh& out = *scene->mMeshes[0];
  out.mMaterialIndex = 0;
  out.mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  out.mNumVertices = static_cast<unsigned int>(mesh.vertices_m.size());
  out.mVertices = new aiVector3D[out.mNumVertices];
  for (unsigned int i = 0; i < out.mNumVertices; ++i) {
    const Eigen::Vector3d p = mesh.vertices_m[i] * file_units_per_m;
    out.mVertices[i] = aiVector3D(static_cast<ai_real>(p.x()), static_cast<ai_real>(p.y()), static_cast<ai_real>(p.z()));
  }
  out.mNumFaces = static_cast<unsigned int>(mesh.triangles.size());
  out.mFaces = new aiFace[out.mNumFaces];
  for (unsigned int f = 0; f < out.mNumFaces; ++f) {
    aiFace& face = out.mFaces[f];
    face.mNumIndices = 3;
    face.mIndices = new unsigned int[3]{mesh.triangles[f][0], mesh.triangles[f][1], mesh.triangles[f][2]};
  }

  Assimp::Exporter exporter;
  if (exporter.Export(scene.get(), format, file.string()) != aiReturn_SUCCESS) {
    throw std::runtime_error("cannot write '" + file.string() + "': " + exporter.GetErrorString());
  }
}

}  // namespace mhd::mesh_gen
