#include "mesh_gen/range_scan.h"

#include "mesh_gen/bowl_mesh.h"
#include "mesh_gen/scan_source.h"
#include "mesh_gen/uv_sphere_mesh.h"

#include "mesh_checks.h"
#include "open_mesh_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace mhd::mesh_gen {
namespace {

constexpr double kQuarterTurn = 0.5 * std::numbers::pi;

TriangleMesh small_bowl() { return make_bowl(0.15, kQuarterTurn, bowl_layout(600, kQuarterTurn)); }

// A 100 mm sphere with a 30 mm one 200 mm in front of it (+z): seen along -z the small
// one covers part of the large one, a depth jump of ~0.2 m all around its outline.
TriangleMesh sphere_in_front_of_sphere() {
  TriangleMesh mesh = make_uv_sphere(0.10, uv_sphere_layout(800));
  const TriangleMesh front = make_uv_sphere(0.03, uv_sphere_layout(400));
  const auto offset = static_cast<std::uint32_t>(mesh.vertices_m.size());
  for (const auto& v : front.vertices_m) mesh.vertices_m.push_back(v + Eigen::Vector3d(0.0, 0.0, 0.2));
  for (const auto& t : front.triangles) mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return mesh;
}

RangeScanParams params(double azimuth_deg, double elevation_deg, int grid, double jump_cells) {
  RangeScanParams p;
  p.azimuth_deg = azimuth_deg;
  p.elevation_deg = elevation_deg;
  p.columns = grid;
  p.rows = grid;
  p.max_depth_jump_cells = jump_cells;
  return p;
}

double depth_range_m(const RangeScan& scan, const TriangleIndices& t) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (auto v : t) {
    const double depth = -scan.mesh.vertices_m[v].dot(scan.to_scanner_O);
    lo = std::min(lo, depth);
    hi = std::max(hi, depth);
  }
  return hi - lo;
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no exception)";
}

TEST(MeshGenRangeScan, SphereScanIsOneOpenPatchFacingTheScanner) {
  const TriangleMesh source = make_uv_sphere(0.1, uv_sphere_layout(2'000));
  const RangeScan scan = make_range_scan(source, params(20.0, 10.0, 40, 4.0));
  ASSERT_GT(scan.mesh.triangle_count(), 1'000u);
  const test::EdgeStats edges = test::edge_stats(scan.mesh);
  EXPECT_GT(edges.boundary, 0u);  // open: only the visible half, trimmed at grazing angles
  EXPECT_EQ(edges.bad, 0u);
  EXPECT_EQ(test::connected_components(scan.mesh), 1u);
  EXPECT_EQ(scan.stats.patches, 1u);
  EXPECT_EQ(scan.stats.dropped_degenerate, 0u);
  EXPECT_GT(test::min_triangle_area(scan.mesh), 0.0);
  EXPECT_TRUE(scan.to_scanner_O.isApprox(scan_direction(20.0, 10.0)));
  for (const auto& t : scan.mesh.triangles) {
    const Eigen::Vector3d& a = scan.mesh.vertices_m[t[0]];
    const Eigen::Vector3d n = (scan.mesh.vertices_m[t[1]] - a).cross(scan.mesh.vertices_m[t[2]] - a);
    ASSERT_GT(n.dot(scan.to_scanner_O), 0.0);  // counter-clockwise seen from the scanner
    ASSERT_GT(a.dot(scan.to_scanner_O), 0.0);  // the near half only
  }
}

TEST(MeshGenRangeScan, DepthJumpCutsTheScanIntoPatches) {
  const TriangleMesh source = sphere_in_front_of_sphere();
  const RangeScan cut = make_range_scan(source, params(0.0, 0.0, 60, 3.0));
  // The small sphere's disc, and the large sphere with a hole where the disc hides it.
  EXPECT_GE(test::connected_components(cut.mesh), 2u);
  EXPECT_EQ(cut.stats.patches, test::connected_components(cut.mesh));
  EXPECT_GT(cut.stats.dropped_depth_jump, 0u);
  EXPECT_GT(test::edge_stats(cut.mesh).boundary, 0u);
  const double max_jump_m = 3.0 * cut.stats.spacing_m;
  for (const auto& t : cut.mesh.triangles) ASSERT_LE(depth_range_m(cut, t), max_jump_m + 1e-12);

  // Without a threshold the same samples bridge the jump: one piece.
  const RangeScan bridged = make_range_scan(source, params(0.0, 0.0, 60, 1e9));
  EXPECT_EQ(test::connected_components(bridged.mesh), 1u);
  EXPECT_GT(bridged.mesh.triangle_count(), cut.mesh.triangle_count());
}

TEST(MeshGenRangeScan, VerticesLieOnTheSourceAndNoiseStaysWithinItsBound) {
  const TriangleMesh source = small_bowl();
  RangeScanParams p = params(30.0, 40.0, 30, 3.0);
  const RangeScan exact = make_range_scan(source, p);
  ASSERT_GT(exact.mesh.triangle_count(), 500u);
  for (const auto& v : exact.mesh.vertices_m) ASSERT_LT(test::distance_to_mesh(source, v), 1e-9);

  p.noise_m = 0.0002;
  p.seed = 7;
  const RangeScan noisy = make_range_scan(source, p);
  ASSERT_EQ(noisy.mesh.vertices_m.size(), exact.mesh.vertices_m.size());
  double largest_m = 0.0;
  for (std::size_t k = 0; k < noisy.mesh.vertices_m.size(); ++k) {
    const Eigen::Vector3d moved = noisy.mesh.vertices_m[k] - exact.mesh.vertices_m[k];
    ASSERT_LE(moved.norm(), 0.0002 + 1e-12);
    ASSERT_LT(moved.cross(noisy.to_scanner_O).norm(), 1e-12);  // along the ray only
    largest_m = std::max(largest_m, moved.norm());
  }
  EXPECT_GT(largest_m, 0.0001);
  for (const auto& t : noisy.mesh.triangles) ASSERT_LE(depth_range_m(noisy, t), 3.0 * noisy.stats.spacing_m + 1e-12);
}

TEST(MeshGenRangeScan, BowlSeenObliquelyIsCutAtItsRim) {
  const RangeScan scan = make_range_scan(small_bowl(), params(30.0, 40.0, 60, 3.0));
  EXPECT_GT(scan.stats.dropped_depth_jump, 0u);  // the near rim hides the far inside wall
  EXPECT_GT(test::edge_stats(scan.mesh).boundary, 0u);
  EXPECT_EQ(test::edge_stats(scan.mesh).bad, 0u);
}

TEST(MeshGenRangeScan, IsDeterministic) {
  const TriangleMesh source = small_bowl();
  RangeScanParams p = params(-45.0, 30.0, 25, 2.5);
  p.noise_m = 0.0001;
  p.seed = 3;
  const RangeScan a = make_range_scan(source, p);
  const RangeScan b = make_range_scan(source, p);
  EXPECT_EQ(a.mesh.vertices_m, b.mesh.vertices_m);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  p.seed = 4;
  const RangeScan c = make_range_scan(source, p);
  EXPECT_NE(a.mesh.vertices_m, c.mesh.vertices_m);
}

TEST(MeshGenRangeScan, RejectsBadArguments) {
  const TriangleMesh source = small_bowl();
  const auto scan_with = [&](const RangeScanParams& p) { return [&source, p] { (void)make_range_scan(source, p); }; };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();

  EXPECT_EQ(message_of(scan_with(params(0, 0, 0, 3))), "range scan: the grid needs at least 2 x 2 samples (got 0 x 0)");
  RangeScanParams one_row = params(0, 0, 30, 3);
  one_row.rows = 1;
  EXPECT_THROW(scan_with(one_row)(), std::invalid_argument);
  EXPECT_EQ(message_of(scan_with(params(nan, 0, 30, 3))),
            "range scan: the view needs a finite azimuth and an elevation in [-90, 90] degrees (got nan, 0)");
  EXPECT_THROW(scan_with(params(0, inf, 30, 3))(), std::invalid_argument);
  EXPECT_THROW(scan_with(params(0, 91, 30, 3))(), std::invalid_argument);
  EXPECT_THROW(scan_with(params(0, 0, 30, -1))(), std::invalid_argument);
  EXPECT_THROW(scan_with(params(0, 0, 30, nan))(), std::invalid_argument);
  RangeScanParams loud = params(0, 0, 30, 3);
  loud.noise_m = 0.001;
  EXPECT_EQ(message_of(scan_with(loud)), "range scan: the noise must be in [0, 1) mm (got 1 mm)");
  EXPECT_EQ(message_of([] { (void)make_range_scan(TriangleMesh{}, RangeScanParams{}); }),
            "range scan: the source mesh has no triangles");
}

TEST(MeshGenScanSource, GeneratorsAndBadSources) {
  ScanSourceOptions options;
  options.generator_triangles = 1'000;
  const TriangleMesh bowl = load_scan_source("bowl", options);
  EXPECT_NEAR(static_cast<double>(bowl.triangle_count()), 1'000.0, 50.0);
  EXPECT_NEAR(mesh_bounds(bowl).sizes().x(), 0.30, 1e-3);

  EXPECT_EQ(message_of([&] { (void)load_scan_source("teapot", options); }),
            "unknown scan source 'teapot' (expected dolphin, bowl, uv-sphere or a mesh file path)");
  EXPECT_THROW((void)load_scan_source("no_such_dir/no_such.obj", options), std::runtime_error);
  EXPECT_NE(message_of([&] { (void)load_scan_source("no_such_dir/no_such.obj", options); }).find("file not found"),
            std::string::npos);
  ScanSourceOptions with_unit = options;
  with_unit.file_unit_m = 0.15;
  EXPECT_THROW((void)load_scan_source("dolphin", with_unit), std::invalid_argument);
  options.generator_triangles = 10;
  EXPECT_THROW((void)load_scan_source("uv-sphere", options), std::invalid_argument);
}

}  // namespace
}  // namespace mhd::mesh_gen
