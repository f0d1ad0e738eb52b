#include "verification/surface_crossing_oracle.h"
#include "test_meshes.h"

using namespace mhd::test;  // hand-made meshes

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>

namespace mhd::verify {
namespace {

using Eigen::Vector3d;

TriangleMesh one_triangle(const Vector3d& a, const Vector3d& b, const Vector3d& c) {
  TriangleMesh mesh;
  mesh.vertices_m = {a, b, c};
  mesh.triangles = {{0, 1, 2}};
  return mesh;
}

// Unit right triangle in z = 0 and its mirror across the diagonal x + y = 1.
TriangleMesh two_triangles_sharing_diagonal() {
  TriangleMesh mesh;
  mesh.vertices_m = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
  return mesh;
}

// Six triangles around the origin in z = 0.
TriangleMesh fan_around_origin() {
  TriangleMesh mesh;
  mesh.vertices_m.push_back(Vector3d::Zero());
  for (int i = 0; i < 6; ++i) {
    const double angle = std::numbers::pi / 3.0 * i;
    mesh.vertices_m.emplace_back(std::cos(angle), std::sin(angle), 0.0);
  }
  for (std::uint32_t i = 0; i < 6; ++i) mesh.triangles.push_back({0, 1 + i, 1 + (i + 1) % 6});
  return mesh;
}

TEST(SurfaceCrossingOracle, SegmentThroughTriangleInterior) {
  const SurfaceCrossingOracle oracle(one_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  EXPECT_TRUE(oracle.segment_touches_surface({0.25, 0.25, 1.0}, {0.25, 0.25, -1.0}));
  EXPECT_TRUE(oracle.segment_touches_surface({0.25, 0.25, -1.0}, {0.25, 0.25, 1.0}));
  EXPECT_FALSE(oracle.segment_touches_surface({0.25, 0.25, 1.0}, {0.25, 0.25, 0.5}));
  EXPECT_FALSE(oracle.segment_touches_surface({0.75, 0.75, 1.0}, {0.75, 0.75, -1.0}));

  const std::optional<OracleHit> hit = oracle.first_touched_triangle({0.25, 0.25, 1.0}, {0.25, 0.25, -1.0});
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->where, (TriangleRef{0, 0}));
  EXPECT_NEAR(hit->t, 0.5, 1e-15);
  EXPECT_FALSE(oracle.first_touched_triangle({0.75, 0.75, 1.0}, {0.75, 0.75, -1.0}).has_value());
}

TEST(SurfaceCrossingOracle, AFrontOnlyFaceIsCrossedOnlyFromTheFront) {
  // The triangle faces +z. Front only: a move down through it crosses, a move up does
  // not; one that starts on it and goes behind does, one that leaves it to the front
  // does not. Back only: the mirror. Both: every move that touches.
  const TriangleMesh mesh = one_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const Vector3d above(0.2, 0.2, 1), below(0.2, 0.2, -1), on(0.2, 0.2, 0);
  struct Case {
    TouchableFaces faces;
    bool down, up, on_to_below, on_to_above, along;
  };
  for (const Case& c : {Case{TouchableFaces::Both, true, true, true, true, true},
                        Case{TouchableFaces::Front, true, false, true, false, true},
                        Case{TouchableFaces::Back, false, true, false, true, true}}) {
    SCOPED_TRACE(std::string(touchable_faces_name(c.faces)));
    const PlacedMesh placed{&mesh, Pose::Identity(), c.faces};
    const SurfaceCrossingOracle oracle(std::span<const PlacedMesh>(&placed, 1));
    EXPECT_EQ(oracle.segment_touches_surface(above, below), c.down);
    EXPECT_EQ(oracle.segment_touches_surface(below, above), c.up);
    EXPECT_EQ(oracle.segment_touches_surface(on, below), c.on_to_below);
    EXPECT_EQ(oracle.segment_touches_surface(on, above), c.on_to_above);
    EXPECT_EQ(oracle.segment_touches_surface(on, Vector3d(0.1, 0.1, 0)), c.along);
    EXPECT_EQ(oracle.first_touched_triangle(above, below).has_value(), c.down);
    EXPECT_EQ(oracle.first_touched_triangle(below, above).has_value(), c.up);
    EXPECT_TRUE(oracle.point_touches_surface(on));  // a point on it touches either way
    // Whatever side is touchable: from above, a point below is behind the face.
    EXPECT_TRUE(oracle.segment_meets_a_front(above, below));
    EXPECT_FALSE(oracle.segment_meets_a_front(below, above));
    EXPECT_FALSE(oracle.segment_meets_a_front(on, below));
    EXPECT_FALSE(oracle.segment_meets_a_front(above, Vector3d(0.2, 0.2, 0.5)));
  }
}

TEST(SurfaceCrossingOracle, SegmentThroughSharedEdgeTouchesBoth) {
  const SurfaceCrossingOracle oracle(two_triangles_sharing_diagonal());
  const Vector3d a(0.5, 0.5, 1.0), b(0.5, 0.5, -1.0);  // (0.5, 0.5, 0) is on the diagonal
  EXPECT_TRUE(oracle.segment_touches_surface(a, b));
  const std::vector<OracleHit> hits = oracle.touched_triangles(a, b);
  ASSERT_EQ(hits.size(), 2U);
  EXPECT_EQ(hits[0].where, (TriangleRef{0, 0}));
  EXPECT_EQ(hits[1].where, (TriangleRef{0, 1}));
  EXPECT_NEAR(hits[0].t, 0.5, 1e-15);
  EXPECT_NEAR(hits[1].t, 0.5, 1e-15);
  // Ending exactly on the edge is touching.
  EXPECT_TRUE(oracle.segment_touches_surface(a, {0.5, 0.5, 0.0}));
}

TEST(SurfaceCrossingOracle, SegmentThroughSharedVertexTouchesWholeFan) {
  const SurfaceCrossingOracle oracle(fan_around_origin());
  const Vector3d a(0.0, 0.0, 1.0), b(0.0, 0.0, -1.0);
  EXPECT_TRUE(oracle.segment_touches_surface(a, b));
  EXPECT_EQ(oracle.touched_triangles(a, b).size(), 6U);
  // A slanted segment through the vertex, too.
  EXPECT_TRUE(oracle.segment_touches_surface({-0.3, 0.7, 2.0}, {0.3, -0.7, -2.0}));
  // The outer rim vertex (1, 0, 0) is shared by triangles 0 and 5.
  EXPECT_EQ(oracle.touched_triangles({1.0, 0.0, 1.0}, {1.0, 0.0, -1.0}).size(), 2U);
}

TEST(SurfaceCrossingOracle, SegmentInTrianglePlane) {
  const SurfaceCrossingOracle oracle(one_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  // Lying in the plane and overlapping the triangle.
  EXPECT_TRUE(oracle.segment_touches_surface({-1.0, 0.25, 0.0}, {2.0, 0.25, 0.0}));
  EXPECT_TRUE(oracle.segment_touches_surface({0.1, 0.1, 0.0}, {0.2, 0.2, 0.0}));  // inside entirely
  // In the plane, ending exactly on the edge x = 0.
  EXPECT_TRUE(oracle.segment_touches_surface({-1.0, 0.25, 0.0}, {0.0, 0.25, 0.0}));
  // Sliding along the edge y = 0.
  EXPECT_TRUE(oracle.segment_touches_surface({-1.0, 0.0, 0.0}, {2.0, 0.0, 0.0}));
  // In the plane, beside the triangle.
  EXPECT_FALSE(oracle.segment_touches_surface({-1.0, -0.1, 0.0}, {2.0, -0.1, 0.0}));
  EXPECT_FALSE(oracle.segment_touches_surface({-1.0, 0.25, 0.0}, {-1e-12, 0.25, 0.0}));
  // Parallel, a hair above.
  EXPECT_FALSE(oracle.segment_touches_surface({-1.0, 0.25, 1e-12}, {2.0, 0.25, 1e-12}));
  const std::optional<OracleHit> hit = oracle.first_touched_triangle({-1.0, 0.25, 0.0}, {2.0, 0.25, 0.0});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->t, 1.0 / 3.0, 1e-15);  // enters at x = 0
}

TEST(SurfaceCrossingOracle, NearMissBy1e12IsNoTouch) {
  const SurfaceCrossingOracle axis(one_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  // Stopping 1e-12 m short of the face.
  EXPECT_FALSE(axis.segment_touches_surface({0.25, 0.25, 1.0}, {0.25, 0.25, 1e-12}));
  EXPECT_TRUE(axis.segment_touches_surface({0.25, 0.25, 1.0}, {0.25, 0.25, -1e-12}));
  // Passing 1e-12 m beside the edge x = 0.
  EXPECT_FALSE(axis.segment_touches_surface({-1e-12, 0.25, 1.0}, {-1e-12, 0.25, -1.0}));
  EXPECT_TRUE(axis.segment_touches_surface({1e-12, 0.25, 1.0}, {1e-12, 0.25, -1.0}));
  // Passing 1e-12 m beside the vertex (1, 0, 0).
  EXPECT_FALSE(axis.segment_touches_surface({1.0 + 1e-12, 0.0, 1.0}, {1.0 + 1e-12, 0.0, -1.0}));

  // A triangle in general position (edges not representable exactly): 1e-12 m outside
  // its edge ab, in its plane, then a segment along the normal through that point.
  const Vector3d a(0.1, 0.2, 0.3), b(0.7, 0.1, 0.35), c(0.3, 0.8, 0.25);
  const SurfaceCrossingOracle general(one_triangle(a, b, c));
  const Vector3d n = (b - a).cross(c - a).normalized();
  const Vector3d out = (b - a).cross(n).normalized();  // in-plane, away from c
  ASSERT_LT(out.dot(c - a), 0.0);
  const Vector3d m = 0.5 * (a + b);
  EXPECT_FALSE(general.segment_touches_surface(m + 1e-12 * out + 0.1 * n, m + 1e-12 * out - 0.1 * n));
  EXPECT_TRUE(general.segment_touches_surface(m - 1e-12 * out + 0.1 * n, m - 1e-12 * out - 0.1 * n));
  // And 1e-12 m above the centroid, coming down along the normal.
  const Vector3d g = (a + b + c) / 3.0;
  EXPECT_FALSE(general.segment_touches_surface(g + 0.1 * n, g + 1e-12 * n));
  EXPECT_TRUE(general.segment_touches_surface(g + 0.1 * n, g - 1e-12 * n));
}

TEST(SurfaceCrossingOracle, TinyTriangles) {
  // Area 1e-10 m^2 (legs ~14 um), a metre from the origin, well below the 1e-13
  // cut-off that makes CHAI3D's point proxy leak.
  const double leg = std::sqrt(2e-10);
  const Vector3d a(0.7, -0.4, 1.0);
  const SurfaceCrossingOracle oracle(one_triangle(a, a + Vector3d(leg, 0, 0), a + Vector3d(0, leg, 0)));
  const Vector3d g = a + Vector3d(leg / 3.0, leg / 3.0, 0.0);
  EXPECT_TRUE(oracle.segment_touches_surface(g + Vector3d(0, 0, 0.01), g - Vector3d(0, 0, 0.01)));
  EXPECT_TRUE(oracle.segment_touches_surface(g + Vector3d(0.005, 0.003, 0.01), g - Vector3d(0.005, 0.003, 0.01)));
  EXPECT_FALSE(oracle.segment_touches_surface(g + Vector3d(leg, leg, 0.01), g + Vector3d(leg, leg, -0.01)));
  // Hundreds of tiny triangles in a row: a fast segment crossing the strip hits it.
  TriangleMesh strip;
  for (std::uint32_t i = 0; i < 500; ++i) {
    const Vector3d o(0.3 + leg * i, 0.2, -0.1);
    strip.vertices_m.insert(strip.vertices_m.end(), {o, o + Vector3d(leg, 0, 0), o + Vector3d(0, leg, 0)});
    strip.triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  const SurfaceCrossingOracle strip_oracle(strip);
  const Vector3d p = Vector3d(0.3 + leg * 250.25, 0.2 + leg * 0.25, -0.1);
  const std::optional<OracleHit> hit =
      strip_oracle.first_touched_triangle(p + Vector3d(0.3, 0.1, 0.5), p - Vector3d(0.3, 0.1, 0.5));
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->where.triangle, 250U);
}

TEST(SurfaceCrossingOracle, DegenerateTriangles) {
  TriangleMesh mesh;
  mesh.vertices_m = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {5, 5, 5}};
  mesh.triangles = {{0, 1, 2}, {3, 3, 3}, {0, 1, 7}};  // collinear, a point, an invalid index
  const SurfaceCrossingOracle oracle(mesh);
  EXPECT_EQ(oracle.triangle_count(), 2U);
  EXPECT_TRUE(oracle.segment_touches_surface({1.5, 0.0, 1.0}, {1.5, 0.0, -1.0}));
  EXPECT_FALSE(oracle.segment_touches_surface({1.5, 1e-12, 1.0}, {1.5, 1e-12, -1.0}));
  EXPECT_FALSE(oracle.segment_touches_surface({2.5, 0.0, 1.0}, {2.5, 0.0, -1.0}));
  EXPECT_TRUE(oracle.segment_touches_surface({4, 4, 4}, {6, 6, 6}));
  EXPECT_TRUE(oracle.point_touches_surface({5, 5, 5}));
  const std::optional<OracleHit> hit = oracle.first_touched_triangle({4, 4, 4}, {6, 6, 6});
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->where, (TriangleRef{0, 1}));
  EXPECT_NEAR(hit->t, 0.5, 1e-15);
}

TEST(SurfaceCrossingOracle, PointQueries) {
  const SurfaceCrossingOracle oracle(one_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  EXPECT_TRUE(oracle.point_touches_surface({0.25, 0.25, 0.0}));
  EXPECT_TRUE(oracle.point_touches_surface({0.5, 0.5, 0.0}));  // on the hypotenuse
  EXPECT_TRUE(oracle.segment_touches_surface({0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}));
  EXPECT_FALSE(oracle.point_touches_surface({0.25, 0.25, 1e-12}));
  EXPECT_NEAR(oracle.distance_to_surface({0.25, 0.25, 0.02}), 0.02, 1e-15);
  EXPECT_NEAR(oracle.distance_to_surface({-0.03, 0.25, 0.04}), 0.05, 1e-15);
}

TEST(SurfaceCrossingOracle, PosesPlaceTrianglesInTheWorld) {
  const TriangleMesh mesh = one_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  Pose X_WO = Pose::Identity();
  X_WO.linear() = Eigen::AngleAxisd(std::numbers::pi / 2.0, Vector3d::UnitX()).toRotationMatrix();
  X_WO.translation() = Vector3d(0.0, 0.0, 2.0);
  // The triangle now lies in y = 0, z in [2, 3].
  const PlacedMesh placed[] = {{&mesh, Pose::Identity()}, {&mesh, X_WO}};
  const SurfaceCrossingOracle oracle(placed);
  ASSERT_EQ(oracle.object_count(), 2);
  const std::optional<OracleHit> hit = oracle.first_touched_triangle({0.25, 1.0, 2.25}, {0.25, -1.0, 2.25});
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->where, (TriangleRef{1, 0}));
  EXPECT_FALSE(oracle.segment_touches_surface({0.25, 0.25, 1.0}, {0.25, 0.25, 1.5}));
  EXPECT_TRUE(oracle.segment_touches_surface({0.25, 0.25, 1.0}, {0.25, 0.25, -1.0}));
}

TEST(SurfaceCrossingOracle, InsideClosedMeshByParity) {
  for (bool welded : {true, false}) {
    SCOPED_TRACE(welded ? "welded" : "unwelded");
    const SurfaceCrossingOracle box(make_test_box({-0.1, -0.2, -0.3}, {0.1, 0.2, 0.3}, welded));
    EXPECT_TRUE(box.is_closed(0));
    EXPECT_EQ(box.side_of_closed_surfaces({0, 0, 0}), SurfaceSide::Inside);
    EXPECT_EQ(box.side_of_closed_surfaces({0.1 - 1e-12, 0.2 - 1e-12, 0.3 - 1e-12}), SurfaceSide::Inside);
    EXPECT_EQ(box.side_of_closed_surfaces({0.1 + 1e-12, 0.0, 0.0}), SurfaceSide::Outside);
    EXPECT_EQ(box.side_of_closed_surfaces({0.1, 0.0, 0.0}), SurfaceSide::OnSurface);
    EXPECT_EQ(box.side_of_closed_surfaces({0.1, 0.2, 0.3}), SurfaceSide::OnSurface);  // corner
    EXPECT_EQ(box.side_of_closed_surfaces({0.0, 0.0, 5.0}), SurfaceSide::Outside);
    EXPECT_TRUE(box.point_inside_closed_mesh({0.05, -0.05, 0.0}));
    EXPECT_FALSE(box.point_inside_closed_mesh({0.5, 0.0, 0.0}));
  }
  // Nested boxes: parity per object, inside either counts.
  const TriangleMesh outer = make_test_box({-1, -1, -1}, {1, 1, 1});
  const TriangleMesh inner = make_test_box({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5});
  const PlacedMesh both[] = {{&outer, Pose::Identity()}, {&inner, Pose::Identity()}};
  const SurfaceCrossingOracle nested(both);
  EXPECT_TRUE(nested.point_inside_closed_mesh({0, 0, 0}));
  EXPECT_TRUE(nested.point_inside_closed_mesh({0.7, 0, 0}));
  EXPECT_FALSE(nested.point_inside_closed_mesh({1.7, 0, 0}));
}

TriangleMesh turned_inside_out(TriangleMesh mesh) {
  for (TriangleIndices& t : mesh.triangles) std::swap(t[1], t[2]);
  return mesh;
}

TEST(SurfaceCrossingOracle, AClosedMeshWoundInsideOutIsARoomWithSolidBeyondItsWalls) {
  // The walls face in, as the engine reads them (the side a face's normal points to is
  // free): the room's air is outside the solid, and all beyond the walls is inside it.
  const TriangleMesh walls = turned_inside_out(make_test_box({-1, -1, -1}, {1, 1, 1}));
  const SurfaceCrossingOracle room(walls);
  EXPECT_TRUE(room.is_closed(0));
  EXPECT_EQ(room.side_of_closed_surfaces({0, 0, 0}), SurfaceSide::Outside);
  EXPECT_EQ(room.side_of_closed_surfaces({1 - 1e-12, 0.5, -0.5}), SurfaceSide::Outside);
  EXPECT_EQ(room.side_of_closed_surfaces({1 + 1e-12, 0.5, -0.5}), SurfaceSide::Inside);
  EXPECT_EQ(room.side_of_closed_surfaces({0.0, 0.0, 50.0}), SurfaceSide::Inside);
  EXPECT_EQ(room.side_of_closed_surfaces({1.0, 0.0, 0.0}), SurfaceSide::OnSurface);
  // A table in the room, in the same mesh (wound outwards): solid again.
  TriangleMesh furnished = walls;
  const TriangleMesh table = make_test_box({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5});
  const auto offset = static_cast<std::uint32_t>(furnished.vertices_m.size());
  for (const Vector3d& v : table.vertices_m) furnished.vertices_m.push_back(v);
  for (const TriangleIndices& t : table.triangles) furnished.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const SurfaceCrossingOracle with_table(furnished);
  EXPECT_TRUE(with_table.point_inside_closed_mesh({0, 0, 0}));
  EXPECT_FALSE(with_table.point_inside_closed_mesh({0.7, 0, 0}));
  EXPECT_TRUE(with_table.point_inside_closed_mesh({1.7, 0, 0}));
}

TEST(SurfaceCrossingOracle, OpenMeshesHaveNoInside) {
  TriangleMesh open_box = make_test_box({-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1});
  open_box.triangles.resize(10);  // drop the x = hi face
  const TriangleMesh square = make_test_square(-1, 1, -1, 1, 0);
  const PlacedMesh meshes[] = {{&open_box, Pose::Identity()}, {&square, Pose::Identity()}};
  const SurfaceCrossingOracle oracle(meshes);
  EXPECT_FALSE(oracle.is_closed(0));
  EXPECT_FALSE(oracle.is_closed(1));
  EXPECT_EQ(oracle.side_of_closed_surfaces({0, 0, 0}), SurfaceSide::Outside);
  EXPECT_EQ(oracle.side_of_closed_surfaces({0.5, 0.5, 0}), SurfaceSide::Outside);
}

TEST(SurfaceCrossingOracle, EmptyOracle) {
  const SurfaceCrossingOracle oracle(std::span<const PlacedMesh>{});
  EXPECT_EQ(oracle.triangle_count(), 0U);
  EXPECT_FALSE(oracle.segment_touches_surface({0, 0, 0}, {1, 1, 1}));
  EXPECT_FALSE(oracle.first_touched_triangle({0, 0, 0}, {1, 1, 1}).has_value());
  EXPECT_EQ(oracle.side_of_closed_surfaces({0, 0, 0}), SurfaceSide::Outside);
  EXPECT_TRUE(std::isinf(oracle.distance_to_surface({0, 0, 0})));
}

}  // namespace
}  // namespace mhd::verify
