#include "collision/split_tree_build.h"

#include "collision/mesh_bvh.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <future>
#include <system_error>
#include <vector>

namespace mhd {
namespace {

/// Bins of the histogram the median centre is taken from: a half may hold one bin's
/// triangles more than the other, which only shifts work between the two threads.
constexpr std::size_t kMedianBins = std::size_t{1} << 16;

static_assert(MeshBvh::kPartTriangles == (1u << (31 - MAX_NUM_PARTS_IN_BITS)),
              "a leaf's index within its part has the bits Bullet leaves it");

/// One half of the mesh: its triangles, and which of the mesh's each one is.
struct Half {
  std::vector<TriangleIndices> triangles;
  std::vector<std::uint32_t> mesh_triangle;
};

/// Bullet's tree with access to its arrays, to rename leaves and join two trees.
class JoinableTree : public btOptimizedBvh {
 public:
  /// Room for the build's `leaves` leaves (which it would otherwise grow by doubling) and
  /// for `nodes` nodes, so that neither the build nor a later join moves the arrays.
  void reserve(std::size_t leaves, std::size_t nodes) {
    m_quantizedLeafNodes.reserve(static_cast<int>(leaves));
    m_quantizedContiguousNodes.reserve(static_cast<int>(nodes));
  }

  /// Renames each leaf from its (part, index) in `half` to the mesh triangle it is.
  void rename_leaves(const Half& half) {
    for (int i = 0; i < m_curNodeIndex; ++i) {
      btQuantizedBvhNode& node = m_quantizedContiguousNodes[i];
      if (!node.isLeafNode()) continue;
      const std::uint32_t mesh_triangle = half.mesh_triangle[MeshBvh::leaf_triangle(node)];
      node.m_escapeIndexOrTriangleIndex =
          static_cast<int>(((mesh_triangle / MeshBvh::kPartTriangles) << (31 - MAX_NUM_PARTS_IN_BITS)) |
                           (mesh_triangle % MeshBvh::kPartTriangles));
    }
  }

  /// Makes this tree a root over itself and `second` (built with the same quantization):
  /// the root, this tree's nodes, then `second`'s, as Bullet lays out every inner node.
  void join(JoinableTree& second) {
    const int first_nodes = m_curNodeIndex;
    const int second_nodes = second.m_curNodeIndex;
    const btQuantizedBvhNode& a = m_quantizedContiguousNodes[0];
    const btQuantizedBvhNode& b = second.m_quantizedContiguousNodes[0];
    btQuantizedBvhNode root{};
    for (int k = 0; k < 3; ++k) {
      root.m_quantizedAabbMin[k] = std::min(a.m_quantizedAabbMin[k], b.m_quantizedAabbMin[k]);
      root.m_quantizedAabbMax[k] = std::max(a.m_quantizedAabbMax[k], b.m_quantizedAabbMax[k]);
    }
    root.m_escapeIndexOrTriangleIndex = -(1 + first_nodes + second_nodes);
    m_quantizedContiguousNodes.resize(1 + first_nodes + second_nodes);
    btQuantizedBvhNode* nodes = &m_quantizedContiguousNodes[0];
    std::memmove(static_cast<void*>(nodes + 1), nodes, static_cast<std::size_t>(first_nodes) * sizeof(root));
    nodes[0] = root;
    std::memcpy(static_cast<void*>(nodes + 1 + first_nodes), &second.m_quantizedContiguousNodes[0],
                static_cast<std::size_t>(second_nodes) * sizeof(root));
    second.m_quantizedContiguousNodes.clear();
    // The subtree headers (Bullet's cache-friendly walk and refit use them) move with
    // their subtrees; both children of the new root are larger than a header covers.
    for (int i = 0; i < m_SubtreeHeaders.size(); ++i) m_SubtreeHeaders[i].m_rootNodeIndex += 1;
    for (int i = 0; i < second.m_SubtreeHeaders.size(); ++i) {
      btBvhSubtreeInfo header = second.m_SubtreeHeaders[i];
      header.m_rootNodeIndex += 1 + first_nodes;
      m_SubtreeHeaders.push_back(header);
    }
    m_subtreeHeaderCount = m_SubtreeHeaders.size();
    m_curNodeIndex = 1 + first_nodes + second_nodes;
  }
};

/// The two halves of the mesh at the median of the triangles' centres along `axis`.
std::array<Half, 2> split_at_median(const TriangleMesh& mesh, int axis, double lo, double hi) {
  const std::size_t n = mesh.triangles.size();
  // A centre's coordinate times 3 (the sum of the corners'), binned over the bounds.
  const double scale = hi > lo ? static_cast<double>(kMedianBins) / (3.0 * (hi - lo)) : 0.0;
  std::vector<std::uint16_t> bin(n);
  std::vector<std::size_t> count(kMedianBins, 0);
  for (std::size_t t = 0; t < n; ++t) {
    const TriangleIndices& c = mesh.triangles[t];
    const double sum = mesh.vertices_m[c[0]][axis] + mesh.vertices_m[c[1]][axis] + mesh.vertices_m[c[2]][axis];
    const double at = (sum - 3.0 * lo) * scale;
    bin[t] = static_cast<std::uint16_t>(std::clamp(at, 0.0, static_cast<double>(kMedianBins - 1)));
    ++count[bin[t]];
  }
  // The first bin at which half the triangles are in or below it (the last bin at most).
  std::size_t median_bin = 0, first_count = count[0];
  while (2 * first_count < n && median_bin + 1 < kMedianBins) first_count += count[++median_bin];
  std::array<Half, 2> halves;
  halves[0].triangles.reserve(first_count);
  halves[0].mesh_triangle.reserve(first_count);
  halves[1].triangles.reserve(n - first_count);
  halves[1].mesh_triangle.reserve(n - first_count);
  for (std::size_t t = 0; t < n; ++t) {
    Half& half = halves[bin[t] <= median_bin ? 0 : 1];
    half.triangles.push_back(mesh.triangles[t]);
    half.mesh_triangle.push_back(static_cast<std::uint32_t>(t));
  }
  return halves;
}

/// Bullet's tree of one half, its leaves naming the mesh's triangles, with room for
/// `nodes` nodes; the half is let go once built.
std::unique_ptr<JoinableTree> build_half(Half& half, const TriangleMesh& mesh, double scale,
                                         const btVector3& aabb_min, const btVector3& aabb_max, std::size_t nodes) {
  btTriangleIndexVertexArray parts;
  add_mesh_parts(parts, half.triangles, mesh.vertices_m, MeshBvh::kPartTriangles);
  parts.setScaling(btVector3(scale, scale, scale));
  parts.setPremadeAabb(aabb_min, aabb_max);
  auto tree = std::make_unique<JoinableTree>();
  tree->reserve(half.triangles.size(), nodes);
  tree->build(&parts, /*useQuantizedAabbCompression=*/true, aabb_min, aabb_max);
  tree->rename_leaves(half);
  half = Half{};  // let go before the join
  return tree;
}

}  // namespace

void add_mesh_parts(btTriangleIndexVertexArray& parts, std::span<const TriangleIndices> triangles,
                    std::span<const Eigen::Vector3d> vertices, std::size_t part_triangles) {
  for (std::size_t first = 0; first < triangles.size(); first += part_triangles) {
    btIndexedMesh part;
    part.m_numTriangles = static_cast<int>(std::min(part_triangles, triangles.size() - first));
    part.m_triangleIndexBase = reinterpret_cast<const unsigned char*>(triangles.data() + first);
    part.m_triangleIndexStride = static_cast<int>(sizeof(TriangleIndices));
    part.m_indexType = PHY_INTEGER;
    part.m_numVertices = static_cast<int>(vertices.size());
    part.m_vertexBase = reinterpret_cast<const unsigned char*>(vertices.data());
    part.m_vertexStride = static_cast<int>(sizeof(Eigen::Vector3d));
    part.m_vertexType = PHY_DOUBLE;
    parts.addIndexedMesh(part, PHY_INTEGER);
  }
}

std::unique_ptr<btOptimizedBvh> build_tree_in_two_halves(const TriangleMesh& mesh, double scale,
                                                         const btVector3& aabb_min, const btVector3& aabb_max) {
  const btVector3 extent = aabb_max - aabb_min;
  const int axis = extent.maxAxis();
  std::array<Half, 2> halves = split_at_median(mesh, axis, aabb_min[axis] / scale, aabb_max[axis] / scale);
  if (halves[0].triangles.empty() || halves[1].triangles.empty()) return nullptr;
  std::future<std::unique_ptr<JoinableTree>> second;
  // Bullet sizes a tree's node array at 2 per leaf: the first half's is made room for
  // the whole tree's, which the join then fills in place.
  const std::size_t n = mesh.triangles.size();
  const auto build_second = [&] {
    return build_half(halves[1], mesh, scale, aabb_min, aabb_max, 2 * halves[1].triangles.size());
  };
  try {
    second = std::async(std::launch::async, build_second);
  } catch (const std::system_error&) {
    second = std::async(std::launch::deferred, build_second);
  }
  std::unique_ptr<JoinableTree> tree = build_half(halves[0], mesh, scale, aabb_min, aabb_max, 2 * n);
  const std::unique_ptr<JoinableTree> second_tree = second.get();
  tree->join(*second_tree);
  return tree;
}

}  // namespace mhd
