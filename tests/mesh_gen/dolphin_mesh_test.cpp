#include "mesh_gen/dolphin_mesh.h"
#include "mesh_gen/dolphin_shape.h"

#include "mesh_checks.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mhd::mesh_gen {
namespace {

using test::count_self_intersections;
using test::edge_stats;
using test::winding_number;

void expect_closed_genus_zero(const TriangleMesh& mesh) {
  const test::EdgeStats edges = edge_stats(mesh);
  EXPECT_EQ(edges.boundary, 0u);
  EXPECT_EQ(edges.bad, 0u);
  EXPECT_EQ(edges.manifold_oriented, edges.edges);
  EXPECT_EQ(test::euler_characteristic(mesh), 2);
  EXPECT_GT(test::enclosed_volume(mesh), 0.0);
}

void expect_count_near(const TriangleMesh& mesh, std::size_t target) {
  const double ratio = static_cast<double>(mesh.triangle_count()) / static_cast<double>(target);
  EXPECT_NEAR(ratio, 1.0, 0.10) << mesh.triangle_count() << " triangles for a target of " << target;
}

void expect_no_degenerate_triangles(const TriangleMesh& mesh) {
  EXPECT_GT(test::min_triangle_area(mesh), 1e-12);   // m^2, i.e. 1e-6 mm^2
  EXPECT_GT(test::min_triangle_shape(mesh), 1e-4);   // no needle collapsed onto a line
  TriangleMesh copy = mesh;
  EXPECT_EQ(remove_invalid_triangles(copy), 0u);
}

void expect_dolphin_size(const TriangleMesh& mesh) {
  const Eigen::AlignedBox3d box = mesh_bounds(mesh);
  EXPECT_NEAR(box.sizes().x(), 2.0, 0.01);  // beak to fluke tips, metres
  EXPECT_GT(box.sizes().y(), 0.45);         // belly to dorsal fin tip
  EXPECT_LT(box.sizes().y(), 0.80);
  EXPECT_GT(box.sizes().z(), 0.45);         // fluke / pectoral span
  EXPECT_LT(box.sizes().z(), 0.80);
  EXPECT_NEAR(box.center().norm(), 0.0, 0.01);
}

void expect_landmarks_classified(const TriangleMesh& mesh) {
  const DolphinShape shape;
  const DolphinLandmarks& lm = shape.landmarks();
  EXPECT_NEAR(winding_number(mesh, lm.p_body_centre_m), 1.0, 1e-6);
  EXPECT_NEAR(winding_number(mesh, lm.p_dorsal_fin_m), 1.0, 1e-6);
  EXPECT_NEAR(winding_number(mesh, lm.p_pectoral_fin_m), 1.0, 1e-6);
  EXPECT_NEAR(winding_number(mesh, lm.p_fluke_lobe_m), 1.0, 1e-6);
  EXPECT_NEAR(winding_number(mesh, lm.p_fluke_notch_m), 0.0, 1e-6);
  EXPECT_NEAR(winding_number(mesh, lm.p_above_back_m), 0.0, 1e-6);
  EXPECT_NEAR(winding_number(mesh, Eigen::Vector3d(0.0, 0.0, 1.0)), 0.0, 1e-6);
  EXPECT_NEAR(winding_number(mesh, Eigen::Vector3d(1.5, 0.0, 0.0)), 0.0, 1e-6);
}

TEST(MeshGenDolphin, LandmarksSitWhereTheyClaim) {
  const DolphinShape shape;
  const DolphinLandmarks& lm = shape.landmarks();
  // Nose towards +x, fluke at -x, back up.
  EXPECT_NEAR(lm.p_beak_tip_m.x(), 1.0, 1e-3);
  EXPECT_LT(shape.tail().x(), -0.9);
  // The dorsal fin point is high above the body centre, on the mid-plane.
  EXPECT_GT(lm.p_dorsal_fin_m.y() - lm.p_body_centre_m.y(), 0.3);
  EXPECT_NEAR(lm.p_dorsal_fin_m.z(), 0.0, 1e-9);
  // The notch point lies on the mid-plane, behind the tail end but ahead of the lobe tips.
  EXPECT_NEAR(lm.p_fluke_notch_m.z(), 0.0, 1e-9);
  EXPECT_LT(lm.p_fluke_notch_m.x(), shape.tail().x());
  EXPECT_GT(lm.p_fluke_notch_m.x(), -1.0);
  // Pectoral fin and fluke lobe points are well off the mid-plane.
  EXPECT_GT(std::abs(lm.p_pectoral_fin_m.z()), 0.15);
  EXPECT_GT(std::abs(lm.p_fluke_lobe_m.z()), 0.1);
}

TEST(MeshGenDolphin, LayoutMeetsTargetsWithinTwoPercent) {
  for (std::size_t target : {3'000u, 10'000u, 100'000u, 1'000'000u, 3'000'000u}) {
    const DolphinLayout layout = dolphin_layout(target);
    EXPECT_NEAR(static_cast<double>(layout.triangle_count()) / static_cast<double>(target), 1.0, 0.02) << target;
    EXPECT_EQ(layout.ring_size % 4, 0);
  }
}

TEST(MeshGenDolphin, Dolphin3kIsClosedCleanAndLooksRight) {
  const TriangleMesh mesh = make_dolphin(dolphin_layout(3'000));
  expect_count_near(mesh, 3'000);
  expect_closed_genus_zero(mesh);
  expect_no_degenerate_triangles(mesh);
  expect_dolphin_size(mesh);
  expect_landmarks_classified(mesh);
  EXPECT_EQ(count_self_intersections(mesh), 0u);
}

TEST(MeshGenDolphin, Dolphin100kIsClosedCleanAndLooksRight) {
  const TriangleMesh mesh = make_dolphin(dolphin_layout(100'000));
  expect_count_near(mesh, 100'000);
  expect_closed_genus_zero(mesh);
  expect_no_degenerate_triangles(mesh);
  expect_dolphin_size(mesh);
  expect_landmarks_classified(mesh);
  EXPECT_EQ(count_self_intersections(mesh), 0u);
}

TEST(MeshGenDolphin, Dolphin1mIsClosedAndSurvivesFloatCoordinates) {
  const TriangleMesh mesh = make_dolphin(dolphin_layout(1'000'000));
  expect_count_near(mesh, 1'000'000);
  expect_closed_genus_zero(mesh);
  expect_no_degenerate_triangles(mesh);
  expect_dolphin_size(mesh);
  // Files store float millimetres: no triangle may collapse or flip when rounded so.
  TriangleMesh rounded = mesh;
  for (auto& v : rounded.vertices_m) {
    v = (v * 1000.0).cast<float>().cast<double>() / 1000.0;
  }
  std::size_t flipped = 0;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    auto normal = [&t](const TriangleMesh& m) {
      return Eigen::Vector3d((m.vertices_m[t[1]] - m.vertices_m[t[0]]).cross(m.vertices_m[t[2]] - m.vertices_m[t[0]]));
    };
    if (normal(mesh).dot(normal(rounded)) <= 0.0) ++flipped;
  }
  EXPECT_EQ(flipped, 0u);
  EXPECT_GT(test::min_triangle_area(rounded), 0.0);
}

TEST(MeshGenDolphin, IsDeterministic) {
  const TriangleMesh a = make_dolphin(dolphin_layout(5'000));
  const TriangleMesh b = make_dolphin(dolphin_layout(5'000));
  ASSERT_EQ(a.vertices_m.size(), b.vertices_m.size());
  ASSERT_EQ(a.triangles, b.triangles);
  for (std::size_t i = 0; i < a.vertices_m.size(); ++i) ASSERT_EQ(a.vertices_m[i], b.vertices_m[i]) << i;
}

TEST(MeshGenDolphin, IsMirrorSymmetricAcrossTheMidPlane) {
  const TriangleMesh mesh = make_dolphin(dolphin_layout(3'000));
  const Eigen::AlignedBox3d box = mesh_bounds(mesh);
  EXPECT_NEAR(box.min().z(), -box.max().z(), 1e-9);
  double sum_z = 0.0;
  for (const auto& v : mesh.vertices_m) sum_z += v.z();
  EXPECT_NEAR(sum_z / static_cast<double>(mesh.vertices_m.size()), 0.0, 1e-9);
}

TEST(MeshGenDolphin, RejectsBadLayouts) {
  EXPECT_THROW((void)make_dolphin({10, 30}), std::invalid_argument);
  EXPECT_THROW((void)make_dolphin({1, 32}), std::invalid_argument);
}

}  // namespace
}  // namespace mhd::mesh_gen
