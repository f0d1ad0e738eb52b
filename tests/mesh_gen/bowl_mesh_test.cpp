#include "mesh_gen/bowl_mesh.h"

#include "mesh_checks.h"

#include <gtest/gtest.h>

#include <numbers>

namespace mhd::mesh_gen {
namespace {

constexpr double kHalfPi = 0.5 * std::numbers::pi;

TEST(MeshGenBowl, LayoutMeetsTargets) {
  for (std::size_t target : {500u, 4'000u, 100'000u}) {
    EXPECT_NEAR(static_cast<double>(bowl_layout(target, kHalfPi).triangle_count()) / static_cast<double>(target), 1.0,
                0.05)
        << target;
  }
}

TEST(MeshGenBowl, IsAnOpenSingleLayerDisc) {
  const BowlLayout layout = bowl_layout(4'000, kHalfPi);
  const TriangleMesh mesh = make_bowl(0.15, kHalfPi, layout);
  EXPECT_EQ(mesh.triangle_count(), layout.triangle_count());
  const test::EdgeStats edges = test::edge_stats(mesh);
  EXPECT_EQ(edges.bad, 0u);
  EXPECT_EQ(edges.boundary, static_cast<std::size_t>(layout.segments));  // the rim
  EXPECT_EQ(edges.boundary + edges.manifold_oriented, edges.edges);
  EXPECT_EQ(test::euler_characteristic(mesh), 1);  // a disc
  EXPECT_EQ(test::count_self_intersections(mesh), 0u);
  EXPECT_GT(test::min_triangle_area(mesh), 0.0);
}

TEST(MeshGenBowl, HemisphereOpensUpwardAndFacesAwayFromItsCentre) {
  const double radius = 0.15;
  const TriangleMesh mesh = make_bowl(radius, kHalfPi, bowl_layout(2'000, kHalfPi));
  const Eigen::AlignedBox3d box = mesh_bounds(mesh);
  EXPECT_NEAR(box.min().y(), -radius, 1e-12);
  EXPECT_NEAR(box.max().y(), 0.0, 1e-12);
  EXPECT_NEAR(box.sizes().x(), 2.0 * radius, 1e-3);
  for (const auto& v : mesh.vertices_m) ASSERT_NEAR(v.norm(), radius, 1e-12);
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices_m[t[0]];
    const Eigen::Vector3d n = (mesh.vertices_m[t[1]] - a).cross(mesh.vertices_m[t[2]] - a);
    const Eigen::Vector3d centroid = (a + mesh.vertices_m[t[1]] + mesh.vertices_m[t[2]]) / 3.0;
    ASSERT_GT(n.dot(centroid), 0.0);
  }
}

TEST(MeshGenBowl, RejectsBadArguments) {
  EXPECT_THROW((void)make_bowl(0.1, 0.0, {4, 8}), std::invalid_argument);
  EXPECT_THROW((void)make_bowl(-0.1, kHalfPi, {4, 8}), std::invalid_argument);
  EXPECT_THROW((void)make_bowl(0.1, kHalfPi, {4, 2}), std::invalid_argument);
}

}  // namespace
}  // namespace mhd::mesh_gen
