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


namespace far_triangle {

// grid_mesh(n) scaled to `side_m`, with one more triangle `far_m` away along x: a scan with
// a stray point, a model with a part left at another origin.
std::shared_ptr<TriangleMesh> sheet_with_far_triangle(int n, double side_m, double far_m) {
  auto mesh = grid_mesh(n);
  for (auto& v : mesh->vertices_m) v *= side_m;
  const auto first = static_cast<std::uint32_t>(mesh->vertices_m.size());
  mesh->vertices_m.emplace_back(far_m, 0.0, 0.0);
  mesh->vertices_m.emplace_back(far_m + side_m / n, 0.0, 0.0);
  mesh->vertices_m.emplace_back(far_m, side_m / n, 0.0);
  mesh->triangles.push_back({first, first + 1, first + 2});
  return mesh;
}

// All triangles whose box overlaps `box`, found the slow way.
std::vector<std::uint32_t> brute_force(const TriangleMesh& mesh, const Eigen::AlignedBox3d& box) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    Eigen::AlignedBox3d b;
    for (auto i : mesh.triangles[t]) b.extend(mesh.vertices_m[i]);
    if (b.intersects(box)) out.push_back(t);
  }
  return out;
}

TEST(MeshBvhGrid, OneTriangleFarAwayLeavesTheTreeAsFineAsTheRestOfTheMesh) {
  // 0.2 m sheet of 2 mm quads (20,000 triangles) and one triangle at each distance. The
  // tree's 16-bit grid over all of it would be 15 m wide at 1000 km: every query then
  // overlaps every leaf of the sheet. A 1 mm query box holds a few triangles at any
  // distance, and still every triangle it touches (the far one too).
  for (const double far_m : {1.0, 1e3, 1e6, 1e9}) {
    SCOPED_TRACE(far_m);
    const auto mesh = sheet_with_far_triangle(100, 0.2, far_m);
    const MeshBvh bvh(mesh);
    const auto adopted = MeshBvh::from_serialized(mesh, bvh.serialize_bvh());
    ASSERT_TRUE(adopted) << "the cached tree of such a mesh is adopted, not rebuilt";
    for (const MeshBvh* tree : std::array<const MeshBvh*, 2>{&bvh, adopted.get()}) {
      const Eigen::AlignedBox3d near(Eigen::Vector3d(0.1003, 0.1003, -0.0005), Eigen::Vector3d(0.1013, 0.1013, 0.0005));
      const auto found = query(*tree, near);
      const auto truth = brute_force(*mesh, near);
      EXPECT_TRUE(std::includes(found.begin(), found.end(), truth.begin(), truth.end()));
      EXPECT_LE(found.size(), 64u) << "of " << mesh->triangles.size();
      const Eigen::AlignedBox3d far_box(Eigen::Vector3d(far_m, 0.0, -1e-4), Eigen::Vector3d(far_m + 1e-4, 1e-4, 1e-4));
      const auto at_far = query(*tree, far_box);
      EXPECT_TRUE(std::binary_search(at_far.begin(), at_far.end(), mesh->triangles.size() - 1))
          << "the far triangle stays in the tree";
    }
  }
}

TEST(MeshBvhGrid, AFloorTheMeshSharesAFileWithIsNoStray) {
  // The dual: the sheet beside a floor 100 m wide of 1 m quads (20,000 triangles). The
  // grid over all of it is 1.5 mm, fine enough for the sheet's 2 mm triangles, so it
  // stays: a query on the floor far from the sheet finds only the floor's triangles there
  // (a grid over the sheet alone would pile the floor's far triangles on its edge).
  auto mesh = sheet_with_far_triangle(100, 0.2, 0.5);
  auto floor = grid_mesh(100);
  const auto first = static_cast<std::uint32_t>(mesh->vertices_m.size());
  for (const auto& v : floor->vertices_m) {
    mesh->vertices_m.emplace_back(100.0 * v.x() - 50.0, 100.0 * v.y() - 50.0, -0.5);
  }
  for (const auto& t : floor->triangles) mesh->triangles.push_back({first + t[0], first + t[1], first + t[2]});
  const MeshBvh bvh(mesh);
  const Eigen::AlignedBox3d on_floor(Eigen::Vector3d(40.2, 40.2, -0.501), Eigen::Vector3d(40.201, 40.201, -0.499));
  const auto found = query(bvh, on_floor);
  const auto truth = brute_force(*mesh, on_floor);
  EXPECT_TRUE(std::includes(found.begin(), found.end(), truth.begin(), truth.end()));
  EXPECT_LE(found.size(), 8u);
  const Eigen::AlignedBox3d near(Eigen::Vector3d(0.1003, 0.1003, -0.0005), Eigen::Vector3d(0.1013, 0.1013, 0.0005));
  EXPECT_LE(query(bvh, near).size(), 256u);
}

}  // namespace far_triangle

}  // namespace
}  // namespace mhd
