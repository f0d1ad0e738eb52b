#include "collision/mesh_bvh.h"

#include "collision/huge_pages.h"
#include "collision/segment_triangle.h"
#include "collision/split_tree_build.h"
#include "collision/tree_grid.h"
#include "collision/two_halves.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace mhd {
namespace {

constexpr std::size_t kBulletAlignment = 16;
// Bullet grows the quantization box by a fixed 1.0 units before quantizing to 16 bits
// (btQuantizedBvh::setQuantizationValues), which in metres would make the tree's
// boxes centimetres wide on a small mesh. Bullet therefore sees the mesh scaled so
// its largest extent is this many units, which makes the margin negligible.
constexpr double kBvhExtentUnits = 1e4;

void free_aligned(std::byte* p) { std::free(p); }

btVector3 to_bt(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

/// True when `outer`'s box holds [min, max]: a parent's box holds its children's, a leaf's its triangle's.
bool box_holds(const btQuantizedBvhNode& outer, const unsigned short* min, const unsigned short* max) {
  for (int k = 0; k < 3; ++k) {
    if (outer.m_quantizedAabbMin[k] > min[k] || outer.m_quantizedAabbMax[k] < max[k]) return false;
  }
  return true;
}

/// True when `given` is unit_face_normal(a, b, c) within MeshBvh::kFaceNormalTolerance
/// per coordinate (NaN never is): the face normal a file gives, which the sweeps trust.
/// Without the square root and divisions of the normal itself, which cost a cached tree's
/// check a fifth of its time: with m the area normal, |given|^2 within tol/2 of 1 puts its
/// length within about tol/4 of 1, and |given x m| <= (tol/4)|given||m| its direction
/// within tol/4 of m's (given . m > 0: not the opposite one), so it lies within
/// tol/4 + tol/4 + (tol/4)^2 of the unit normal. Rounding of the stored normal is 1e-16.
bool face_normal_holds(const Eigen::Vector3d& given, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                       const Eigen::Vector3d& c) {
  constexpr double kTol = MeshBvh::kFaceNormalTolerance;
  const Eigen::Vector3d m = (b - a).cross(c - a);
  const double mm = m.squaredNorm();
  // Zero area gives a zero normal; an area normal past double's range, none worth keeping.
  if (!(mm > 0.0)) return given.cwiseAbs().maxCoeff() <= kTol;
  if (!(mm <= std::numeric_limits<double>::max())) return false;
  const double nn = given.squaredNorm();
  return std::abs(nn - 1.0) <= 0.5 * kTol && given.dot(m) > 0.0 &&
         given.cross(m).squaredNorm() <= (0.25 * kTol) * (0.25 * kTol) * nn * mm;
}

/// Node arrays shorter than this are checked on one thread.
constexpr std::size_t kParallelNodes = std::size_t{1} << 20;
/// How far ahead of a check its node pages are mapped, and how far behind released.
constexpr std::size_t kPageWindowNodes = std::size_t{1} << 20;

}  // namespace

bool MeshBvh::make_interface(MeshArray<Eigen::Vector3d> given_face_normals_O, bool check_mesh) {
  if (mesh_->triangles.empty()) throw std::invalid_argument("MeshBvh: mesh has no triangles");
  if (!holds(mesh_->triangles.size())) {
    throw std::length_error("MeshBvh: " + std::to_string(mesh_->triangles.size()) + " triangles, more than the " +
                            std::to_string(kMaxTriangles) + " one tree holds");
  }
  interface_ = std::make_unique<btTriangleIndexVertexArray>();
  // One Bullet part per kPartTriangles triangles, all over the same vertices: a leaf then
  // names (part, index in part), and part * kPartTriangles + index is the mesh's triangle.
  add_mesh_parts(*interface_, mesh_->triangles, mesh_->vertices_m, kPartTriangles);
  const std::size_t triangle_count = mesh_->triangles.size();
  const bool given = !given_face_normals_O.empty();
  if (given) {
    if (given_face_normals_O.size() != triangle_count) return false;
    face_normals_O_ = std::move(given_face_normals_O);
  } else {
    resize_in_huge_pages(face_normals_O_, triangle_count);
  }
  // The bounds in the same pass, each half of the triangles taking the same share of the
  // vertices (the shares cover them all, once). Given normals are checked by the tree's
  // check instead, leaf by leaf, where it has the triangle's corners at hand, and so are
  // a checked mesh's triangles.
  const std::size_t vertex_count = mesh_->vertices_m.size();
  const bool check_normals = check_mesh && mesh_->vertex_normals.size() == vertex_count;
  if (check_mesh && !check_normals && !mesh_->vertex_normals.empty()) return false;
  std::array<Eigen::AlignedBox3d, 2> half_bounds;
  const bool mesh_holds = in_two_halves(triangle_count, kParallelNodes, [&](std::size_t first, std::size_t last) {
    if (!given) {
      for (std::size_t i = first; i < last; ++i) {
        const TriangleIndices& t = mesh_->triangles[i];
        if (check_mesh && (t[0] >= vertex_count || t[1] >= vertex_count || t[2] >= vertex_count)) return false;
        face_normals_O_[i] =
            unit_face_normal(mesh_->vertices_m[t[0]], mesh_->vertices_m[t[1]], mesh_->vertices_m[t[2]]);
      }
    }
    // Over local pointers and accumulators, without a branch: written through the box,
    // or read through the mesh's arrays, every vertex reloaded them (they might alias).
    const Eigen::Vector3d* const vertices = mesh_->vertices_m.data();
    const Eigen::Vector3f* const normals = check_normals ? mesh_->vertex_normals.data() : nullptr;
    const auto not_finite = [](auto x) {
      return static_cast<int>(!(std::abs(x) <= std::numeric_limits<decltype(x)>::max()));
    };
    Eigen::Array3d lo = Eigen::Array3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Array3d hi = -lo;
    int bad = 0;
    const std::size_t v_end = last * vertex_count / triangle_count;
    for (std::size_t v = first * vertex_count / triangle_count; v < v_end; ++v) {
      const Eigen::Array3d p = vertices[v].array();
      lo = lo.min(p);
      hi = hi.max(p);
      if (check_mesh) bad |= not_finite(p.x()) | not_finite(p.y()) | not_finite(p.z());
      if (normals != nullptr) bad |= not_finite(normals[v].x()) | not_finite(normals[v].y()) | not_finite(normals[v].z());
    }
    if ((lo <= hi).all()) half_bounds[first == 0 ? std::size_t{0} : std::size_t{1}] = Eigen::AlignedBox3d(lo.matrix(), hi.matrix());
    return bad == 0;
  });
  if (!mesh_holds) return false;
  bounds_ = half_bounds[0].extend(half_bounds[1]);
  grid_ = tree_grid_box(*mesh_, bounds_);
  off_grid_ = grid_.min() != bounds_.min() || grid_.max() != bounds_.max();
  const double extent = grid_.sizes().maxCoeff();
  bvh_scale_ = extent > 0.0 ? kBvhExtentUnits / extent : 1.0;
  interface_->setScaling(btVector3(bvh_scale_, bvh_scale_, bvh_scale_));
  // The bounds are known; without them Bullet walks every triangle to find them. The
  // shape's box (a body's, in the dynamics) is the whole mesh's, whatever the grid.
  interface_->setPremadeAabb(to_bt(bounds_.min() * bvh_scale_), to_bt(bounds_.max() * bvh_scale_));
  return true;
}

MeshBvh::MeshBvh(std::shared_ptr<const TriangleMesh> mesh, MeshOrder order,
                 const BuildProgress& progress)
    : mesh_(std::move(mesh)) {
  (void)make_interface();  // computes the normals: always true
  // Bullet's own build quantizes over the shape's box without clamping: a grid smaller
  // than the bounds needs the build in pieces, which clamps.
  if (mesh_->triangles.size() >= kSplitBuildMinTriangles || off_grid_) {
    // The last tenth is left for what follows the pieces (the leaf order, the adoption).
    BuildProgress pieces;
    if (progress) pieces = [&progress](double placed) { progress(0.9 * placed); };
    built_tree_ = build_tree_in_pieces(*mesh_, bvh_scale_, to_bt(grid_.min() * bvh_scale_),
                                       to_bt(grid_.max() * bvh_scale_), pieces, off_grid_);
  }
  if (built_tree_) {
    shape_ = std::make_unique<btBvhTriangleMeshShape>(interface_.get(), /*quantized=*/true, /*buildBvh=*/false);
    // Same scaling as the interface, or Bullet resets it and builds the tree again.
    shape_->setOptimizedBvh(built_tree_.get(), btVector3(bvh_scale_, bvh_scale_, bvh_scale_));
  } else {
    shape_ = std::make_unique<btBvhTriangleMeshShape>(interface_.get(), /*quantized=*/true, /*buildBvh=*/true);
  }
  if (order == MeshOrder::Leaves) put_mesh_in_leaf_order(*shape_->getOptimizedBvh());
  adopt_tree(shape_->getOptimizedBvh());
}

void MeshBvh::put_mesh_in_leaf_order(btQuantizedBvh& tree) {
  const TriangleMesh& given = *mesh_;
  const std::size_t triangle_count = given.triangles.size();
  const std::size_t vertex_count = given.vertices_m.size();
  btQuantizedBvhNode* const nodes = &tree.getQuantizedNodeArray()[0];
  const std::size_t node_count = nodes[0].isLeafNode() ? 1 : static_cast<std::size_t>(nodes[0].getEscapeIndex());
  // 1. The leaves renamed in walk order; given_of[k] is the given triangle leaf k named.
  std::vector<std::uint32_t> given_of;
  resize_in_huge_pages(given_of, triangle_count);
  std::size_t leaves = 0;
  for (std::size_t i = 0; i < node_count; ++i) {
    btQuantizedBvhNode& node = nodes[i];
    if (!node.isLeafNode()) continue;
    if (leaves == triangle_count) throw std::logic_error("MeshBvh: the tree has more leaves than triangles");
    given_of[leaves] = static_cast<std::uint32_t>(leaf_triangle(node));
    node.m_escapeIndexOrTriangleIndex = leaf_code(leaves);
    ++leaves;
  }
  if (leaves != triangle_count) throw std::logic_error("MeshBvh: the tree has fewer leaves than triangles");
  // 2. The face normals in the new order, the given ones let go first: the load's peak
  // of memory holds one copy of them.
  {
    MeshArray<Eigen::Vector3d> face_normals_O;
    resize_in_huge_pages(face_normals_O, triangle_count);
    for (std::size_t k = 0; k < triangle_count; ++k) face_normals_O[k] = face_normals_O_[given_of[k]];
    face_normals_O_ = std::move(face_normals_O);
  }
  // 3. Each vertex numbered where a triangle first uses it, the unused ones after.
  auto ordered = std::make_shared<TriangleMesh>();
  resize_in_huge_pages(ordered->triangles, triangle_count);
  std::vector<std::uint32_t> new_vertex;
  new_vertex.assign(vertex_count, std::numeric_limits<std::uint32_t>::max());
  std::uint32_t next = 0;
  for (std::size_t k = 0; k < triangle_count; ++k) {
    const TriangleIndices& t = given.triangles[given_of[k]];
    for (std::size_t c = 0; c < 3; ++c) {
      std::uint32_t& v = new_vertex[t[c]];
      if (v == std::numeric_limits<std::uint32_t>::max()) v = next++;
      ordered->triangles[k][c] = v;
    }
  }
  for (std::uint32_t& v : new_vertex) {
    if (v == std::numeric_limits<std::uint32_t>::max()) v = next++;
  }
  given_of = {};
  // 4. The vertices and their normals moved to their new places.
  resize_in_huge_pages(ordered->vertices_m, vertex_count);
  for (std::size_t v = 0; v < vertex_count; ++v) ordered->vertices_m[new_vertex[v]] = given.vertices_m[v];
  if (!given.vertex_normals.empty()) {
    resize_in_huge_pages(ordered->vertex_normals, vertex_count);
    for (std::size_t v = 0; v < vertex_count; ++v) ordered->vertex_normals[new_vertex[v]] = given.vertex_normals[v];
  }
  // 5. Bullet's parts point at the new arrays: the same parts, over the same counts.
  IndexedMeshArray& parts = interface_->getIndexedMeshArray();
  for (int p = 0; p < parts.size(); ++p) {
    parts[p].m_triangleIndexBase = reinterpret_cast<const unsigned char*>(
        ordered->triangles.data() + static_cast<std::size_t>(p) * kPartTriangles);
    parts[p].m_vertexBase = reinterpret_cast<const unsigned char*>(ordered->vertices_m.data());
  }
  mesh_ = std::move(ordered);
}

void MeshBvh::adopt_tree(btQuantizedBvh* tree) {
  tree_ = tree;
  nodes_ = &tree->getQuantizedNodeArray()[0];
  // The root spans the whole tree: its escape index, or itself when it is a leaf (one
  // triangle). The array itself may be longer than the tree (Bullet sizes it 2n).
  node_count_ = nodes_->isLeafNode() ? 1 : nodes_->getEscapeIndex();
}

std::unique_ptr<MeshBvh> MeshBvh::from_serialized(std::shared_ptr<const TriangleMesh> mesh,
                                                  std::span<const std::byte> serialized) {
  if (serialized.empty() || serialized.size() > kMaxSerializedBytes) return nullptr;
  const std::size_t size = (serialized.size() + kBulletAlignment - 1) / kBulletAlignment * kBulletAlignment;
  std::shared_ptr<std::byte> buffer(static_cast<std::byte*>(std::aligned_alloc(kBulletAlignment, size)),
                                    &free_aligned);
  if (!buffer) return nullptr;
  std::memcpy(buffer.get(), serialized.data(), serialized.size());
  return adopt_serialized(std::move(mesh), {buffer.get(), serialized.size()}, buffer);
}

std::unique_ptr<MeshBvh> MeshBvh::adopt_serialized(std::shared_ptr<const TriangleMesh> mesh,
                                                   std::span<std::byte> serialized, std::shared_ptr<void> storage,
                                                   TreePages pages, const std::function<bool()>& ready,
                                                   MeshArray<Eigen::Vector3d> face_normals_O) {
  if (!mesh || mesh->triangles.empty() || serialized.empty() || serialized.size() > kMaxSerializedBytes ||
      reinterpret_cast<std::uintptr_t>(serialized.data()) % kBulletAlignment != 0) {
    return nullptr;
  }
  std::unique_ptr<MeshBvh> out(new MeshBvh());
  out->mesh_ = std::move(mesh);
  // Whatever fails, a caller reading the buffer is waited for before it is let go.
  const auto refused = [&] {
    if (ready) (void)ready();
    return nullptr;
  };
  if (!out->make_interface(std::move(face_normals_O), /*check_mesh=*/true)) return refused();
  out->serialized_storage_ = std::move(storage);
  // Bullet's own adoption path: it builds a btQuantizedBvh in the buffer and hands it out
  // as btOptimizedBvh* (which adds no data). Our calls go through the object's true
  // type, btQuantizedBvh, at the same address (single inheritance, offset 0).
  btOptimizedBvh* adopted = btOptimizedBvh::deSerializeInPlace(serialized.data(),
                                                               static_cast<unsigned>(serialized.size()),
                                                               /*swapEndian=*/false);
  if (adopted == nullptr) return refused();
  auto* tree = reinterpret_cast<btQuantizedBvh*>(adopted);
  out->adopted_tree_ = tree;  // from here on the destructor releases it
  if (!tree->isQuantized()) return refused();
  const auto& nodes = tree->getQuantizedNodeArray();
  if (nodes.size() <= 0) return refused();
  // The subtree headers and the other walks would trust the file's other fields; the
  // stackless walk needs only the nodes, checked below. The quantization is this mesh's,
  // set as the build sets it, not the file's.
  tree->setTraversalMode(btQuantizedBvh::TRAVERSAL_STACKLESS);
  tree->setQuantizationValues(to_bt(out->grid_.min() * out->bvh_scale_), to_bt(out->grid_.max() * out->bvh_scale_));
  out->tree_ = tree;  // quantize() for the check; the nodes are adopted only once checked
  if (!out->tree_checks_out({&nodes[0], static_cast<std::size_t>(nodes.size())}, pages)) return refused();
  if (ready && !ready()) return nullptr;
  out->adopt_tree(tree);
  out->shape_ = std::make_unique<btBvhTriangleMeshShape>(out->interface_.get(), true, /*buildBvh=*/false);
  // Same scaling as the interface, or Bullet resets it and re-walks the tree.
  out->shape_->setOptimizedBvh(adopted, btVector3(out->bvh_scale_, out->bvh_scale_, out->bvh_scale_));
  return out;
}

bool MeshBvh::subtree_checks_out(std::span<const btQuantizedBvhNode> nodes, std::size_t begin, std::size_t end,
                                 const btQuantizedBvhNode* parent, std::uint64_t* named,
                                 TreeCheckState& state) const {
  struct Open {
    std::size_t end;  // one past the inner node's last node
    const btQuantizedBvhNode* node;
    int children = 0;  // of its two subtrees, how many have begun
  };
  std::vector<Open> open;
  std::size_t window = begin;  // nodes before this are released (TreePages::Release)
  // Read once and counted here: the other thread's subtree shares `state`, and a write to
  // it per leaf, or a read of the line such a write moves, costs most of the check.
  const bool release_pages = state.release_pages;
  const Eigen::AlignedBox3d corner_box = state.corner_box;
  const std::size_t triangle_count = mesh_->triangles.size();
  const std::size_t vertex_count = mesh_->vertices_m.size();
  std::size_t leaves = 0;
  for (std::size_t i = begin; i < end; ++i) {
    if (release_pages && i % kPageWindowNodes == 0) {
      populate_for_reading(&nodes[i], std::min(kPageWindowNodes, end - i) * sizeof(btQuantizedBvhNode));
      if (i > window) {
        release_file_pages(&nodes[window], (i - window) * sizeof(btQuantizedBvhNode));
        window = i;
      }
    }
    const btQuantizedBvhNode& node = nodes[i];
    const std::size_t limit = open.empty() ? end : open.back().end;
    if (open.empty() ? i != begin : ++open.back().children > 2) return false;
    const btQuantizedBvhNode* holder = open.empty() ? parent : open.back().node;
    if (holder != nullptr && !box_holds(*holder, node.m_quantizedAabbMin, node.m_quantizedAabbMax)) return false;
    if (node.isLeafNode()) {
      const std::uint64_t triangle = leaf_triangle(node);
      if (triangle >= triangle_count) return false;
      const std::uint64_t bit = std::uint64_t{1} << (triangle % 64);
      if ((named[triangle / 64] & bit) != 0) return false;
      named[triangle / 64] |= bit;
      ++leaves;
      const TriangleIndices& corners = mesh_->triangles[triangle];
      if (corners[0] >= vertex_count || corners[1] >= vertex_count || corners[2] >= vertex_count ||
          corners[0] == corners[1] || corners[1] == corners[2] || corners[0] == corners[2]) {
        return false;
      }
      const Eigen::Vector3d& a = mesh_->vertices_m[corners[0]];
      const Eigen::Vector3d& b = mesh_->vertices_m[corners[1]];
      const Eigen::Vector3d& c = mesh_->vertices_m[corners[2]];
      if (!face_normal_holds(face_normals_O_[triangle], a, b, c)) return false;
      // quantize() of the triangle's box, inline: returned through a call, its box cost
      // the check more than the rounding itself.
      Eigen::Vector3d lo = a.cwiseMin(b).cwiseMin(c) * bvh_scale_;
      Eigen::Vector3d hi = a.cwiseMax(b).cwiseMax(c) * bvh_scale_;
      if (off_grid_) {  // clamped as the build clamped its corners
        lo = lo.cwiseMax(corner_box.min()).cwiseMin(corner_box.max());
        hi = hi.cwiseMax(corner_box.min()).cwiseMin(corner_box.max());
      }
      std::array<std::uint16_t, 3> q_min{}, q_max{};
      tree_->quantizeWithClamp(q_min.data(), to_bt(lo), 0);
      tree_->quantizeWithClamp(q_max.data(), to_bt(hi), 1);
      if (!box_holds(node, q_min.data(), q_max.data())) return false;
      if (open.empty() && end - begin != 1) return false;  // a leaf root is the whole subtree
      // Every subtree ends with a leaf: close the inner nodes that end here.
      while (!open.empty() && open.back().end == i + 1) {
        if (open.back().children != 2) return false;
        open.pop_back();
      }
    } else {
      // Stored negated; INT_MIN has no positive counterpart.
      const std::int64_t span = -static_cast<std::int64_t>(node.m_escapeIndexOrTriangleIndex);
      if (span < 3 || static_cast<std::uint64_t>(span) > limit - i) return false;
      if (open.empty() && static_cast<std::size_t>(span) != end - begin) return false;
      open.push_back(Open{i + static_cast<std::size_t>(span), &node});
    }
  }
  if (release_pages && end > window) {
    release_file_pages(&nodes[window], (end - window) * sizeof(btQuantizedBvhNode));
  }
  state.leaves.fetch_add(leaves, std::memory_order_relaxed);
  return open.empty();
}

bool MeshBvh::tree_checks_out(std::span<const btQuantizedBvhNode> nodes, TreePages pages) const {
  const std::size_t triangles = mesh_->triangles.size();
  TreeCheckState state{{0}, pages == TreePages::Release, off_grid_corner_box(*tree_)};
  // One bit per triangle for each thread's leaves: a triangle named twice has its bit set
  // twice in one, or once in both.
  std::array<std::vector<std::uint64_t>, 2> named;
  named[0].assign((triangles + 63) / 64, 0);
  const std::size_t n = nodes.size();
  if (n == 0) return false;
  bool whole = false;
  if (nodes[0].isLeafNode() || n < kParallelNodes) {
    whole = subtree_checks_out(nodes, 0, n, nullptr, named[0].data(), state);
  } else {
    named[1].assign(named[0].size(), 0);
    // The root's two subtrees are checked side by side, each against the root's box. The
    // root spans the whole array, and its first subtree starts right after it.
    const auto span_of = [&](std::size_t i) {
      return nodes[i].isLeafNode() ? std::int64_t{1} : -static_cast<std::int64_t>(nodes[i].m_escapeIndexOrTriangleIndex);
    };
    const std::int64_t span = span_of(0);
    const std::int64_t first_span = span_of(1);
    if (first_span < 1) return false;
    const std::size_t first_end = 1 + static_cast<std::size_t>(first_span);
    if (span != static_cast<std::int64_t>(n) || first_end < 2 || first_end >= n) return false;
    const std::array<std::size_t, 3> bounds{1, first_end, n};
    whole = in_two_halves(2, 2, [&](std::size_t first, std::size_t last) {
      for (std::size_t k = first; k < last; ++k) {
        if (!subtree_checks_out(nodes, bounds[k], bounds[k + 1], &nodes[0], named[k].data(), state)) return false;
      }
      return true;
    });
    for (std::size_t w = 0; whole && w < named[0].size(); ++w) whole = (named[0][w] & named[1][w]) == 0;
  }
  return whole && state.leaves.load() == triangles;
}

MeshBvh::~MeshBvh() {
  shape_.reset();
  // An in-place BVH lives in serialized_storage_; run its destructor, the buffer is freed after.
  if (adopted_tree_ != nullptr) adopted_tree_->~btQuantizedBvh();
}

std::uint64_t MeshBvh::serialized_bytes(std::uint64_t nodes, std::uint64_t subtrees) {
  // As btQuantizedBvh::calculateSerializeBufferSize adds them, without its wrap-around.
  return sizeof(btQuantizedBvh) + btQuantizedBvh::getAlignmentSerializationPadding() +
         subtrees * sizeof(btBvhSubtreeInfo) + nodes * sizeof(btQuantizedBvhNode);
}

MeshBvh::SerializedTree MeshBvh::serialize_tree() const {
  // Bullet's API is not const-correct; this only reads the subtree count.
  auto* tree = const_cast<btQuantizedBvh*>(tree_);  // NOLINT
  const std::uint64_t bytes = serialized_bytes(static_cast<std::uint64_t>(node_count_),
                                               static_cast<std::uint64_t>(tree->getSubtreeInfoArray().size()));
  if (bytes > kMaxSerializedBytes) {
    throw std::length_error("MeshBvh: the tree takes " + std::to_string(bytes) + " bytes, more than the " +
                            std::to_string(kMaxSerializedBytes) + " Bullet's serialized format holds");
  }
  const unsigned size = tree_->calculateSerializeBufferSize();
  if (size != bytes) throw std::runtime_error("MeshBvh: Bullet's serialized size is not the one counted");
  const std::size_t padded = (size + kBulletAlignment - 1) / kBulletAlignment * kBulletAlignment;
  SerializedTree out{{static_cast<std::byte*>(std::aligned_alloc(kBulletAlignment, padded)), &free_aligned}, size};
  if (!out.bytes || !tree_->serialize(out.bytes.get(), size, /*swapEndian=*/false)) {
    throw std::runtime_error("MeshBvh: Bullet failed to serialize the BVH");
  }
  return out;
}

std::vector<std::byte> MeshBvh::serialize_bvh() const {
  const SerializedTree tree = serialize_tree();
  return {tree.bytes.get(), tree.bytes.get() + tree.size};
}

Eigen::AlignedBox3d MeshBvh::off_grid_corner_box(const btQuantizedBvh& tree) {
  const std::array<unsigned short, 3> bottom{0, 0, 0};
  const std::array<unsigned short, 3> below_top{65532, 65532, 65532};
  const btVector3 lo = tree.unQuantize(bottom.data());
  const btVector3 hi = tree.unQuantize(below_top.data());
  return {Eigen::Vector3d(lo.x(), lo.y(), lo.z()), Eigen::Vector3d(hi.x(), hi.y(), hi.z())};
}

MeshBvh::QuantizedBox MeshBvh::quantize(const Eigen::AlignedBox3d& box_O) const {
  // What reportAabbOverlappingNodex does with its query box before it walks the tree.
  QuantizedBox q;
  tree_->quantizeWithClamp(q.min.data(), to_bt(box_O.min() * bvh_scale_), 0);
  tree_->quantizeWithClamp(q.max.data(), to_bt(box_O.max() * bvh_scale_), 1);
  return q;
}

}  // namespace mhd
