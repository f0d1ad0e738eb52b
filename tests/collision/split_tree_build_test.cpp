// A large mesh's tree built in pieces on two threads (collision/split_tree_build.h): split
// in space whatever the triangles' order, every leaf naming its triangle once and every
// box holding what it must (the cached tree's check), and every triangle a box overlaps
// reported; at every size around a piece's, and where the centres cannot be split.

#include "collision/mesh_bvh.h"
#include "collision/split_tree_build.h"
#include "support/large_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <thread>
#include <vector>

namespace mhd {
namespace split_tree_build_test {

std::vector<std::uint32_t> reported(const MeshBvh& bvh, const Eigen::AlignedBox3d& box_O) {
  std::vector<std::uint32_t> out;
  bvh.for_each_triangle_overlapping(box_O, [&](std::uint32_t t) { out.push_back(t); });
  std::sort(out.begin(), out.end());
  return out;
}

// Every triangle whose own bounds overlap one of `boxes` must be reported for that box.
void expect_every_overlap_reported(const MeshBvh& bvh, const std::vector<Eigen::AlignedBox3d>& boxes) {
  const TriangleMesh& mesh = bvh.mesh();
  std::vector<std::vector<std::uint32_t>> must(boxes.size());
  for (std::uint32_t t = 0; t < mesh.triangle_count(); ++t) {
    Eigen::AlignedBox3d b;
    for (auto v : mesh.triangles[t]) b.extend(mesh.vertices_m[v]);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      if (b.intersects(boxes[i])) must[i].push_back(t);
    }
  }
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    ASSERT_FALSE(must[i].empty()) << "box " << i;
    const auto got = reported(bvh, boxes[i]);
    EXPECT_TRUE(std::includes(got.begin(), got.end(), must[i].begin(), must[i].end()))
        << "box " << i << ": " << got.size() << " reported, " << must[i].size() << " overlap";
  }
}

std::vector<Eigen::AlignedBox3d> random_boxes(std::uint32_t seed, const Eigen::AlignedBox3d& within, double size) {
  std::mt19937 rng(seed);
  std::vector<Eigen::AlignedBox3d> boxes;
  for (int i = 0; i < 8; ++i) {
    std::uniform_real_distribution<> uniform(0.0, 1.0);
    const Eigen::Vector3d unit(uniform(rng), uniform(rng), uniform(rng));
    Eigen::Vector3d at = within.min() + unit.cwiseProduct(within.sizes());
    at.z() = within.min().z();  // on the lowest triangles
    boxes.emplace_back(at - Eigen::Vector3d::Constant(size), at + Eigen::Vector3d::Constant(size));
  }
  return boxes;
}

TEST(SplitTreeBuild, AShuffledLargeMeshIsSplitInSpaceAndEveryLeafNamesItsTriangle) {
  // The triangles in random order: halves taken by index would each span the whole grid.
  const auto mesh = test::mesh_past_one_bullet_part();
  ASSERT_GE(mesh->triangle_count(), kSplitBuildMinTriangles);
  std::shuffle(mesh->triangles.begin(), mesh->triangles.end(), std::mt19937(27));
  const MeshBvh built(mesh);

  // The root's two subtrees share little of the longest axis: a box in one half walks one.
  auto& shape = const_cast<btBvhTriangleMeshShape&>(built.shape());  // NOLINT: Bullet is not const-correct
  const auto& nodes = shape.getOptimizedBvh()->getQuantizedNodeArray();
  ASSERT_FALSE(nodes[0].isLeafNode());
  const btQuantizedBvhNode& first = nodes[1];
  const btQuantizedBvhNode& second = nodes[1 + (first.isLeafNode() ? 1 : first.getEscapeIndex())];
  int shared_least = 65536;
  for (int k = 0; k < 2; ++k) {  // x and y: the grid's extent; z is half of it
    const int shared = std::min(first.m_quantizedAabbMax[k], second.m_quantizedAabbMax[k]) -
                       std::max(first.m_quantizedAabbMin[k], second.m_quantizedAabbMin[k]);
    const int extent = nodes[0].m_quantizedAabbMax[k] - nodes[0].m_quantizedAabbMin[k];
    shared_least = std::min(shared_least, shared * 100 / extent);
  }
  EXPECT_LE(shared_least, 5) << "percent of the longest axis both halves span";

  // The cached tree's check: layout, every leaf naming its triangle once, every box
  // holding its children and its triangle. A tree that fails it is refused.
  ASSERT_NE(MeshBvh::from_serialized(mesh, built.serialize_bvh()), nullptr);
  std::vector<Eigen::AlignedBox3d> boxes = random_boxes(7, built.bounds(), 0.004);
  boxes.emplace_back(Eigen::Vector3d(0.49, 0.49, 0.49), Eigen::Vector3d(0.51, 0.51, 0.51));  // the patch above
  expect_every_overlap_reported(built, boxes);
}

/// A grid of `quads` x `quads` squares, two triangles each, over [0, quads / 100] in x and
/// y with a little relief, its triangles shuffled by `seed`.
std::shared_ptr<TriangleMesh> shuffled_grid(int quads, std::uint32_t seed) {
  auto mesh = std::make_shared<TriangleMesh>();
  for (int j = 0; j <= quads; ++j) {
    for (int i = 0; i <= quads; ++i) mesh->vertices_m.emplace_back(i * 0.01, j * 0.01, 0.001 * ((i * j) % 7));
  }
  const auto id = [quads](int i, int j) { return static_cast<std::uint32_t>(j * (quads + 1) + i); };
  for (int j = 0; j < quads; ++j) {
    for (int i = 0; i < quads; ++i) {
      mesh->triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh->triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  std::shuffle(mesh->triangles.begin(), mesh->triangles.end(), std::mt19937(seed));
  return mesh;
}

/// The mesh's tree built in pieces, with the quantization MeshBvh gives the mesh, then
/// serialized and adopted as a cache entry is: null when it fails the cached tree's check.
std::unique_ptr<MeshBvh> built_in_pieces_and_adopted(const std::shared_ptr<TriangleMesh>& mesh) {
  const MeshBvh whole(mesh);  // for the scale and bounds the tree is quantized by
  const double scale = whole.bvh_scale();
  const Eigen::Vector3d lo = whole.bounds().min() * scale, hi = whole.bounds().max() * scale;
  const std::unique_ptr<btOptimizedBvh> tree =
      build_tree_in_pieces(*mesh, scale, btVector3(lo.x(), lo.y(), lo.z()), btVector3(hi.x(), hi.y(), hi.z()));
  EXPECT_NE(tree, nullptr);
  if (!tree) return nullptr;
  const unsigned size = tree->calculateSerializeBufferSize();
  const std::size_t padded = (size + 15) / 16 * 16;
  const std::unique_ptr<std::byte, void (*)(void*)> buffer(static_cast<std::byte*>(std::aligned_alloc(16, padded)),
                                                           &std::free);
  EXPECT_TRUE(tree->serialize(buffer.get(), size, /*swapEndian=*/false));
  return MeshBvh::from_serialized(mesh, {buffer.get(), size});
}

TEST(SplitTreeBuild, ASmallMeshBuiltInPiecesPassesTheTreeCheck) {
  // The two-thread build called directly on a grid small enough for ThreadSanitizer, of
  // 3200 triangles: a dozen pieces under levels split here.
  const auto mesh = shuffled_grid(40, 3);
  ASSERT_GT(mesh->triangle_count(), 8 * kPieceTriangles);
  const auto adopted = built_in_pieces_and_adopted(mesh);
  ASSERT_NE(adopted, nullptr) << "the tree built in pieces fails the cached tree's check";
  expect_every_overlap_reported(*adopted, random_boxes(5, adopted->bounds(), 0.02));
}

TEST(SplitTreeBuild, ProgressRisesOnTheCallingThreadToTheWhole) {
  // A long build says how far it is: the share of triangles placed in pieces, the other
  // thread's counted too, told on the calling thread only (a progress printer need not be
  // thread-safe), rising, at most once a hundredth, and ending at the whole.
  const auto mesh = shuffled_grid(40, 5);
  const MeshBvh whole(mesh);
  const double scale = whole.bvh_scale();
  const Eigen::Vector3d lo = whole.bounds().min() * scale, hi = whole.bounds().max() * scale;
  std::vector<double> told;
  bool other_thread = false;
  const std::thread::id caller = std::this_thread::get_id();
  const auto tree = build_tree_in_pieces(*mesh, scale, btVector3(lo.x(), lo.y(), lo.z()),
                                         btVector3(hi.x(), hi.y(), hi.z()), [&](double fraction) {
                                           other_thread = other_thread || std::this_thread::get_id() != caller;
                                           told.push_back(fraction);
                                         });
  ASSERT_NE(tree, nullptr);
  EXPECT_FALSE(other_thread);
  ASSERT_GE(told.size(), 2u);
  EXPECT_LE(told.size(), 101u);
  EXPECT_GT(told.front(), 0.0);
  EXPECT_EQ(told.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(told.begin(), told.end()));
  EXPECT_EQ(std::adjacent_find(told.begin(), told.end()), told.end()) << "a fraction told twice";
}

TEST(SplitTreeBuild, EveryTriangleCountAroundAPiecesSizeMakesAWholeTree) {
  // One triangle, a piece less one, one, and one more, and so on: each layout of levels
  // split here over pieces of Bullet's makes a tree that passes the check and answers.
  const std::size_t p = kPieceTriangles;
  for (const std::size_t count : {std::size_t{1}, std::size_t{2}, std::size_t{3}, p - 1, p, p + 1, 2 * p - 1, 2 * p,
                                  2 * p + 1, 4 * p + 3}) {
    auto mesh = shuffled_grid(static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count) / 2.0))),
                              static_cast<std::uint32_t>(count));
    mesh->triangles.resize(count);
    const auto adopted = built_in_pieces_and_adopted(mesh);
    ASSERT_NE(adopted, nullptr) << count << " triangles";
    Eigen::AlignedBox3d all = adopted->bounds();
    all.extend(all.min() - Eigen::Vector3d::Constant(1e-3)).extend(all.max() + Eigen::Vector3d::Constant(1e-3));
    EXPECT_EQ(reported(*adopted, all).size(), count) << count << " triangles";
  }
}

TEST(SplitTreeBuild, CentresOnOnePointAreOnePieceOfAnySize) {
  // Triangles centred on one point cannot be split by their centres: however many, they
  // are one piece, which Bullet builds, beside the rest of the mesh split as usual.
  auto mesh = shuffled_grid(20, 9);
  const std::size_t grid = mesh->triangles.size();
  constexpr int kConcentric = 3 * static_cast<int>(kPieceTriangles) + 7;
  for (int k = 1; k <= kConcentric; ++k) {
    const double r = 0.02 * k / kConcentric;
    const auto first = static_cast<std::uint32_t>(mesh->vertices_m.size());
    for (int c = 0; c < 3; ++c) {
      const double a = 2.0 * 3.141592653589793 * c / 3.0 + k;
      mesh->vertices_m.emplace_back(0.1 + r * std::cos(a), 0.1 + r * std::sin(a), 0.05);
    }
    mesh->triangles.push_back({first, first + 1, first + 2});
  }
  std::shuffle(mesh->triangles.begin(), mesh->triangles.end(), std::mt19937(4));
  ASSERT_EQ(mesh->triangles.size(), grid + kConcentric);
  const auto adopted = built_in_pieces_and_adopted(mesh);
  ASSERT_NE(adopted, nullptr);
  // A box around the common centre meets every concentric triangle.
  const Eigen::AlignedBox3d centre(Eigen::Vector3d(0.0999, 0.0999, 0.0499), Eigen::Vector3d(0.1001, 0.1001, 0.0501));
  std::size_t concentric_reported = 0;
  for (const std::uint32_t t : reported(*adopted, centre)) {
    concentric_reported += mesh->vertices_m[mesh->triangles[t][0]].z() == 0.05 ? 1 : 0;
  }
  EXPECT_EQ(concentric_reported, static_cast<std::size_t>(kConcentric));
  expect_every_overlap_reported(*adopted, random_boxes(13, adopted->bounds(), 0.01));
}

}  // namespace split_tree_build_test
}  // namespace mhd
