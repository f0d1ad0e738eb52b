#include "collision/split_tree_build.h"

#include "collision/mesh_bvh.h"
#include "collision/two_halves.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <future>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace mhd {
namespace {

static_assert(MeshBvh::kPartTriangles == (1u << (31 - MAX_NUM_PARTS_IN_BITS)),
              "a leaf's index within its part has the bits Bullet leaves it");
static_assert(kPieceTriangles >= 2 && kPieceTriangles <= MeshBvh::kPartTriangles);

/// A triangle of the mesh and its centre, quantized over the mesh's box.
struct Item {
  std::uint32_t triangle;
  std::array<std::uint16_t, 3> centre;
};

/// The bounds of a range's quantized centres.
struct CentreBounds {
  std::array<std::uint16_t, 3> lo{0xffff, 0xffff, 0xffff};
  std::array<std::uint16_t, 3> hi{0, 0, 0};

  void extend(const std::array<std::uint16_t, 3>& c) {
    for (std::size_t k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], c[k]);
      hi[k] = std::max(hi[k], c[k]);
    }
  }
  void extend(const CentreBounds& b) {
    extend(b.lo);
    extend(b.hi);
  }
};

/// The node count of a subtree over `triangles` leaves: Bullet's trees are binary with
/// one triangle a leaf, as are the levels built here.
std::size_t subtree_nodes(std::size_t triangles) { return 2 * triangles - 1; }

/// The whole tree: Bullet's object with its node array sized for the whole mesh, which
/// the pieces and the inner nodes above them fill in place.
class AssembledTree : public btOptimizedBvh {
 public:
  AssembledTree(const btVector3& aabb_min, const btVector3& aabb_max, std::size_t nodes) {
    // What btOptimizedBvh::build sets before it builds a quantized tree.
    setQuantizationValues(aabb_min, aabb_max);
    m_useQuantization = true;
    m_quantizedContiguousNodes.resize(static_cast<int>(nodes));
    m_curNodeIndex = static_cast<int>(nodes);
  }

  btQuantizedBvhNode* nodes() { return &m_quantizedContiguousNodes[0]; }

  void add_headers(const std::vector<btBvhSubtreeInfo>& headers) {
    for (const btBvhSubtreeInfo& header : headers) m_SubtreeHeaders.push_back(header);
    m_subtreeHeaderCount = m_SubtreeHeaders.size();
  }
};

/// Bullet's tree of one piece, with access to its arrays.
class PieceTree : public btOptimizedBvh {
 public:
  [[nodiscard]] std::size_t node_count() const { return static_cast<std::size_t>(m_curNodeIndex); }

  /// Copies the piece's nodes to `out`, each leaf renamed from its index in `items` to
  /// the mesh triangle it is, and its subtree headers (Bullet's cache-friendly walk and
  /// refit use them) to `headers`, moved to where the nodes went.
  void place(btQuantizedBvhNode* out, std::size_t at, std::span<const Item> items,
             std::vector<btBvhSubtreeInfo>& headers) const {
    for (std::size_t i = 0; i < node_count(); ++i) {
      btQuantizedBvhNode node = m_quantizedContiguousNodes[static_cast<int>(i)];
      if (node.isLeafNode()) {
        const std::uint32_t triangle = items[MeshBvh::leaf_triangle(node)].triangle;
        node.m_escapeIndexOrTriangleIndex = MeshBvh::leaf_code(triangle);
      }
      out[at + i] = node;
    }
    for (int i = 0; i < m_SubtreeHeaders.size(); ++i) {
      btBvhSubtreeInfo header = m_SubtreeHeaders[i];
      header.m_rootNodeIndex += static_cast<int>(at);
      headers.push_back(header);
    }
  }
};

/// What each building thread keeps to itself.
struct Worker {
  std::vector<TriangleIndices> piece;
  std::vector<Eigen::Vector3d> corners;  // a clamped piece's own corners, in Bullet's units
  std::vector<std::uint32_t> histogram;
  std::vector<btBvhSubtreeInfo> headers;
};

class PieceBuilder {
 public:
  PieceBuilder(const TriangleMesh& mesh, double scale, const btVector3& aabb_min, const btVector3& aabb_max,
               const BuildProgress& progress, bool clamp)
      : mesh_(mesh), scale_(scale), aabb_min_(aabb_min), aabb_max_(aabb_max),
        tree_(std::make_unique<AssembledTree>(aabb_min, aabb_max, subtree_nodes(mesh.triangles.size()))),
        nodes_(tree_->nodes()), progress_(progress), clamp_(clamp) {}

  std::unique_ptr<btOptimizedBvh> build() {
    const CentreBounds bounds = make_items();
    std::array<Worker, 2> workers;
    caller_ = &workers[0];
    build_range(0, mesh_.triangles.size(), 0, bounds, workers[0], &workers[1]);
    if (progress_) progress_(1.0);
    items_.reset();
    for (const Worker& w : workers) tree_->add_headers(w.headers);
    return std::move(tree_);
  }

 private:
  /// Each triangle with its centre, quantized to 16 bits over the mesh's box (on two
  /// threads), and the bounds of all the centres.
  CentreBounds make_items() {
    const std::size_t n = mesh_.triangles.size();
    // Every item is written below: no need to zero 12 bytes a triangle first.
    items_ = std::make_unique_for_overwrite<Item[]>(n);
    std::array<double, 3> to_steps{};
    for (std::size_t k = 0; k < 3; ++k) {
      const double extent = aabb_max_[static_cast<int>(k)] - aabb_min_[static_cast<int>(k)];
      to_steps[k] = extent > 0.0 ? 65535.0 / extent : 0.0;
      step_[k] = extent / 65535.0;
    }
    std::array<CentreBounds, 2> halves;
    in_two_halves(n, std::size_t{1} << 16, [&](std::size_t first, std::size_t last) {
      CentreBounds& bounds = halves[first == 0 ? 0u : 1u];
      for (std::size_t t = first; t < last; ++t) {
        const TriangleIndices& c = mesh_.triangles[t];
        Item& item = items_[t];
        item.triangle = static_cast<std::uint32_t>(t);
        const Eigen::Vector3d centre =
            (mesh_.vertices_m[c[0]] + mesh_.vertices_m[c[1]] + mesh_.vertices_m[c[2]]) * (scale_ / 3.0);
        for (std::size_t k = 0; k < 3; ++k) {
          const double steps = (centre[static_cast<Eigen::Index>(k)] - aabb_min_[static_cast<int>(k)]) * to_steps[k];
          item.centre[k] = static_cast<std::uint16_t>(std::clamp(steps, 0.0, 65535.0));
        }
        bounds.extend(item.centre);
      }
      return true;
    });
    // The second half's bounds are empty (lo above hi) when the pass was not split.
    if (halves[1].lo[0] <= halves[1].hi[0]) halves[0].extend(halves[1]);
    return halves[0];
  }

  /// The subtree over items [begin, end) at node `at`, built by `worker`: split at the
  /// median centre until a piece is small enough for Bullet. With a `helper`, the first
  /// split's second half is built by it on another thread.
  void build_range(std::size_t begin, std::size_t end, std::size_t at, const CentreBounds& bounds, Worker& worker,
                   Worker* helper) {
    const std::size_t n = end - begin;
    // Longest in space: each axis is quantized over the mesh's own extent along it.
    std::size_t axis = 0;
    for (std::size_t k = 1; k < 3; ++k) {
      if ((bounds.hi[k] - bounds.lo[k]) * step_[k] > (bounds.hi[axis] - bounds.lo[axis]) * step_[axis]) axis = k;
    }
    const auto extent = static_cast<std::uint32_t>(bounds.hi[axis] - bounds.lo[axis]);
    if (n <= kPieceTriangles || extent == 0) {
      build_piece(begin, end, at, worker);
      return;
    }
    CentreBounds first_bounds, second_bounds;
    const std::size_t mid =
        split_at_median(begin, end, axis, bounds.lo[axis], extent, worker.histogram, first_bounds, second_bounds);
    const std::size_t first_at = at + 1;
    const std::size_t second_at = first_at + subtree_nodes(mid - begin);
    nodes_[at].m_escapeIndexOrTriangleIndex = -static_cast<int>(subtree_nodes(n));
    std::future<void> second;
    if (helper != nullptr) {
      const auto build_second = [&, helper] { build_range(mid, end, second_at, second_bounds, *helper, nullptr); };
      try {
        second = std::async(std::launch::async, build_second);
      } catch (const std::system_error&) {
        second = std::async(std::launch::deferred, build_second);
      }
    }
    build_range(begin, mid, first_at, first_bounds, worker, nullptr);
    if (second.valid()) {
      second.get();
    } else {
      build_range(mid, end, second_at, second_bounds, worker, nullptr);
    }
    // The inner node's box holds its two children's.
    btQuantizedBvhNode& node = nodes_[at];
    const btQuantizedBvhNode& a = nodes_[first_at];
    const btQuantizedBvhNode& b = nodes_[second_at];
    for (int k = 0; k < 3; ++k) {
      node.m_quantizedAabbMin[k] = std::min(a.m_quantizedAabbMin[k], b.m_quantizedAabbMin[k]);
      node.m_quantizedAabbMax[k] = std::max(a.m_quantizedAabbMax[k], b.m_quantizedAabbMax[k]);
    }
  }

  /// Moves the items of [begin, end) whose centre along `axis` is at or below the median
  /// to the front, and returns where the others start. Both sides are never empty: the
  /// lowest centre is in the first and the highest in the second.
  std::size_t split_at_median(std::size_t begin, std::size_t end, std::size_t axis, std::uint16_t lo,
                              std::uint32_t extent,
                              std::vector<std::uint32_t>& histogram, CentreBounds& first_bounds,
                              CentreBounds& second_bounds) {
    const std::size_t n = end - begin;
    // Bins of 2^shift quantization steps, no more of them than the range has items
    // (times two, and at least 256): the histogram then costs no more than the pass.
    const std::size_t most_bins = std::max<std::size_t>(256, 2 * n);
    unsigned shift = 0;
    while ((extent >> shift) + 1 > most_bins) ++shift;
    const std::uint32_t bins = (extent >> shift) + 1;
    const auto bin_of = [&](const Item& item) {
      return static_cast<std::uint32_t>(item.centre[axis] - lo) >> shift;
    };
    histogram.assign(bins, 0);
    for (std::size_t i = begin; i < end; ++i) ++histogram[bin_of(items_[i])];
    std::uint32_t median = 0;
    std::size_t below = histogram[0];
    while (2 * below < n && median + 2 < bins) below += histogram[++median];
    // Hoare's partition: the first side takes the bins up to the median.
    std::size_t i = begin, j = end;
    while (true) {
      while (i < j && bin_of(items_[i]) <= median) first_bounds.extend(items_[i++].centre);
      while (i < j && bin_of(items_[j - 1]) > median) second_bounds.extend(items_[--j].centre);
      if (i >= j) break;
      std::swap(items_[i], items_[j - 1]);
    }
    return i;
  }

  /// Bullet's tree of the items [begin, end), placed at node `at`.
  void build_piece(std::size_t begin, std::size_t end, std::size_t at, Worker& worker) {
    const std::span<const Item> items(items_.get() + begin, end - begin);
    worker.piece.clear();
    btTriangleIndexVertexArray parts;
    if (clamp_) {
      // Bullet's build quantizes without clamping: it gets each corner scaled (the product
      // its scaling would make) and clamped onto the grid, three a triangle.
      worker.corners.clear();
      const Eigen::AlignedBox3d box = MeshBvh::off_grid_corner_box(*tree_);
      for (const Item& item : items) {
        const auto first = static_cast<std::uint32_t>(worker.corners.size());
        for (const std::uint32_t v : mesh_.triangles[item.triangle]) {
          worker.corners.push_back((mesh_.vertices_m[v] * scale_).cwiseMax(box.min()).cwiseMin(box.max()));
        }
        worker.piece.push_back({first, first + 1, first + 2});
      }
      add_mesh_parts(parts, worker.piece, worker.corners, MeshBvh::kPartTriangles);
    } else {
      for (const Item& item : items) worker.piece.push_back(mesh_.triangles[item.triangle]);
      add_mesh_parts(parts, worker.piece, mesh_.vertices_m, MeshBvh::kPartTriangles);
      parts.setScaling(btVector3(scale_, scale_, scale_));
    }
    parts.setPremadeAabb(aabb_min_, aabb_max_);
    PieceTree piece;
    piece.build(&parts, /*useQuantizedAabbCompression=*/true, aabb_min_, aabb_max_);
    if (piece.node_count() != subtree_nodes(items.size())) {
      throw std::logic_error("build_tree_in_pieces: Bullet built " + std::to_string(piece.node_count()) +
                             " nodes over " + std::to_string(items.size()) + " triangles");
    }
    piece.place(nodes_, at, items, worker.headers);
    const std::size_t placed = placed_.fetch_add(items.size(), std::memory_order_relaxed) + items.size();
    if (progress_ && &worker == caller_) tell(placed);
  }

  /// Tells the share placed when it has risen by a hundredth (short of the whole, which
  /// build() tells once the other thread is done too).
  void tell(std::size_t placed) {
    const std::size_t n = mesh_.triangles.size();
    const std::size_t hundredths = placed * 100 / n;
    if (hundredths <= told_hundredths_ || placed >= n) return;
    told_hundredths_ = hundredths;
    progress_(static_cast<double>(placed) / static_cast<double>(n));
  }

  const TriangleMesh& mesh_;
  double scale_;
  btVector3 aabb_min_, aabb_max_;
  std::unique_ptr<AssembledTree> tree_;
  btQuantizedBvhNode* nodes_;
  std::array<double, 3> step_{};  // the length of one quantization step along each axis
  std::unique_ptr<Item[]> items_;  // one per triangle, reordered by the splits
  const BuildProgress& progress_;
  bool clamp_;  // triangles may lie off the grid (build_tree_in_pieces)
  const Worker* caller_ = nullptr;  // the calling thread's, the only one that tells progress
  std::atomic<std::size_t> placed_{0};  // triangles placed, by either thread
  std::size_t told_hundredths_ = 0;
};

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

std::unique_ptr<btOptimizedBvh> build_tree_in_pieces(const TriangleMesh& mesh, double scale,
                                                     const btVector3& aabb_min, const btVector3& aabb_max,
                                                     const BuildProgress& progress, bool clamp_to_box) {
  if (!MeshBvh::holds(mesh.triangles.size())) {
    throw std::length_error("build_tree_in_pieces: " + std::to_string(mesh.triangles.size()) + " triangles");
  }
  return PieceBuilder(mesh, scale, aabb_min, aabb_max, progress, clamp_to_box).build();
}

}  // namespace mhd
