#pragma once
// Loads a mesh file (any format assimp reads) into one TriangleMesh in metres.

#include "diagnostics/result.h"
#include "geometry/triangle_mesh.h"
#include "mesh_io/isolated_assimp_read.h"
#include "mesh_io/triangle_budget.h"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace mhd {

/// Progress of a long step: (what is being done, fraction 0..1 of that step).
using MeshProgress = std::function<void(std::string_view, double)>;

/// Why a mesh file could not be used.
struct MeshLoadError {
  std::filesystem::path file;
  std::string reason;  ///< e.g. "file not found", "mesh has no triangles"
  /// "mesh file '<file>': <reason>"
  [[nodiscard]] std::string message() const;
};

struct LoadedMesh {
  TriangleMesh mesh;
  /// Triangles dropped: bad or repeated indices, zero area, non-triangle faces.
  std::size_t dropped_triangles = 0;
  /// Triangles turned to the winding of the surface they belong to.
  std::size_t flipped_triangles = 0;
  /// Empty when assimp read the file in a child process; else why none could start
  /// (AssimpRead::unisolated_read).
  std::string unisolated_read;
};

/// What a mesh file's first kMeshHeaderBytes can refuse it for: not a readable regular
/// file, empty, header counts that do not fit its size, and with a `budget` a header face
/// count over what is left of max_triangles or, at `bytes_per_triangle`, over the memory
/// available. nullopt when none refuses it. Reads the head only, so its time does not
/// grow with the file.
[[nodiscard]] std::optional<MeshLoadError> refusal_from_header(const std::filesystem::path& file,
                                                               const std::optional<TriangleBudget>& budget,
                                                               std::uint64_t bytes_per_triangle);

/// Loads every triangle of every mesh in `file` (scene-graph transforms applied, points
/// and lines dropped) into one mesh, multiplies coordinates by `scale_to_m` per axis
/// (a mirroring scale, i.e. an odd number of negative factors, flips the winding so the
/// mesh keeps facing outwards), welds vertices at identical positions across the
/// file's meshes, drops degenerate triangles and unused vertices, turns triangles wound
/// against the rest of their surface (orient_coherently), and computes vertex normals. Positions pass through assimp's single precision.
/// `progress`, if set, receives assimp's read/post-processing progress.
/// Bounded: the file and every side file assimp opens (an OBJ's mtllib) must be regular
/// files, and so must textures that exist; a PLY's or binary STL's header counts must fit
/// the file's size, and with a `budget` neither the header's face count (checked before
/// assimp allocates) nor the loaded triangles may exceed what is left of it. assimp reads
/// in a child process (read_with_assimp): a reader that crashes, or runs past `limits`,
/// ends as an error.
[[nodiscard]] Result<LoadedMesh, MeshLoadError> load_mesh_file(const std::filesystem::path& file,
                                                              const Eigen::Vector3d& scale_to_m,
                                                              const MeshProgress& progress = {},
                                                              std::optional<TriangleBudget> budget = std::nullopt,
                                                              const MeshReadLimits& limits = {});

/// What the loader's clean-up changed.
struct MeshCleanUp {
  std::size_t dropped_triangles = 0;
  std::size_t flipped_triangles = 0;
};

/// Applies the loader's clean-up to a mesh in memory: scale (and winding flip for a
/// mirroring scale), invalid/degenerate triangle and unused vertex removal, one winding
/// per surface (orient_coherently), vertex normals. Exposed for tests and tools.
MeshCleanUp finish_loaded_mesh(TriangleMesh& mesh, const Eigen::Vector3d& scale_to_m);

}  // namespace mhd
