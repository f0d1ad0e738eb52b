// A large mesh's tree built in two halves on two threads (collision/split_tree_build.h):
// split in space whatever the triangles' order, every leaf naming its triangle once and
// every box holding what it must (the cached tree's check), and every triangle a box
// overlaps reported; and a mesh whose centres the median cannot split is built whole.

#include "collision/mesh_bvh.h"
#include "collision/split_tree_build.h"
#include "support/large_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
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

TEST(SplitTreeBuild, ASmallMeshBuiltInTwoHalvesPassesTheTreeCheck) {
  // The two-thread build called directly on a grid small enough for ThreadSanitizer: the
  // tree it makes, with the quantization MeshBvh gives the mesh, is adopted and answers.
  auto mesh = std::make_shared<TriangleMesh>();
  constexpr int kQuads = 40;
  for (int j = 0; j <= kQuads; ++j) {
    for (int i = 0; i <= kQuads; ++i) mesh->vertices_m.emplace_back(i * 0.01, j * 0.01, 0.001 * ((i * j) % 7));
  }
  const auto id = [](int i, int j) { return static_cast<std::uint32_t>(j * (kQuads + 1) + i); };
  for (int j = 0; j < kQuads; ++j) {
    for (int i = 0; i < kQuads; ++i) {
      mesh->triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh->triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  std::shuffle(mesh->triangles.begin(), mesh->triangles.end(), std::mt19937(3));
  const MeshBvh whole(mesh);  // for the scale and bounds the tree is quantized by
  const double scale = whole.bvh_scale();
  const Eigen::Vector3d lo = whole.bounds().min() * scale, hi = whole.bounds().max() * scale;
  const std::unique_ptr<btOptimizedBvh> tree =
      build_tree_in_two_halves(*mesh, scale, btVector3(lo.x(), lo.y(), lo.z()), btVector3(hi.x(), hi.y(), hi.z()));
  ASSERT_NE(tree, nullptr);
  const unsigned size = tree->calculateSerializeBufferSize();
  const std::size_t padded = (size + 15) / 16 * 16;
  const std::unique_ptr<std::byte, void (*)(void*)> buffer(static_cast<std::byte*>(std::aligned_alloc(16, padded)),
                                                           &std::free);
  ASSERT_TRUE(tree->serialize(buffer.get(), size, /*swapEndian=*/false));
  const auto adopted = MeshBvh::from_serialized(mesh, {buffer.get(), size});
  ASSERT_NE(adopted, nullptr) << "the tree built in two halves fails the cached tree's check";
  expect_every_overlap_reported(*adopted, random_boxes(5, adopted->bounds(), 0.02));
}

TEST(SplitTreeBuild, CentresOnOnePlaneAcrossTheLongestAxisAreBuiltWhole) {
  // Every triangle centred on x = 0 across [-1, 1] in x, the longest axis: the median
  // leaves one half empty, so the tree is built whole, and holds as well.
  auto mesh = std::make_shared<TriangleMesh>();
  const std::size_t n = kSplitBuildMinTriangles;
  mesh->vertices_m.reserve(3 * n);
  mesh->triangles.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double y = static_cast<double>(k) / static_cast<double>(n);
    const auto first = static_cast<std::uint32_t>(mesh->vertices_m.size());
    mesh->vertices_m.emplace_back(-1.0, y, 0.0);
    mesh->vertices_m.emplace_back(1.0, y, 0.0);
    mesh->vertices_m.emplace_back(0.0, y + 0.25, 0.1);
    mesh->triangles.push_back({first, first + 1, first + 2});
  }
  const MeshBvh built(mesh);
  ASSERT_NE(MeshBvh::from_serialized(mesh, built.serialize_bvh()), nullptr);
  expect_every_overlap_reported(built, random_boxes(11, built.bounds(), 0.01));
}

}  // namespace split_tree_build_test
}  // namespace mhd
