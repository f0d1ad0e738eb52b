#pragma once
// Normals for force shading (Ruspini, Kolarov & Khatib 1997): one normal per triangle
// corner, so that a vertex on a crease (a cube's edge) can carry a different normal on
// each side of it while a vertex on a smooth, coarsely tessellated surface (a sphere)
// carries one normal shared by all its triangles. Computed once, when a scene is
// compiled; read by the proxy each tick.

#include "geometry/triangle_mesh.h"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace mhd {

struct ShadingNormals {
  /// corner_normals_O[t][i]: unit normal, in the object frame, at corner i of triangle t.
  /// Indexed like TriangleMesh::triangles. Single precision: a direction good to 1e-7
  /// rad is far below what a hand feels, and it halves the memory of a large scan.
  std::vector<std::array<Eigen::Vector3f, 3>> corner_normals_O;
  /// Faces meeting at an angle above this (radians) keep their own normal at the edge.
  double crease_angle_rad = 0.0;
};

/// Crease-aware, angle-weighted corner normals of `mesh`. At each corner, the normal
/// is the sum of the unit normals of the triangles that share the corner's position
/// (vertices at the same position count as one, so unwelded STL meshes shade too),
/// each weighted by its angle at that position, taken over those triangles whose normal
/// is within `crease_angle_rad` of this triangle's own. A corner with nothing to sum
/// (degenerate triangles only) gets the face normal, or zero for a degenerate face.
/// Angle weighting (Thürmer & Wüthrich 1998) makes the normal independent of how a
/// face is split into triangles, so a cube's face stays flat however it is meshed.
/// Precondition: 0 <= crease_angle_rad <= pi; triangle indices valid.
[[nodiscard]] ShadingNormals compute_shading_normals(const TriangleMesh& mesh, double crease_angle_rad);

/// The shading normal at p_O (object frame): corner normals of triangle `t` blended by
/// the barycentric coordinates of p_O's projection onto its plane, clamped into the
/// triangle, normalised. Falls back to the face normal where the blend vanishes; zero
/// for a degenerate triangle. Allocation-free.
[[nodiscard]] Eigen::Vector3d interpolated_normal_O(const TriangleMesh& mesh, const ShadingNormals& normals,
                                                    std::uint32_t t, const Eigen::Vector3d& p_O);

}  // namespace mhd
