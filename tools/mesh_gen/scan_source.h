#pragma once
// What a range scan scans: one of our generated meshes by name, or a mesh file.

#include "geometry/triangle_mesh.h"

#include <cstddef>
#include <optional>
#include <string>

namespace mhd::mesh_gen {

struct ScanSourceOptions {
  /// Triangles of a generated source (dolphin, bowl, uv-sphere).
  std::size_t generator_triangles = 200'000;
  /// Metres per unit of a mesh file (nullopt: 0.001, our files are in millimetres);
  /// must stay unset for a generated source.
  std::optional<double> file_unit_m;
};

/// The generated sources by name, for messages: "dolphin, bowl, uv-sphere".
[[nodiscard]] std::string scan_source_names();

/// `source` is a generator name (dolphin: 2000 mm long; bowl: the 150 mm hemisphere of
/// assets/bowl.ply; uv-sphere: radius 100 mm), else, if it has a folder or an
/// extension, a mesh file read by MHD's own loader (load_mesh_file) and scaled by
/// file_unit_m. Metres, in the source's own frame. Throws std::invalid_argument for an
/// unknown name or bad options, std::runtime_error for a file that cannot be loaded.
[[nodiscard]] TriangleMesh load_scan_source(const std::string& source, const ScanSourceOptions& options);

}  // namespace mhd::mesh_gen
