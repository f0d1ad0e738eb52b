#pragma once
// Bullet's quantized tree of a large mesh, built in small pieces on two threads. Bullet's
// own build is one thread and costs about 60 ns per triangle for each level of the tree
// (it unquantizes every leaf box several times per level), which made it most of a cold
// load of a large mesh. Here the top levels are ours: the triangles' centres, quantized
// to 16 bits, are split in place at the median along their bounds' longest axis, found
// from a histogram, until a range holds at most kPieceTriangles. Bullet builds each
// such piece with the whole mesh's quantization, and the pieces are copied into one node
// array with their leaves renamed to the mesh's triangles. The result is the layout
// Bullet's build makes (each inner node followed by its two subtrees), so it walks,
// serializes, adopts and passes the cached tree's check alike. Never used on the haptic
// thread.

#include "collision/mesh_bvh.h"
#include "geometry/triangle_mesh.h"

#include <btBulletCollisionCommon.h>

#include <cstddef>
#include <memory>
#include <span>

namespace mhd {

/// Meshes with at least this many triangles are built in pieces (below it Bullet's own
/// build takes well under a second).
inline constexpr std::size_t kSplitBuildMinTriangles = std::size_t{1} << 21;

/// The most triangles a piece that Bullet builds holds; ranges are split until they
/// hold no more, or until their centres fall on one quantized point.
inline constexpr std::size_t kPieceTriangles = 256;

/// Gives Bullet `triangles` over `vertices` as parts of at most `part_triangles` each, so
/// that a leaf's (part, index) is part * part_triangles + index into `triangles`.
void add_mesh_parts(btTriangleIndexVertexArray& parts, std::span<const TriangleIndices> triangles,
                    std::span<const Eigen::Vector3d> vertices, std::size_t part_triangles);

/// The whole mesh's tree, built in pieces; `scale` is the interface's scaling and the box
/// [aabb_min, aabb_max] the tree's grid (the mesh's bounds, what Bullet's own build of the
/// whole mesh would quantize by, or its bulk: tree_grid.h). The mesh has 1 to
/// MeshBvh::kMaxTriangles triangles. `progress`, when set, is told the share of the
/// triangles placed in pieces (by both threads) on the calling thread only, each time it
/// has risen by a hundredth or more, and last 1. With
/// `clamp_to_box`, triangles may lie outside the box (a grid over a mesh's bulk,
/// tree_grid.h): each leaf's box is then its triangle's clamped onto the grid, as
/// Bullet's quantizeWithClamp() clamps queries and the cached tree's check.
[[nodiscard]] std::unique_ptr<btOptimizedBvh> build_tree_in_pieces(const TriangleMesh& mesh, double scale,
                                                                   const btVector3& aabb_min,
                                                                   const btVector3& aabb_max,
                                                                   const BuildProgress& progress = {},
                                                                   bool clamp_to_box = false);

}  // namespace mhd
