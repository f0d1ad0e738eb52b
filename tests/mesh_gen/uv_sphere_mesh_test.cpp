#include "mesh_gen/uv_sphere_mesh.h"

#include "mesh_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace mhd::mesh_gen {
namespace {

TEST(MeshGenUvSphere, OneMillionIsExactlyTheBenchmarkLayout) {
  const UvSphereLayout layout = uv_sphere_layout(1'000'000);
  EXPECT_EQ(layout.bands, 501);
  EXPECT_EQ(layout.segments, 1000);
  EXPECT_EQ(layout.triangle_count(), 1'000'000u);
}

TEST(MeshGenUvSphere, LayoutMeetsTargets) {
  for (std::size_t target : {100u, 3'000u, 100'000u, 5'000'000u}) {
    EXPECT_NEAR(static_cast<double>(uv_sphere_layout(target).triangle_count()) / static_cast<double>(target), 1.0,
                0.05)
        << target;
  }
}

TEST(MeshGenUvSphere, IsClosedOutwardAndRound) {
  const double radius_m = 0.1;
  const TriangleMesh mesh = make_uv_sphere(radius_m, uv_sphere_layout(20'000));
  EXPECT_EQ(mesh.triangle_count(), uv_sphere_layout(20'000).triangle_count());
  const test::EdgeStats edges = test::edge_stats(mesh);
  EXPECT_EQ(edges.manifold_oriented, edges.edges);
  EXPECT_EQ(test::euler_characteristic(mesh), 2);
  const double ball = 4.0 / 3.0 * std::numbers::pi * radius_m * radius_m * radius_m;
  EXPECT_NEAR(test::enclosed_volume(mesh) / ball, 1.0, 0.01);
  for (const auto& v : mesh.vertices_m) ASSERT_NEAR(v.norm(), radius_m, 1e-12);
  EXPECT_NEAR(test::winding_number(mesh, Eigen::Vector3d(0.01, 0.02, -0.03)), 1.0, 1e-9);
  EXPECT_NEAR(test::winding_number(mesh, Eigen::Vector3d(0.2, 0.0, 0.0)), 0.0, 1e-9);
  EXPECT_GT(test::min_triangle_area(mesh), 0.0);
}

TEST(MeshGenUvSphere, RejectsBadArguments) {
  EXPECT_THROW((void)make_uv_sphere(0.0, {4, 8}), std::invalid_argument);
  EXPECT_THROW((void)make_uv_sphere(1.0, {1, 8}), std::invalid_argument);
}

}  // namespace
}  // namespace mhd::mesh_gen
