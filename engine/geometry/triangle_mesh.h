#pragma once
// An indexed triangle mesh in one object's local frame, in metres.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "geometry/mesh_array.h"

#include <array>
#include <cstdint>
#include <vector>

namespace mhd {

using TriangleIndices = std::array<std::uint32_t, 3>;

struct TriangleMesh {
  /// Vertex positions p_O (object frame), metres, the object's scale already applied.
  MeshArray<Eigen::Vector3d> vertices_m;
  /// Counter-clockwise seen from the outside where the mesh has an outside.
  MeshArray<TriangleIndices> triangles;
  /// Unit, area-weighted vertex normals; empty until computed. Single precision: they
  /// only give directions to shade by (rounding of about 1e-7 rad), and it halves their
  /// memory, which a large mesh keeps resident.
  MeshArray<Eigen::Vector3f> vertex_normals;

  [[nodiscard]] std::size_t triangle_count() const { return triangles.size(); }
};

/// Fills mesh.vertex_normals with area-weighted unit normals. A vertex that only
/// touches degenerate triangles gets the zero vector.
void compute_vertex_normals(TriangleMesh& mesh);

/// Axis-aligned bounds of the vertices; empty box for an empty mesh.
[[nodiscard]] Eigen::AlignedBox3d mesh_bounds(const TriangleMesh& mesh);

/// Drops triangles whose corners are not three distinct valid vertex indices.
/// Returns how many were dropped.
std::size_t remove_invalid_triangles(TriangleMesh& mesh);

}  // namespace mhd
