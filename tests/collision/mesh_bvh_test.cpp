#include "collision/mesh_bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
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

TEST(MeshBvh, RejectsATreeOfAnotherMesh) {
  const MeshBvh big(grid_mesh(30));
  const auto bytes = big.serialize_bvh();
  EXPECT_EQ(MeshBvh::from_serialized(grid_mesh(5), bytes), nullptr);
  EXPECT_EQ(MeshBvh::from_serialized(grid_mesh(5), std::span<const std::byte>()), nullptr);
}

}  // namespace
}  // namespace mhd
