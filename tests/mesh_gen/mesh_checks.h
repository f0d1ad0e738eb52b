#pragma once
// Independent checks of generated meshes, written for the tests: edge manifoldness,
// topology, inside/outside by winding number, triangle quality and self-intersections.

#include "geometry/triangle_mesh.h"

#include <cstddef>

namespace mhd::mesh_gen::test {

struct EdgeStats {
  std::size_t edges = 0;               ///< undirected edges
  std::size_t boundary = 0;            ///< used by exactly one triangle
  std::size_t manifold_oriented = 0;   ///< used by exactly two triangles, in opposite directions
  std::size_t bad = 0;                 ///< anything else (3+ triangles, or two in the same direction)
};

[[nodiscard]] EdgeStats edge_stats(const TriangleMesh& mesh);

/// V - E + F over the vertices that triangles use.
[[nodiscard]] long euler_characteristic(const TriangleMesh& mesh);

/// Signed volume (positive for a closed, outward-facing mesh).
[[nodiscard]] double enclosed_volume(const TriangleMesh& mesh);

/// Generalised winding number of p (sum of signed solid angles / 4 pi): ~1 inside a
/// closed outward-facing mesh, ~0 outside.
[[nodiscard]] double winding_number(const TriangleMesh& mesh, const Eigen::Vector3d& p);

/// Smallest 2 * area / (longest edge)^2 over all triangles (0 for a degenerate one;
/// an equilateral triangle has sqrt(3)/2).
[[nodiscard]] double min_triangle_shape(const TriangleMesh& mesh);

[[nodiscard]] double min_triangle_area(const TriangleMesh& mesh);

/// Pairs of triangles that cross each other, not counting shared vertices or edges; an
/// edge-sharing pair counts when it folds flat onto itself.
[[nodiscard]] std::size_t count_self_intersections(const TriangleMesh& mesh);

}  // namespace mhd::mesh_gen::test
