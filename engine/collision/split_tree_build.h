#pragma once
// Bullet's quantized tree of a large mesh, built as two halves on two threads. Bullet's
// own build is one thread and most of a cold load of a large mesh. The triangles are
// split at the median of their centres along the bounds' longest axis; each half gets
// its own tree with the whole mesh's quantization, its leaves renamed to the mesh's
// triangles, and the two trees are joined under one root. The result is the layout
// Bullet's build makes (each inner node followed by its two subtrees), so it walks,
// serializes, adopts and passes the cached tree's check alike. Never used on the haptic
// thread.

#include "geometry/triangle_mesh.h"

#include <btBulletCollisionCommon.h>

#include <cstddef>
#include <memory>
#include <span>

namespace mhd {

/// Meshes with at least this many triangles are built in two halves (below it the build
/// takes well under a second on one thread).
inline constexpr std::size_t kSplitBuildMinTriangles = std::size_t{1} << 21;

/// Gives Bullet `triangles` over `vertices` as parts of at most `part_triangles` each, so
/// that a leaf's (part, index) is part * part_triangles + index into `triangles`.
void add_mesh_parts(btTriangleIndexVertexArray& parts, std::span<const TriangleIndices> triangles,
                    std::span<const Eigen::Vector3d> vertices, std::size_t part_triangles);

/// The whole mesh's tree, built in two halves; `scale` and the box [aabb_min, aabb_max]
/// are the interface's scaling and premade box (what Bullet's own build of the whole
/// mesh would quantize by). Null where the median leaves a half empty (every centre on
/// one plane across the longest axis): then the caller builds it whole.
[[nodiscard]] std::unique_ptr<btOptimizedBvh> build_tree_in_two_halves(const TriangleMesh& mesh, double scale,
                                                                       const btVector3& aabb_min,
                                                                       const btVector3& aabb_max);

}  // namespace mhd
