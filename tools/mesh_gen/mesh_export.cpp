#include "mesh_gen/mesh_export.h"

#include <assimp/Exporter.hpp>
#include <assimp/material.h>
#include <assimp/mesh.h>
#include <assimp/scene.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

namespace mhd::mesh_gen {
std::string mesh_file_format(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".ply") return "plyb";
  if (ext == ".obj") return "objnomtl";
  if (ext == ".stl") return "stlb";
  throw std::runtime_error("cannot write '" + file.string() + "': unknown extension (use .ply, .obj or .stl)");
}

namespace {

// Binary PLY written as a stream: assimp's exporter holds a second copy of the mesh with
// one heap block per face, about 50 bytes per triangle more than the mesh itself, which
// at hundreds of millions of triangles does not fit.
void write_binary_ply(const TriangleMesh& mesh, const std::filesystem::path& file, double file_units_per_m) {
  static_assert(std::endian::native == std::endian::little, "binary_little_endian is written as in memory");
  if (mesh.vertices_m.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
    throw std::runtime_error("cannot write '" + file.string() + "': more vertices than a PLY int index reaches");
  }
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot write '" + file.string() + "': " + std::strerror(errno));
  out << "ply\nformat binary_little_endian 1.0\ncomment written by mhd-mesh-gen\n"
      << "element vertex " << mesh.vertices_m.size() << "\nproperty float x\nproperty float y\nproperty float z\n"
      << "element face " << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  std::vector<char> chunk;
  constexpr std::size_t kChunkBytes = std::size_t{1} << 22;
  chunk.reserve(kChunkBytes + 64);
  auto put = [&chunk](const auto& value) {
    const auto* bytes = reinterpret_cast<const char*>(&value);
    chunk.insert(chunk.end(), bytes, bytes + sizeof value);
  };
  auto flush = [&](bool force) {
    if (!force && chunk.size() < kChunkBytes) return;
    out.write(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    chunk.clear();
  };
  for (const Eigen::Vector3d& v : mesh.vertices_m) {
    const Eigen::Vector3f p = (v * file_units_per_m).cast<float>();
    put(p.x());
    put(p.y());
    put(p.z());
    flush(false);
  }
  for (const TriangleIndices& t : mesh.triangles) {
    put(std::uint8_t{3});
    for (const std::uint32_t i : t) put(static_cast<std::int32_t>(i));
    flush(false);
  }
  flush(true);
  out.close();
  if (!out) throw std::runtime_error("cannot write '" + file.string() + "': " + std::strerror(errno));
}

// Writes `file` in assimp's `format` (or the streamed binary PLY).
void write_mesh_file_as(const TriangleMesh& mesh, const std::filesystem::path& file, const std::string& format,
                        double file_units_per_m) {
  if (format == "plyb") {
    write_binary_ply(mesh, file, file_units_per_m);
    return;
  }
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

}  // namespace

void write_mesh_file(const TriangleMesh& mesh, const std::filesystem::path& file, double file_units_per_m) {
  const std::string format = mesh_file_format(file);
  // Written beside the file, then renamed over it: a reader of the file (a test of another
  // build, while this one regenerates the assets) sees the old mesh or the new one, never a
  // part, and a failed write leaves the old one.
  std::filesystem::path part = file;
  part += ".part" + std::to_string(::getpid());
  try {
    write_mesh_file_as(mesh, part, format, file_units_per_m);
    std::filesystem::rename(part, file);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(part, ignored);
    throw;
  }
}

}  // namespace mhd::mesh_gen
