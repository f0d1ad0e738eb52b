#pragma once
// The box a mesh's tree quantizes over. Bullet's tree keeps every box on a 16-bit grid
// over one box; over a mesh's whole bounds, a few stray triangles far from the rest (a
// range scan's stray point, a part left at another origin) make a cell of that grid
// wider than the mesh itself, and every query then overlaps every leaf. The grid then
// spans the bulk of the mesh instead: a box off the grid is clamped onto its edge, in the
// build, in the check of a cached tree and in every query alike, and a clamped box
// overlaps whatever the unclamped one did (clamping keeps order), so the triangles
// outside are still found, only less finely.

#include "geometry/triangle_mesh.h"

#include <Eigen/Geometry>

namespace mhd {

/// A grid cell may be up to this many times the spacing of the mesh's vertices (its bulk's
/// size over the square root of their count, as on a surface) before the grid shrinks to
/// the mesh's bulk.
inline constexpr double kMaxGridCellPerSpacing = 4.0;

/// `bounds` (the mesh's, in its own frame) while a 16-bit grid over them is fine enough for
/// the mesh's vertex spacing; otherwise the box of the middle 98 % of its vertices along
/// each axis, grown by half its largest side each way and kept within `bounds`. From
/// samples of at most about 65,536 vertices; the one that decides is chosen by the
/// vertices' coordinates, not their numbers, so the same mesh in another vertex order gets
/// the same box.
[[nodiscard]] Eigen::AlignedBox3d tree_grid_box(const TriangleMesh& mesh, const Eigen::AlignedBox3d& bounds);

}  // namespace mhd
