#include "collision/mesh_bvh.h"

#include "collision/segment_triangle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

namespace mhd {
namespace {

// A grid of n x n quads in z = 0 over [0, 1]^2.
std::shared_ptr<TriangleMesh> grid_mesh(int n) {
  auto mesh = std::make_shared<TriangleMesh>();
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) mesh->vertices_m.emplace_back(double(i) / n, double(j) / n, 0.0);
  auto id = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      mesh->triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh->triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return mesh;
}

std::vector<std::uint32_t> query(const MeshBvh& bvh, const Eigen::AlignedBox3d& box) {
  std::vector<std::uint32_t> out;
  bvh.for_each_triangle_overlapping(box, [&](std::uint32_t t) { out.push_back(t); });
  std::sort(out.begin(), out.end());
  return out;
}

TEST(MeshBvh, KeepsEachFaceNormalAsTheSweepWouldComputeIt) {
  // Bit for bit, in a tree built and in one adopted from the cache, so a sweep given the
  // stored normal answers as one that computes it. A zero-area triangle keeps zero.
  const auto mesh = grid_mesh(8);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1e-3, 1e-3);
  for (auto& v : mesh->vertices_m) v.z() = u(rng);
  mesh->triangles.push_back({0, 1, 2});  // 0, 1, 2 lie on one line (y = 0): no area
  mesh->vertices_m[2].z() = mesh->vertices_m[1].z() = mesh->vertices_m[0].z() = 0.0;
  const MeshBvh built(mesh);
  const auto adopted = MeshBvh::from_serialized(mesh, built.serialize_bvh());
  ASSERT_TRUE(adopted);
  for (std::uint32_t t = 0; t < mesh->triangle_count(); ++t) {
    const auto& c = mesh->triangles[t];
    const Eigen::Vector3d n = unit_face_normal(mesh->vertices_m[c[0]], mesh->vertices_m[c[1]], mesh->vertices_m[c[2]]);
    EXPECT_EQ(std::memcmp(n.data(), built.face_normal_O(t).data(), sizeof(double) * 3), 0) << t;
    EXPECT_EQ(std::memcmp(n.data(), adopted->face_normal_O(t).data(), sizeof(double) * 3), 0) << t;
  }
  EXPECT_EQ(built.face_normal_O(static_cast<std::uint32_t>(mesh->triangle_count() - 1)), Eigen::Vector3d::Zero());
}

TEST(MeshBvh, BoxQueryReportsEveryOverlappingTriangle) {
  const auto mesh = grid_mesh(40);
  const MeshBvh bvh(mesh);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-0.1, 1.1);
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector3d c(u(rng), u(rng), 0.0);
    const Eigen::AlignedBox3d box(c - Eigen::Vector3d(0.02, 0.02, 0.001), c + Eigen::Vector3d(0.02, 0.02, 0.001));
    const auto found = query(bvh, box);
    for (std::uint32_t t = 0; t < mesh->triangles.size(); ++t) {
      Eigen::AlignedBox3d tb;
      for (auto v : mesh->triangles[t]) tb.extend(mesh->vertices_m[v]);
      if (tb.intersects(box)) {
        EXPECT_TRUE(std::binary_search(found.begin(), found.end(), t)) << "missed triangle " << t;
      }
    }
  }
}

TEST(MeshBvh, SerializedTreeAnswersLikeTheBuiltOne) {
  const auto mesh = grid_mesh(30);
  const MeshBvh built(mesh);
  const auto bytes = built.serialize_bvh();
  ASSERT_FALSE(bytes.empty());
  const auto loaded = MeshBvh::from_serialized(mesh, bytes);
  ASSERT_NE(loaded, nullptr);
  const Eigen::AlignedBox3d box(Eigen::Vector3d(0.2, 0.3, -0.01), Eigen::Vector3d(0.25, 0.45, 0.01));
  EXPECT_EQ(query(built, box), query(*loaded, box));
  EXPECT_FALSE(query(built, box).empty());
  // A tree adopted from a buffer serializes again to a tree that answers the same.
  const auto again = MeshBvh::from_serialized(mesh, loaded->serialize_bvh());
  ASSERT_NE(again, nullptr);
  EXPECT_EQ(query(built, box), query(*again, box));
}

// Bullet's own query, through its virtual callback: what the tree's walk must report.
std::vector<std::uint32_t> bullet_query(const MeshBvh& bvh, const Eigen::AlignedBox3d& box, double scale) {
  struct Collect final : btNodeOverlapCallback {
    std::vector<std::uint32_t> found;
    void processNode(int /*subPart*/, int triangle) override { found.push_back(static_cast<std::uint32_t>(triangle)); }
  } collect;
  const auto* tree = const_cast<btBvhTriangleMeshShape&>(bvh.shape()).getOptimizedBvh();
  const Eigen::Vector3d lo = box.min() * scale, hi = box.max() * scale;
  tree->reportAabbOverlappingNodex(&collect, btVector3(lo.x(), lo.y(), lo.z()), btVector3(hi.x(), hi.y(), hi.z()));
  std::sort(collect.found.begin(), collect.found.end());
  return collect.found;
}

TEST(MeshBvh, OwnWalkReportsExactlyWhatBulletsQueryReports) {
  // A wavy grid, so the tree's boxes are not all flat, and boxes from a point to most of
  // the mesh, partly outside it.
  auto mesh = grid_mesh(60);
  for (auto& v : mesh->vertices_m) v.z() = 0.05 * std::sin(9.0 * v.x()) * std::cos(7.0 * v.y());
  const MeshBvh built(mesh);
  const auto loaded = MeshBvh::from_serialized(mesh, built.serialize_bvh());
  ASSERT_NE(loaded, nullptr);
  // Bullet sees the mesh scaled so its largest extent is 1e4 units (mesh_bvh.cpp).
  const double scale = 1e4 / mhd::mesh_bounds(*mesh).sizes().maxCoeff();
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  std::uniform_real_distribution<double> size(0.0, 1.0);
  int non_empty = 0;
  for (int k = 0; k < 500; ++k) {
    const Eigen::Vector3d c(u(rng), u(rng), 0.1 * u(rng) - 0.05);
    const Eigen::Vector3d half = Eigen::Vector3d::Constant(std::pow(size(rng), 4.0) * 0.5);
    const Eigen::AlignedBox3d box(c - half, c + half);
    const auto expected = bullet_query(built, box, scale);
    EXPECT_EQ(query(built, box), expected) << "box " << k;
    EXPECT_EQ(query(*loaded, box), expected) << "box " << k;
    non_empty += expected.empty() ? 0 : 1;
  }
  EXPECT_GT(non_empty, 100);
}

TEST(MeshBvh, AWalkStopsWhenAskedTo) {
  const auto mesh = grid_mesh(20);
  const MeshBvh bvh(mesh);
  int calls = 0;
  bvh.for_each_leaf_overlapping(bvh.quantize(mhd::mesh_bounds(*mesh)), [&](std::uint32_t, const btQuantizedBvhNode&) {
    return ++calls < 5;
  });
  EXPECT_EQ(calls, 5);
}

TEST(MeshBvh, ABoxInsideAnotherReportsNoTriangleTheOtherMisses) {
  const auto mesh = grid_mesh(40);
  const MeshBvh bvh(mesh);
  const Eigen::AlignedBox3d outer(Eigen::Vector3d(0.3, 0.3, -0.01), Eigen::Vector3d(0.4, 0.45, 0.01));
  const Eigen::AlignedBox3d inner(Eigen::Vector3d(0.31, 0.35, -0.001), Eigen::Vector3d(0.33, 0.4, 0.001));
  const Eigen::AlignedBox3d beside(Eigen::Vector3d(0.39, 0.35, -0.001), Eigen::Vector3d(0.41, 0.4, 0.001));
  EXPECT_TRUE(MeshBvh::contains(bvh.quantize(outer), bvh.quantize(inner)));
  EXPECT_FALSE(MeshBvh::contains(bvh.quantize(outer), bvh.quantize(beside)));
  const auto all = query(bvh, outer);
  for (std::uint32_t t : query(bvh, inner)) EXPECT_TRUE(std::binary_search(all.begin(), all.end(), t));
}

TEST(MeshBvh, RejectsATreeOfAnotherMesh) {
  const MeshBvh big(grid_mesh(30));
  const auto bytes = big.serialize_bvh();
  EXPECT_EQ(MeshBvh::from_serialized(grid_mesh(5), bytes), nullptr);
  EXPECT_EQ(MeshBvh::from_serialized(grid_mesh(5), std::span<const std::byte>()), nullptr);
}

}  // namespace
}  // namespace mhd
