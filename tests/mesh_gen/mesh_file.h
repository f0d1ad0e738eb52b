#pragma once
// Reads a mesh file back with assimp for the tests (independent of MHD's own loader).

#include "geometry/triangle_mesh.h"

#include <filesystem>

namespace mhd::mesh_gen::test {

/// All triangles of all meshes in the file, vertices at identical positions welded (the
/// way a loader rebuilds an indexed mesh from STL), coordinates multiplied by to_m. Adds a test
/// failure and returns an empty mesh when the file cannot be read.
[[nodiscard]] TriangleMesh read_mesh_file(const std::filesystem::path& file, double to_m);

}  // namespace mhd::mesh_gen::test
