// The oracle judges exact primitives as the solids they are, not by their tessellations.

#include "collision/point_containment.h"
#include "geometry/primitive_mesh.h"
#include "verification/surface_crossing_oracle.h"

#include <gtest/gtest.h>

#include <memory>

namespace mhd::verify {
namespace {

using Eigen::Vector3d;

// A coarse sphere (radius 0.05 m) at (0, 0, 0.1) made exact, and an exact floor.
CollisionWorld exact_world() {
  CollisionWorld world;
  auto mesh = [](TriangleMesh m) {
    return std::make_shared<const MeshBvh>(std::make_shared<const TriangleMesh>(std::move(m)));
  };
  Pose X = Pose::Identity();
  X.translation() = Vector3d(0.0, 0.0, 0.1);
  const int ball = world.add_object(mesh(make_sphere_mesh(0.05, 0)), X);
  world.set_exact_shape(ball, ExactShape{ExactKind::Sphere, 0.05, 0.0, Vector3d::Zero()});
  const int floor = world.add_object(mesh(make_plane_mesh(0.2, 0.2)), Pose::Identity());
  world.set_exact_shape(floor, ExactShape{ExactKind::HalfSpace, 0.0, 0.0, Vector3d::Zero()});
  return world;
}

TEST(ExactSolidOracle, ASegmentTouchingTheSphereCrossesItAndOneMissingByNanometresDoesNot) {
  const CollisionWorld world = exact_world();
  const SurfaceCrossingOracle oracle(world);
  EXPECT_FALSE(oracle.segment_touches_surface({-0.1, 0.05 + 1e-9, 0.1}, {0.1, 0.05 + 1e-9, 0.1}));
  EXPECT_TRUE(oracle.segment_touches_surface({-0.1, 0.05 - 1e-9, 0.1}, {0.1, 0.05 - 1e-9, 0.1}));
  const auto hit = oracle.first_touched_triangle({0.0, 0.0, 0.3}, {0.0, 0.0, 0.12});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->where, (TriangleRef{0, kExactSurface}));
  EXPECT_NEAR(0.3 + hit->t * (0.12 - 0.3), 0.15, 1e-12);
}

TEST(ExactSolidOracle, ThePointsBetweenTheFacetsAndTheTrueSphereAreInsideIt) {
  const CollisionWorld world = exact_world();
  const SurfaceCrossingOracle oracle(world);
  // An icosahedron's face centre lies well inside the sphere's radius: 0.049 m from the
  // centre is inside the exact sphere, outside the 20-triangle tessellation in most directions.
  const Vector3d between = Vector3d(0.0, 0.0, 0.1) + 0.049 * Vector3d(0.3, 0.5, 0.81).normalized();
  EXPECT_EQ(oracle.side_of_closed_surfaces(between), SurfaceSide::Inside);
  EXPECT_TRUE(point_inside_surface(world, between));
  const Vector3d outside = Vector3d(0.0, 0.0, 0.1) + 0.0501 * Vector3d(0.3, 0.5, 0.81).normalized();
  EXPECT_EQ(oracle.side_of_closed_surfaces(outside), SurfaceSide::Outside);
  EXPECT_FALSE(point_inside_surface(world, outside));
  EXPECT_TRUE(oracle.is_closed(0));
  EXPECT_NEAR(oracle.distance_to_surface(outside), 1e-4, 1e-12);
}

TEST(ExactSolidOracle, TheInfiniteFloorHoldsFarBeyondItsTessellation) {
  const CollisionWorld world = exact_world();
  const SurfaceCrossingOracle oracle(world);
  EXPECT_TRUE(oracle.segment_touches_surface({30.0, 0.0, 0.01}, {30.0, 0.0, -0.01}));
  EXPECT_FALSE(oracle.segment_touches_surface({30.0, 0.0, 0.01}, {31.0, 0.0, 1e-12}));
  EXPECT_TRUE(oracle.point_inside_closed_mesh({30.0, 0.0, -1e-9}));
  EXPECT_TRUE(point_inside_surface(world, {30.0, 0.0, -1e-9}));
  EXPECT_FALSE(point_inside_surface(world, {30.0, 0.0, 1e-9}));
}

TEST(ExactSolidOracle, ABrushIsASurfacePassedCloseNotTheOneTheStartRestsOn) {
  const CollisionWorld world = exact_world();
  const SurfaceCrossingOracle oracle(world);
  // From the floor (resting on it) along it: no brush; past the sphere's side within
  // 5 um from far away: a brush.
  EXPECT_FALSE(oracle.segment_brushes_surface({0.1, 0.1, 1e-6}, {0.15, 0.1, 1e-6}, 1e-5));
  EXPECT_TRUE(oracle.segment_brushes_surface({-0.1, 0.05 + 5e-6, 0.1}, {0.1, 0.05 + 5e-6, 0.1}, 1e-5));
  EXPECT_FALSE(oracle.segment_brushes_surface({-0.1, 0.06, 0.1}, {0.1, 0.06, 0.1}, 1e-5));
}

}  // namespace
}  // namespace mhd::verify
