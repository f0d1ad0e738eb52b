#pragma once
// A triangle mesh with its Bullet BVH (btBvhTriangleMeshShape, quantized AABBs).
// A leaf has 21 bits for a triangle's index, so the mesh is given to Bullet as parts of
// 2^21 triangles over one vertex array, and a leaf's (part, index) names the triangle.
// The BVH is built once per mesh in the mesh's own frame; moving the object moves
// only its pose, never the tree. btScalar is double (Debian's -float64 Bullet).

#include "geometry/triangle_mesh.h"

#include <btBulletCollisionCommon.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <type_traits>
#include <vector>

namespace mhd {

/// How far a tree's build is, as a share in (0, 1], told as it rises.
using BuildProgress = std::function<void(double)>;

class MeshBvh {
 public:
  /// Most triangles one tree holds. Bullet keeps its node array (2 per triangle) in an
  /// int, and a leaf's triangle as 10 bits of part and 21 of index in that part.
  static constexpr std::uint64_t kMaxTriangles = (std::uint64_t{1} << 30) - 1;
  /// Triangles per Bullet part: the 21 bits a leaf has for the index within its part.
  static constexpr std::uint32_t kPartTriangles = std::uint32_t{1} << 21;

  /// True when a tree can hold a mesh of `triangles` (1 to kMaxTriangles).
  [[nodiscard]] static constexpr bool holds(std::uint64_t triangles) {
    return triangles >= 1 && triangles <= kMaxTriangles;
  }

  /// The order of the mesh() a tree is built over. With Leaves, the mesh's triangles are
  /// put in the order of the tree's leaves and its vertices in the order those triangles
  /// first use them (unused ones last): a walk, a sweep and the cached tree's check then
  /// read neighbouring triangles and corners from neighbouring memory, where a large
  /// mesh's file order scatters them over gigabytes. The triangles, vertices and vertex
  /// normals are the same, renumbered: mesh() is a new mesh, and triangle numbers are no
  /// longer the given mesh's.
  enum class MeshOrder { AsGiven, Leaves };

  /// Builds the BVH. Precondition: mesh has at least one triangle, all indices valid.
  /// `progress`, when set, is told on the calling thread how far a tree built in pieces
  /// (kSplitBuildMinTriangles or more) is, rising, below 1: placing the pieces is most of
  /// the build, and up to nine tenths of what it tells.
  explicit MeshBvh(std::shared_ptr<const TriangleMesh> mesh, MeshOrder order = MeshOrder::AsGiven,
                   const BuildProgress& progress = {});

  /// Adopts a BVH produced by serialize_bvh() for the same mesh (the BVH cache).
  /// Returns nullptr if the buffer is not a valid serialized BVH for this mesh, or the
  /// mesh is not one (a triangle's corner out of range or repeated, a vertex or vertex
  /// normal not finite): a file hands both.
  static std::unique_ptr<MeshBvh> from_serialized(std::shared_ptr<const TriangleMesh> mesh,
                                                  std::span<const std::byte> serialized);

  /// Adopts it in place, not copied: `serialized` (16-byte aligned and writable, e.g. a
  /// private mapping of a cache file) becomes the tree's storage, and `storage` keeps it
  /// alive as long as the tree. Bullet writes only the tree's header in it, so the nodes
  /// of a mapped file stay shared pages, read as the tree's walks reach them. Returns
  /// nullptr as from_serialized() does.
  /// With TreePages::Release, `serialized` must lie in a private file mapping that nothing
  /// wrote beyond Bullet's header: the check maps the node pages a range at a time and lets
  /// each range go behind it, so a tree of gigabytes is never resident at once, and its
  /// pages come back from the file as walks reach them.
  /// `face_normals_O`, where given (one per triangle, such as a cache entry's), are taken
  /// for the face normals once each is within kFaceNormalTolerance of its triangle's own;
  /// else nothing is adopted (nullptr). Where not given, they are computed.
  /// With `ready`, `ready()` is called once the mesh and the tree are checked, or as soon
  /// as they fail; if it returns false nothing is adopted (nullptr). A caller still
  /// reading the buffer, such as its checksum, finishes there. Until then the adoption
  /// has written only the first kSerializedHeadBytes of `serialized` (Bullet's header),
  /// so that the caller may read the rest meanwhile, and that head as it was from a copy.
  enum class TreePages { Keep, Release };
  /// The bytes at the start of a serialized tree that adopting it writes: Bullet's tree
  /// object, built again where it lies. Never the nodes.
  static constexpr std::size_t kSerializedHeadBytes = sizeof(btQuantizedBvh);
  static std::unique_ptr<MeshBvh> adopt_serialized(std::shared_ptr<const TriangleMesh> mesh,
                                                   std::span<std::byte> serialized, std::shared_ptr<void> storage,
                                                   TreePages pages = TreePages::Keep,
                                                   const std::function<bool()>& ready = {},
                                                   MeshArray<Eigen::Vector3d> face_normals_O = {});

  ~MeshBvh();
  MeshBvh(const MeshBvh&) = delete;
  MeshBvh& operator=(const MeshBvh&) = delete;

  /// The BVH in Bullet's own in-place format (the cache stores it verbatim), in a
  /// 16-byte-aligned buffer of its own. Throws std::length_error for a tree over
  /// kMaxSerializedBytes.
  struct SerializedTree {
    std::unique_ptr<std::byte, void (*)(std::byte*)> bytes{nullptr, nullptr};
    std::size_t size = 0;
  };
  [[nodiscard]] SerializedTree serialize_tree() const;
  /// serialize_tree() copied into a vector (for small trees and tests; the cache writes
  /// the buffer itself, which for a large mesh is gigabytes).
  [[nodiscard]] std::vector<std::byte> serialize_bvh() const;

  /// Bullet's serialized format counts its bytes in an unsigned int and writes every node
  /// whatever size it was given: a larger tree (from about 134 M triangles) cannot be
  /// serialized, and trying would write past the buffer.
  static constexpr std::uint64_t kMaxSerializedBytes = 0xFFFF'FFFFu;
  /// Bytes Bullet's format takes for a tree of `nodes` nodes and `subtrees` subtree
  /// headers, counted in 64 bits.
  [[nodiscard]] static std::uint64_t serialized_bytes(std::uint64_t nodes, std::uint64_t subtrees);

  [[nodiscard]] const TriangleMesh& mesh() const { return *mesh_; }
  [[nodiscard]] const std::shared_ptr<const TriangleMesh>& mesh_ptr() const { return mesh_; }
  [[nodiscard]] const Eigen::AlignedBox3d& bounds() const { return bounds_; }
  /// The spacing of the mesh's vertices as the tree's grid judges it (tree_grid.h): its
  /// bulk's largest side over the square root of their count. Zero for a mesh of one point.
  [[nodiscard]] double vertex_spacing_m() const {
    const auto n = static_cast<double>(std::max<std::size_t>(mesh_->vertices_m.size(), 1));
    return grid_.isEmpty() ? 0.0 : grid_.sizes().maxCoeff() / std::sqrt(n);
  }
  [[nodiscard]] const btBvhTriangleMeshShape& shape() const { return *shape_; }
  /// Unit counter-clockwise normal of triangle t in the mesh frame, zero for a triangle of
  /// zero area: unit_face_normal() of its corners, computed when the tree is built or
  /// taken from a cache entry once checked against it (24 bytes per triangle), so a
  /// sweep's triangle test does not redo it.
  [[nodiscard]] const Eigen::Vector3d& face_normal_O(std::uint32_t t) const { return face_normals_O_[t]; }
  /// All of them, in triangle order (what a cache entry stores).
  [[nodiscard]] std::span<const Eigen::Vector3d> face_normals_O() const { return face_normals_O_; }
  /// How far a given face normal may lie from the one its corners give (per coordinate):
  /// rounding of another build of the same sum, never a turn of the face.
  static constexpr double kFaceNormalTolerance = 1e-12;

  /// Bullet sees the mesh scaled by this (largest extent 1e4 units, see mesh_bvh.cpp):
  /// shape() is in those units.
  [[nodiscard]] double bvh_scale() const { return bvh_scale_; }

  /// The mesh's triangle a leaf names: its part's first triangle plus its index there.
  [[nodiscard]] static std::uint64_t leaf_triangle(const btQuantizedBvhNode& leaf) {
    return static_cast<std::uint64_t>(leaf.getPartId()) * kPartTriangles +
           static_cast<std::uint64_t>(leaf.getTriangleIndex());
  }

  /// A leaf's stored name of the mesh's triangle `triangle` (below kMaxTriangles + 1):
  /// its part in the upper bits, its index in that part in the lower 21.
  [[nodiscard]] static int leaf_code(std::uint64_t triangle) {
    return static_cast<int>(((triangle / kPartTriangles) << (31 - MAX_NUM_PARTS_IN_BITS)) |
                            (triangle % kPartTriangles));
  }

  /// A box on the tree's grid: Bullet's 16-bit quantization of the mesh's bounds, or of
  /// its bulk where a few triangles lie far from the rest (tree_grid.h).
  struct QuantizedBox {
    std::array<std::uint16_t, 3> min{};
    std::array<std::uint16_t, 3> max{};
  };

  /// Where a triangle off the grid (tree_grid.h) has its corners clamped, in Bullet's
  /// units, in the build and in the check of a cached tree alike: Bullet's own clamping
  /// box less one cell at the top. Bullet rounds a box's top up by a cell, and its build
  /// merges boxes without clamping, so a corner on its clamping box's top would round past
  /// 16 bits there. A clamped box still overlaps every query that Bullet's clamping puts
  /// at or beyond the grid's edge.
  [[nodiscard]] static Eigen::AlignedBox3d off_grid_corner_box(const btQuantizedBvh& tree);

  /// box_O on the tree's grid, rounded outwards exactly as Bullet rounds its own queries.
  [[nodiscard]] QuantizedBox quantize(const Eigen::AlignedBox3d& box_O) const;

  /// True when every point of `inner` lies in `outer` (then every leaf that overlaps
  /// `inner` overlaps `outer`).
  [[nodiscard]] static bool contains(const QuantizedBox& outer, const QuantizedBox& inner) {
    for (std::size_t i = 0; i < 3; ++i) {
      if (inner.min[i] < outer.min[i] || inner.max[i] > outer.max[i]) return false;
    }
    return true;
  }

  /// True when `node`'s box overlaps `box`, as Bullet tests it
  /// (testQuantizedAabbAgainstQuantizedAabb: closed intervals).
  [[nodiscard]] static bool overlaps(const QuantizedBox& box, const btQuantizedBvhNode& node) {
    return box.min[0] <= node.m_quantizedAabbMax[0] && box.max[0] >= node.m_quantizedAabbMin[0] &&
           box.min[1] <= node.m_quantizedAabbMax[1] && box.max[1] >= node.m_quantizedAabbMin[1] &&
           box.min[2] <= node.m_quantizedAabbMax[2] && box.max[2] >= node.m_quantizedAabbMin[2];
  }

  /// Walks the tree and calls f(triangle_index, leaf) for every leaf whose quantized box
  /// overlaps `box`: exactly the triangles Bullet's own query (reportAabbOverlappingNodex)
  /// reports for it, without its virtual call per triangle. If f returns false the walk
  /// stops there (f may also return void).
  template <class F>
  void for_each_leaf_overlapping(const QuantizedBox& box, F&& f) const {
    const btQuantizedBvhNode* node = nodes_;
    const btQuantizedBvhNode* const end = nodes_ + node_count_;
    while (node < end) {
      const bool overlap = overlaps(box, *node);
      if (node->isLeafNode()) {
        if (overlap) {
          const auto triangle = static_cast<std::uint32_t>(leaf_triangle(*node));
          if constexpr (std::is_same_v<decltype(f(triangle, *node)), bool>) {
            if (!f(triangle, *node)) return;
          } else {
            f(triangle, *node);
          }
        }
        ++node;
      } else {
        node += overlap ? 1 : node->getEscapeIndex();
      }
    }
  }

  /// The tree's nodes in Bullet's stackless order: what a walk reads.
  [[nodiscard]] std::span<const btQuantizedBvhNode> tree_nodes() const {
    return {nodes_, static_cast<std::size_t>(node_count_)};
  }

  /// Calls f(triangle_index) for every triangle whose (conservative) BVH box
  /// overlaps box_O. Never misses a triangle that overlaps the box; may report extra.
  template <class F>
  void for_each_triangle_overlapping(const Eigen::AlignedBox3d& box_O, F&& f) const {
    for_each_leaf_overlapping(quantize(box_O), [&](std::uint32_t triangle, const btQuantizedBvhNode&) { f(triangle); });
  }

 private:
  MeshBvh() = default;
  // Sets up Bullet's view of the mesh, its bounds and face normals: computed, or the given
  // ones taken (false where their count is off; tree_checks_out() holds each to its
  // triangle). With `check_mesh` (a mesh a file hands us), false too where a vertex or
  // vertex normal is not finite, or a corner out of range where normals are computed.
  [[nodiscard]] bool make_interface(MeshArray<Eigen::Vector3d> given_face_normals_O = {}, bool check_mesh = false);
  void adopt_tree(btQuantizedBvh* tree);
  /// MeshOrder::Leaves for a built tree: renames its leaves 0, 1, 2 ... in walk order and
  /// makes mesh_ and the face normals the given ones in that order.
  void put_mesh_in_leaf_order(btQuantizedBvh& tree);
  struct TreeCheckState {
    std::atomic<std::size_t> leaves;
    bool release_pages;
    Eigen::AlignedBox3d corner_box;  // off_grid_corner_box() of the tree checked
  };
  /// A tree a file hands us, checked node by node before it is walked: Bullet's stackless
  /// layout (each inner node followed by its two subtrees, its escape index spanning
  /// exactly them, the root the whole array), leaves naming every triangle once, each
  /// leaf's triangle three distinct corners in range, every box holding its children's
  /// boxes and its leaf's triangle, and each leaf's face normal its triangle's own. The
  /// root's two subtrees are checked on two threads.
  [[nodiscard]] bool tree_checks_out(std::span<const btQuantizedBvhNode> nodes, TreePages pages) const;
  /// The check of the subtree rooted at `begin` that must span [begin, end), its root
  /// held by `parent`'s box (none for the tree's root). `named` has a bit per triangle,
  /// set for each leaf that names it: this thread's own, so that no bit is shared.
  [[nodiscard]] bool subtree_checks_out(std::span<const btQuantizedBvhNode> nodes, std::size_t begin, std::size_t end,
                                        const btQuantizedBvhNode* parent, std::uint64_t* named,
                                        TreeCheckState& state) const;

  std::shared_ptr<const TriangleMesh> mesh_;
  MeshArray<Eigen::Vector3d> face_normals_O_;
  Eigen::AlignedBox3d bounds_;
  // The box the tree's grid spans (tree_grid.h): bounds_, or the bulk of a mesh with strays.
  Eigen::AlignedBox3d grid_;
  bool off_grid_ = false;  // some triangles lie off the grid: their corners are clamped
  // Bullet sees the mesh scaled by this (see make_interface); queries are scaled alike.
  double bvh_scale_ = 1.0;
  std::unique_ptr<btTriangleIndexVertexArray> interface_;
  // A large mesh's tree built in pieces (split_tree_build.h); shape_ uses it, not owns it.
  std::unique_ptr<btOptimizedBvh> built_tree_;
  std::unique_ptr<btBvhTriangleMeshShape> shape_;
  // Backing store of a deserialized BVH (Bullet's in-place format points into it): a
  // buffer of our own, or a cache file's mapping.
  std::shared_ptr<void> serialized_storage_;
  // The tree our own code queries. A deserialized tree is a plain btQuantizedBvh
  // (Bullet's deSerializeInPlace builds that), so it is never used as btOptimizedBvh here.
  const btQuantizedBvh* tree_ = nullptr;
  btQuantizedBvh* adopted_tree_ = nullptr;
  // The tree's nodes in Bullet's stackless order, and how many the root's subtree spans.
  const btQuantizedBvhNode* nodes_ = nullptr;
  std::ptrdiff_t node_count_ = 0;
};

}  // namespace mhd
