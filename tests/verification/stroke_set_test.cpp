#include "verification/stroke_set.h"
#include "verification/surface_crossing_oracle.h"
#include "test_meshes.h"

using namespace mhd::test;  // hand-made meshes

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace mhd::verify {
namespace {

using Eigen::Vector3d;

constexpr double kTol = 1e-12;

// Every step between samples is at most speed / rate, and exactly that except where
// a step cuts one of the polyline's interior corners or ends the path.
void expect_speed(const std::vector<Vector3d>& p_W_hip, double speed_m_per_s, double rate_Hz,
                  std::size_t corner_count) {
  const double step = speed_m_per_s / rate_Hz;
  ASSERT_GE(p_W_hip.size(), 2U);
  std::size_t short_steps = 0;
  for (std::size_t k = 1; k < p_W_hip.size(); ++k) {
    const double d = (p_W_hip[k] - p_W_hip[k - 1]).norm();
    ASSERT_LE(d, step * (1.0 + 1e-9)) << "step " << k;
    if (std::abs(d - step) > 1e-9 * step) ++short_steps;
  }
  EXPECT_LE(short_steps, corner_count - 1);
}

TEST(SamplePolyline, ConstantSpeedAlongCorners) {
  const std::vector<Vector3d> corners{{0, 0, 0}, {0.010, 0, 0}, {0.010, 0.0025, 0}};
  const std::vector<Vector3d> s = sample_polyline(corners, 1.0, 1000.0);  // 1 mm per tick
  ASSERT_EQ(s.size(), 14U);  // 0..12 mm, then the end corner at 12.5 mm
  EXPECT_EQ(s.front(), corners.front());
  EXPECT_EQ(s.back(), corners.back());
  EXPECT_NEAR((s[10] - corners[1]).norm(), 0.0, kTol);
  EXPECT_NEAR((s[12] - Vector3d(0.010, 0.002, 0)).norm(), 0.0, kTol);
  expect_speed(s, 1.0, 1000.0, corners.size());
  EXPECT_THROW((void)sample_polyline(corners, 0.0, 1000.0), std::invalid_argument);
  EXPECT_EQ(sample_polyline(std::vector<Vector3d>{{1, 2, 3}}, 1.0, 1000.0).size(), 1U);
}

TEST(SurfaceSampler, AreaWeighted) {
  // Box 0.4 x 0.2 x 0.1: faces +-z have area 0.08, +-y 0.04, +-x 0.02.
  const SurfaceCrossingOracle box(make_test_box({0, 0, 0}, {0.4, 0.2, 0.1}));
  const SurfaceSampler sampler(box);
  std::mt19937_64 rng(7);
  int z_faces = 0, y_faces = 0, x_faces = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const SurfaceSample s = sampler.sample(rng);
    const auto& [a, b, c] = box.triangle_W(s.oracle_triangle);
    // On the triangle, with its face normal.
    EXPECT_NEAR(s.normal_W.dot(s.point_W - a), 0.0, kTol);
    EXPECT_NEAR(s.normal_W.norm(), 1.0, kTol);
    const Vector3d nn = (b - a).cross(c - a);
    EXPECT_GE((b - a).cross(s.point_W - a).dot(nn), -kTol);
    EXPECT_GE((c - b).cross(s.point_W - b).dot(nn), -kTol);
    EXPECT_GE((a - c).cross(s.point_W - c).dot(nn), -kTol);
    if (std::abs(s.normal_W.z()) > 0.5) ++z_faces;
    if (std::abs(s.normal_W.y()) > 0.5) ++y_faces;
    if (std::abs(s.normal_W.x()) > 0.5) ++x_faces;
  }
  // Expected 4/7, 2/7, 1/7; 5 sigma bounds are ~1.7 %.
  EXPECT_NEAR(z_faces / double(n), 4.0 / 7.0, 0.02);
  EXPECT_NEAR(y_faces / double(n), 2.0 / 7.0, 0.02);
  EXPECT_NEAR(x_faces / double(n), 1.0 / 7.0, 0.02);
}

TEST(AnchorStrokes, FollowTheProtocol) {
  const SurfaceCrossingOracle box(make_test_box({-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1}));
  const AnchorStrokeParams params;  // 0.5 m/s, 1 kHz, 20 / 5 / 50 mm
  const StrokeSet set = make_anchor_strokes(box, 42, 200, params);
  ASSERT_EQ(set.strokes.size(), 200U);
  EXPECT_EQ(set.rejected, 0U);  // a convex box: every start is free
  for (std::size_t i = 0; i < set.strokes.size(); ++i) {
    SCOPED_TRACE("stroke " + std::to_string(i));
    const Stroke& s = set.strokes[i];
    const Vector3d& n = s.anchor.normal_W;
    const Vector3d& p = s.anchor.point_W;
    ASSERT_EQ(s.corners_W.size(), 4U);
    const Vector3d& start = s.corners_W[0];
    // Start: 20 mm outside along the normal, in free space, 20 mm from the box.
    EXPECT_NEAR((start - p).dot(n), 0.020, kTol);
    EXPECT_NEAR((start - p - 0.020 * n).norm(), 0.0, kTol);
    EXPECT_FALSE(box.point_inside_closed_mesh(start));
    EXPECT_NEAR(box.distance_to_surface(start), 0.020, 1e-9);
    // The approach meets the surface first at the anchor, 20 mm in.
    const std::optional<OracleHit> first = box.first_touched_triangle(start, s.corners_W[1]);
    ASSERT_TRUE(first.has_value());
    EXPECT_NEAR(first->t, 0.8, 1e-9);
    // Depth 5 mm along the start normal at both ends of the slide.
    EXPECT_NEAR((s.corners_W[1] - p).dot(n), -0.005, kTol);
    EXPECT_NEAR((s.corners_W[2] - p).dot(n), -0.005, kTol);
    EXPECT_TRUE(box.point_inside_closed_mesh(s.corners_W[1]));
    // Slide: 50 mm, tangent.
    EXPECT_NEAR((s.corners_W[2] - s.corners_W[1]).norm(), 0.050, kTol);
    EXPECT_NEAR(s.direction_W.dot(n), 0.0, kTol);
    EXPECT_NEAR(s.direction_W.norm(), 1.0, kTol);
    // Retract to 20 mm outside along the normal.
    EXPECT_NEAR((s.corners_W[3] - s.corners_W[2] - 0.025 * n).norm(), 0.0, kTol);
    // Samples: start to end at 0.5 mm per tick over 100 mm.
    EXPECT_EQ(s.p_W_hip.front(), start);
    EXPECT_EQ(s.p_W_hip.back(), s.corners_W[3]);
    EXPECT_EQ(s.p_W_hip.size(), 201U);
    EXPECT_EQ(s.speed_m_per_s, 0.5);
    expect_speed(s.p_W_hip, 0.5, 1000.0, s.corners_W.size());
  }
}

TEST(AnchorStrokes, DeterministicForASeed) {
  const SurfaceCrossingOracle box(make_test_box({-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1}));
  const StrokeSet a = make_anchor_strokes(box, 3, 20);
  const StrokeSet b = make_anchor_strokes(box, 3, 20);
  const StrokeSet c = make_anchor_strokes(box, 4, 20);
  ASSERT_EQ(a.strokes.size(), b.strokes.size());
  for (std::size_t i = 0; i < a.strokes.size(); ++i) {
    EXPECT_EQ(a.strokes[i].p_W_hip, b.strokes[i].p_W_hip);
    EXPECT_EQ(a.strokes[i].anchor.where, b.strokes[i].anchor.where);
  }
  EXPECT_NE(a.strokes[0].p_W_hip, c.strokes[0].p_W_hip);
}

TEST(AnchorStrokes, RejectStartsBehindOtherSurface) {
  // Two facing-up squares 10 mm apart: a start 20 mm above the lower one would have to
  // pass the upper one on its way in, so every stroke anchors on the upper square.
  const TriangleMesh lower = make_test_square(-0.2, 0.2, -0.2, 0.2, 0.0);
  const TriangleMesh upper = make_test_square(-0.2, 0.2, -0.2, 0.2, 0.010);
  const PlacedMesh meshes[] = {{&lower, Pose::Identity()}, {&upper, Pose::Identity()}};
  const SurfaceCrossingOracle oracle(meshes);
  const StrokeSet set = make_anchor_strokes(oracle, 11, 50);
  ASSERT_EQ(set.strokes.size(), 50U);
  EXPECT_GT(set.rejected, 20U);  // about half of the draws land on the lower square
  for (const Stroke& s : set.strokes) EXPECT_EQ(s.anchor.where.object, 1);
}

TEST(AnchorStrokes, RejectStartsTooCloseToOtherSurface) {
  // A floor and a wall standing on it at x = 0: starts above the floor within the
  // clearance of the wall (and starts beside the wall within it of the floor) are drawn
  // again.
  const TriangleMesh floor = make_test_square(-0.2, 0.2, -0.2, 0.2, 0.0);
  TriangleMesh wall;
  wall.vertices_m = {{0, -0.2, 0.001}, {0, 0.2, 0.001}, {0, 0.2, 0.1}, {0, -0.2, 0.1}};
  wall.triangles = {{0, 1, 2}, {0, 2, 3}};
  const PlacedMesh meshes[] = {{&floor, Pose::Identity()}, {&wall, Pose::Identity()}};
  const SurfaceCrossingOracle oracle(meshes);
  AnchorStrokeParams params;
  params.min_start_clearance_m = 0.015;
  const StrokeSet set = make_anchor_strokes(oracle, 5, 100, params);
  ASSERT_EQ(set.strokes.size(), 100U);
  EXPECT_GT(set.rejected, 0U);
  for (const Stroke& s : set.strokes) {
    EXPECT_GE(oracle.distance_to_surface(s.corners_W[0]), 0.015);
    EXPECT_FALSE(oracle.segment_touches_surface(s.corners_W[0], s.anchor.point_W + 1e-9 * s.anchor.normal_W));
  }
}

TEST(AnchorStrokes, ThrowsWhenNoStartIsFree) {
  // A closed box and, in the same place, its twin wound inside out (a room, solid beyond
  // its walls): a start out along the box's face normal is in the room's solid, and one
  // in along the room's face normal is in the box.
  const TriangleMesh box = make_test_box({-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1});
  TriangleMesh inverted = box;
  for (TriangleIndices& t : inverted.triangles) std::swap(t[1], t[2]);
  const PlacedMesh both[] = {{&box, Pose::Identity()}, {&inverted, Pose::Identity()}};
  const SurfaceCrossingOracle oracle(both);
  AnchorStrokeParams params;
  params.max_attempts_per_stroke = 50;
  EXPECT_THROW((void)make_anchor_strokes(oracle, 1, 1, params), std::runtime_error);
  EXPECT_THROW((void)SurfaceSampler(SurfaceCrossingOracle(std::span<const PlacedMesh>{})), std::runtime_error);
}

TEST(FastStrokes, StartFreeAndPassThrough) {
  const SurfaceCrossingOracle box(make_test_box({-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1}));
  FastStrokeParams params;
  params.max_speed_m_per_s = 1.0;
  const StrokeSet set = make_fast_strokes(box, 9, 300, params);
  ASSERT_EQ(set.strokes.size(), 300U);
  double slowest = 1e9, fastest = 0.0, shallowest = 1e9;
  for (std::size_t i = 0; i < set.strokes.size(); ++i) {
    SCOPED_TRACE("stroke " + std::to_string(i));
    const Stroke& s = set.strokes[i];
    ASSERT_EQ(s.corners_W.size(), 3U);
    EXPECT_EQ(s.corners_W[0], s.corners_W[2]);
    const Vector3d& start = s.corners_W[0];
    EXPECT_FALSE(box.point_inside_closed_mesh(start));
    EXPECT_GE(box.distance_to_surface(start), params.min_start_clearance_m);
    // The first surface on the way in is the anchor (near an edge a grazing path may
    // leave the box again before its deepest point).
    const std::optional<OracleHit> first = box.first_touched_triangle(start, s.corners_W[1]);
    ASSERT_TRUE(first.has_value());
    EXPECT_NEAR((start + first->t * (s.corners_W[1] - start) - s.anchor.point_W).norm(), 0.0, 1e-9);
    // The path goes into the surface at the drawn grazing angle.
    EXPECT_NEAR(std::asin(-s.direction_W.dot(s.anchor.normal_W)), s.grazing_angle_rad, 1e-9);
    EXPECT_GE(s.grazing_angle_rad, params.min_grazing_angle_rad);
    EXPECT_LE(s.grazing_angle_rad, params.max_grazing_angle_rad);
    EXPECT_GE(s.speed_m_per_s, params.min_speed_m_per_s);
    EXPECT_LE(s.speed_m_per_s, params.max_speed_m_per_s);
    expect_speed(s.p_W_hip, s.speed_m_per_s, params.rate_Hz, s.corners_W.size());
    slowest = std::min(slowest, s.speed_m_per_s);
    fastest = std::max(fastest, s.speed_m_per_s);
    shallowest = std::min(shallowest, s.grazing_angle_rad);
  }
  EXPECT_GT(fastest, 0.9);
  EXPECT_LT(slowest, 0.2);
  EXPECT_LT(shallowest, 0.05);
}

}  // namespace
}  // namespace mhd::verify
