// The committed meshes in assets/ and, once built, the generated ones in
// assets/generated/: readable, the right size and shape, closed where they should be.

#include "mesh_gen/dolphin_shape.h"

#include "mesh_checks.h"
#include "mesh_file.h"
#include "open_mesh_checks.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

namespace mhd::mesh_gen {
namespace {

const std::filesystem::path kAssets = std::filesystem::path(MHD_SOURCE_DIR) / "assets";
constexpr double kMm = 0.001;

void expect_closed_dolphin(const TriangleMesh& mesh, std::size_t target) {
  EXPECT_NEAR(static_cast<double>(mesh.triangle_count()) / static_cast<double>(target), 1.0, 0.10);
  const test::EdgeStats edges = test::edge_stats(mesh);
  EXPECT_EQ(edges.manifold_oriented, edges.edges);
  EXPECT_EQ(test::euler_characteristic(mesh), 2);
  EXPECT_GT(test::enclosed_volume(mesh), 0.0);
  EXPECT_NEAR(mesh_bounds(mesh).sizes().x(), 2.0, 0.01);
}

TEST(MeshGenAssets, DefaultDolphinIsTheSmallClosedOne) {
  const std::filesystem::path file = kAssets / "dolphin.ply";
  ASSERT_TRUE(std::filesystem::exists(file));
  EXPECT_LT(std::filesystem::file_size(file), 100'000u);
  const TriangleMesh mesh = test::read_mesh_file(file, kMm);
  expect_closed_dolphin(mesh, 3'000);
  EXPECT_GT(test::min_triangle_area(mesh), 0.0);
  const DolphinShape shape;
  const DolphinLandmarks& lm = shape.landmarks();
  EXPECT_NEAR(test::winding_number(mesh, lm.p_dorsal_fin_m), 1.0, 1e-6);
  EXPECT_NEAR(test::winding_number(mesh, lm.p_fluke_notch_m), 0.0, 1e-6);
}

TEST(MeshGenAssets, BowlIsAnOpenShell) {
  const TriangleMesh mesh = test::read_mesh_file(kAssets / "bowl.ply", kMm);
  EXPECT_GT(mesh.triangle_count(), 2'000u);
  EXPECT_LT(mesh.triangle_count(), 10'000u);
  const test::EdgeStats edges = test::edge_stats(mesh);
  EXPECT_GT(edges.boundary, 0u);
  EXPECT_EQ(edges.bad, 0u);
  EXPECT_EQ(test::euler_characteristic(mesh), 1);
}

TEST(MeshGenAssets, GeneratedMeshesOnceBuilt) {
  const std::filesystem::path generated = kAssets / "generated";
  const std::filesystem::path d100k = generated / "dolphin_100k.ply";
  const std::filesystem::path d1m = generated / "dolphin_1m.ply";
  const std::filesystem::path s1m = generated / "uv_sphere_1m.ply";
  if (!std::filesystem::exists(d100k) || !std::filesystem::exists(d1m) || !std::filesystem::exists(s1m)) {
    GTEST_SKIP() << "assets/generated/ not built yet (target mhd_generated_meshes)";
  }
  expect_closed_dolphin(test::read_mesh_file(d100k, kMm), 100'000);
  expect_closed_dolphin(test::read_mesh_file(d1m, kMm), 1'000'000);
  const TriangleMesh sphere = test::read_mesh_file(s1m, kMm);
  EXPECT_EQ(sphere.triangle_count(), 1'000'000u);
  EXPECT_NEAR(mesh_bounds(sphere).sizes().x(), 0.2, 1e-4);
  const test::EdgeStats edges = test::edge_stats(sphere);
  EXPECT_EQ(edges.manifold_oriented, edges.edges);
}

// The open range scans: over 200k triangles, open, in several pieces, and
// the size of what was scanned.
TEST(MeshGenAssets, GeneratedRangeScansOnceBuilt) {
  struct Scan {
    const char* file;
    double width_x_m;  // of the source, seen whole in x from these views
  };
  for (const Scan& scan : {Scan{"scan_dolphin.ply", 2.0}, Scan{"scan_bunny.ply", 0.29}, Scan{"scan_bowl.ply", 0.30}}) {
    const std::filesystem::path file = kAssets / "generated" / scan.file;
    if (!std::filesystem::exists(file)) {
      std::printf("%s not built yet (target mhd_generated_meshes), skipped\n", scan.file);
      continue;
    }
    const TriangleMesh mesh = test::read_mesh_file(file, kMm);
    EXPECT_GE(mesh.triangle_count(), 200'000u) << scan.file;
    const test::EdgeStats edges = test::edge_stats(mesh);
    EXPECT_GT(edges.boundary, 1'000u) << scan.file;
    EXPECT_EQ(edges.boundary + edges.manifold_oriented, edges.edges) << scan.file;
    EXPECT_GT(test::connected_components(mesh), 3u) << scan.file;
    EXPECT_NEAR(mesh_bounds(mesh).sizes().x(), scan.width_x_m, 0.02 * scan.width_x_m) << scan.file;
  }
}

}  // namespace
}  // namespace mhd::mesh_gen
