#pragma once
// Writes a TriangleMesh, the format chosen by the file's extension: .ply (binary PLY,
// streamed by hand so any size fits), .obj (no material file) and .stl (binary STL)
// through assimp's exporter.

#include "geometry/triangle_mesh.h"

#include <filesystem>
#include <string>

namespace mhd::mesh_gen {

/// The assimp exporter id for the file's extension ("plyb", "objnomtl", "stlb"); throws
/// std::runtime_error for any other extension.
[[nodiscard]] std::string mesh_file_format(const std::filesystem::path& file);

/// Writes `mesh` with every coordinate multiplied by file_units_per_m (1000 writes
/// millimetres). An existing file is replaced whole: one who has it open, or opens it
/// meanwhile, reads the old mesh or the new one, never a part. Throws std::runtime_error
/// for an unknown extension or a failed write, which leaves the old file as it was.
void write_mesh_file(const TriangleMesh& mesh, const std::filesystem::path& file, double file_units_per_m);

}  // namespace mhd::mesh_gen
