// Sweeps of a point against the exact primitives, checked against the analytic answer.

#include "collision/collision_world.h"
#include "collision/exact_sweep.h"
#include "geometry/primitive_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace mhd {
namespace {

constexpr double kExactSkin = 1e-6;

ExactShape sphere(double r) { return ExactShape{ExactKind::Sphere, r, 0.0, Eigen::Vector3d::Zero()}; }
ExactShape capsule(double r, double half) { return ExactShape{ExactKind::Capsule, r, half, Eigen::Vector3d::Zero()}; }
ExactShape cylinder(double r, double half) { return ExactShape{ExactKind::Cylinder, r, half, Eigen::Vector3d::Zero()}; }
ExactShape box(const Eigen::Vector3d& half) { return ExactShape{ExactKind::Box, 0.0, 0.0, half}; }
ExactShape half_space() { return ExactShape{ExactKind::HalfSpace, 0.0, 0.0, Eigen::Vector3d::Zero()}; }

// The stop point of a sweep that hit.
Eigen::Vector3d stop_point(const ExactSweep& hit, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return a + hit.t_stop * (b - a);
}

TEST(ExactSweep, SphereStopsOneSkinOffTheAnalyticHitWithTheRadialNormal) {
  const ExactShape s = sphere(0.05);
  const Eigen::Vector3d a(0.2, 0.01, 0.02), b(-0.2, 0.01, 0.02);
  const auto hit = sweep_point_exact(s, a, b, kExactSkin);
  ASSERT_TRUE(hit);
  // Analytic: x^2 = (r + skin)^2 - y^2 - z^2 on the near side.
  const double x = std::sqrt(std::pow(0.05 + kExactSkin, 2) - 0.01 * 0.01 - 0.02 * 0.02);
  const Eigen::Vector3d p = stop_point(*hit, a, b);
  EXPECT_NEAR(p.x(), x, 1e-12);
  EXPECT_NEAR(p.norm(), 0.05 + kExactSkin, 1e-12);
  EXPECT_NEAR((hit->contact.normal_O - p.normalized()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(hit->contact.point_O.norm(), 0.05, 1e-12);
}

TEST(ExactSweep, SphereMissesAPassingSegmentAndOneThatStopsShort) {
  const ExactShape s = sphere(0.05);
  EXPECT_FALSE(sweep_point_exact(s, {0.2, 0.051, 0.0}, {-0.2, 0.051, 0.0}, kExactSkin));
  EXPECT_FALSE(sweep_point_exact(s, {0.2, 0.0, 0.0}, {0.06, 0.0, 0.0}, kExactSkin));
  // The same line reaching just past the skin is stopped.
  EXPECT_TRUE(sweep_point_exact(s, {0.2, 0.0, 0.0}, {0.05 + 0.5 * kExactSkin, 0.0, 0.0}, kExactSkin));
}

TEST(ExactSweep, ASegmentOnTheSurfaceMovingOutIsFreeAndMovingInIsStoppedAtOnce) {
  const ExactShape s = sphere(0.05);
  const Eigen::Vector3d on(0.05, 0.0, 0.0);
  EXPECT_FALSE(sweep_point_exact(s, on, {0.1, 0.0, 0.0}, kExactSkin));
  EXPECT_FALSE(sweep_point_exact(s, on, {0.05, 0.01, 0.0}, kExactSkin));  // tangent: moves away
  const auto in = sweep_point_exact(s, on, {0.0, 0.0, 0.0}, kExactSkin);
  ASSERT_TRUE(in);
  EXPECT_EQ(in->t_stop, 0.0);
  EXPECT_NEAR((in->contact.normal_O - Eigen::Vector3d::UnitX()).norm(), 0.0, 1e-15);
}

TEST(ExactSweep, AStartInsideTheSolidIsLetOut) {
  EXPECT_FALSE(sweep_point_exact(sphere(0.05), {0.0, 0.0, 0.0}, {0.2, 0.0, 0.0}, kExactSkin));
  EXPECT_FALSE(sweep_point_exact(half_space(), {0.0, 0.0, -0.1}, {0.0, 0.0, 0.1}, kExactSkin));
  EXPECT_FALSE(sweep_point_exact(box({0.1, 0.1, 0.1}), {0.0, 0.0, 0.0}, {0.3, 0.0, 0.0}, kExactSkin));
}

TEST(ExactSweep, HalfSpaceStopsOneSkinAboveTheInfinitePlaneFarFromTheOrigin) {
  const Eigen::Vector3d a(1e3, -2e3, 0.3), b(1e3 + 0.1, -2e3, -0.3);
  const auto hit = sweep_point_exact(half_space(), a, b, kExactSkin);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(stop_point(*hit, a, b).z(), kExactSkin, 1e-12);
  EXPECT_EQ(hit->contact.normal_O, Eigen::Vector3d::UnitZ());
  EXPECT_FALSE(sweep_point_exact(half_space(), {0.0, 0.0, 0.3}, {5.0, 0.0, 0.3}, kExactSkin));  // parallel
  EXPECT_FALSE(sweep_point_exact(half_space(), {0.0, 0.0, 0.3}, {0.0, 0.0, 0.1}, kExactSkin));  // stops short
}

TEST(ExactSweep, CapsuleHitsItsSideAndItsCapsAnalytically) {
  const ExactShape c = capsule(0.02, 0.05);
  // The side: stops at radius r + skin, normal radial.
  const auto side = sweep_point_exact(c, {0.1, 0.0, 0.03}, {-0.1, 0.0, 0.03}, kExactSkin);
  ASSERT_TRUE(side);
  EXPECT_NEAR(stop_point(*side, {0.1, 0.0, 0.03}, {-0.1, 0.0, 0.03}).x(), 0.02 + kExactSkin, 1e-12);
  EXPECT_NEAR((side->contact.normal_O - Eigen::Vector3d::UnitX()).norm(), 0.0, 1e-12);
  // A cap along a slanted line: the stop lies r + skin from the cap's centre.
  const Eigen::Vector3d a(0.01, 0.0, 0.2), b(0.01, 0.0, 0.0);
  const auto cap = sweep_point_exact(c, a, b, kExactSkin);
  ASSERT_TRUE(cap);
  const Eigen::Vector3d p = stop_point(*cap, a, b);
  EXPECT_NEAR((p - Eigen::Vector3d(0.0, 0.0, 0.05)).norm(), 0.02 + kExactSkin, 1e-12);
  EXPECT_NEAR((cap->contact.normal_O - (p - Eigen::Vector3d(0, 0, 0.05)).normalized()).norm(), 0.0, 1e-9);
  EXPECT_FALSE(sweep_point_exact(c, {0.021, 0.0, 0.2}, {0.021, 0.0, -0.2}, kExactSkin));  // passes beside
}

TEST(ExactSweep, CylinderHitsItsSideAndItsFlatEnd) {
  const ExactShape c = cylinder(0.03, 0.04);
  const auto side = sweep_point_exact(c, {0.0, 0.1, 0.0}, {0.0, -0.1, 0.0}, kExactSkin);
  ASSERT_TRUE(side);
  EXPECT_NEAR(stop_point(*side, {0.0, 0.1, 0.0}, {0.0, -0.1, 0.0}).y(), 0.03 + kExactSkin, 1e-12);
  EXPECT_NEAR((side->contact.normal_O - Eigen::Vector3d::UnitY()).norm(), 0.0, 1e-12);
  const auto end = sweep_point_exact(c, {0.01, 0.01, 0.1}, {0.01, 0.01, -0.1}, kExactSkin);
  ASSERT_TRUE(end);
  EXPECT_NEAR(stop_point(*end, {0.01, 0.01, 0.1}, {0.01, 0.01, -0.1}).z(), 0.04 + kExactSkin, 1e-12);
  EXPECT_EQ(end->contact.normal_O, Eigen::Vector3d::UnitZ());
  // Past the rim, in the corner of the bounding box: a miss.
  EXPECT_FALSE(sweep_point_exact(c, {0.025, 0.025, 0.1}, {0.025, 0.025, -0.1}, kExactSkin));
}

TEST(ExactSweep, BoxHitsAFaceAndStopsConservativelyAtAnEdge) {
  const ExactShape b = box({0.1, 0.05, 0.02});
  const auto face = sweep_point_exact(b, {0.0, 0.0, 0.1}, {0.01, 0.0, -0.1}, kExactSkin);
  ASSERT_TRUE(face);
  EXPECT_NEAR(stop_point(*face, {0.0, 0.0, 0.1}, {0.01, 0.0, -0.1}).z(), 0.02 + kExactSkin, 1e-12);
  EXPECT_EQ(face->contact.normal_O, Eigen::Vector3d::UnitZ());
  // Straight at an edge, diagonally: stops at least a skin away, the normal diagonal.
  const Eigen::Vector3d a(0.2, 0.0, 0.12), e(0.1, 0.0, 0.02);
  const auto edge = sweep_point_exact(b, a, e + (e - a), kExactSkin);
  ASSERT_TRUE(edge);
  const Eigen::Vector3d p = stop_point(*edge, a, e + (e - a));
  EXPECT_GE(exact_signed_distance(b, p), kExactSkin * (1.0 - 1e-9));
  EXPECT_LE(exact_signed_distance(b, p), 2.0 * kExactSkin);
  EXPECT_NEAR((edge->contact.normal_O - Eigen::Vector3d(1.0, 0.0, 1.0).normalized()).norm(), 0.0, 1e-9);
  EXPECT_FALSE(sweep_point_exact(b, {0.0, 0.06, 0.1}, {0.0, 0.06, -0.1}, kExactSkin));
}

TEST(ExactSweep, SignedDistanceIsNegativeInsideAndZeroOnEveryShapesSurface) {
  EXPECT_NEAR(exact_signed_distance(sphere(0.05), {0.0, 0.05, 0.0}), 0.0, 1e-15);
  EXPECT_LT(exact_signed_distance(capsule(0.02, 0.05), {0.0, 0.0, 0.06}), 0.0);
  EXPECT_NEAR(exact_signed_distance(capsule(0.02, 0.05), {0.0, 0.0, 0.07}), 0.0, 1e-15);
  EXPECT_NEAR(exact_signed_distance(cylinder(0.03, 0.04), {0.03, 0.0, 0.01}), 0.0, 1e-15);
  EXPECT_NEAR(exact_signed_distance(cylinder(0.03, 0.04), {0.06, 0.0, 0.08}), 0.05, 1e-15);
  EXPECT_NEAR(exact_signed_distance(box({0.1, 0.05, 0.02}), {0.0, 0.0, 0.0}), -0.02, 1e-15);
  EXPECT_NEAR(exact_signed_distance(half_space(), {7.0, 7.0, -0.5}), -0.5, 1e-15);
}

// A world with a tessellated floor and an exact sphere, the sphere placed by a pose.
struct ExactWorld {
  CollisionWorld world;
  ExactWorld() {
    auto floor = std::make_shared<const MeshBvh>(std::make_shared<const TriangleMesh>(make_plane_mesh(1.0, 1.0)));
    (void)world.add_object(floor, Pose::Identity());
    auto ball = std::make_shared<const MeshBvh>(std::make_shared<const TriangleMesh>(make_sphere_mesh(0.05, 1)));
    Pose X_WO = Pose::Identity();
    X_WO.translation() = Eigen::Vector3d(0.1, 0.0, 0.05);
    const int id = world.add_object(ball, X_WO);
    world.set_exact_shape(id, sphere(0.05));
  }
};

TEST(ExactSweepWorld, TheExactSphereFollowsItsPoseAndIsNamedByItsExactRef) {
  ExactWorld w;
  const Eigen::Vector3d a(0.1, 0.0, 0.3), b(0.1, 0.0, 0.07);
  const auto hit = w.world.sweep(a, b, kExactSkin);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->where, (TriangleRef{1, kExactSurface}));
  EXPECT_NEAR((a + hit->t_stop * (b - a)).z(), 0.1 + kExactSkin, 1e-12);  // not a facet of the tessellation
  Pose moved = Pose::Identity();
  moved.translation() = Eigen::Vector3d(0.3, 0.0, 0.05);
  w.world.set_pose(1, moved);
  EXPECT_FALSE(w.world.sweep(a, b, kExactSkin));
  const auto there = w.world.sweep(a + Eigen::Vector3d(0.2, 0.0, 0.0), b + Eigen::Vector3d(0.2, 0.0, 0.0), kExactSkin);
  ASSERT_TRUE(there);
  EXPECT_EQ(there->where.object, 1);
}

TEST(ExactSweepWorld, TheEarliestHitAmongTrianglesAndExactShapesWins) {
  ExactWorld w;
  // Down beside the sphere: the floor's triangles; down onto it: the sphere, also when
  // the sweep is long enough to go in pieces.
  const auto floor = w.world.sweep({0.3, 0.0, 0.3}, {0.3, 0.0, -0.3}, kExactSkin);
  ASSERT_TRUE(floor);
  EXPECT_EQ(floor->where.object, 0);
  const auto ball = w.world.sweep({0.1, 0.0, 0.9}, {0.1, 0.0, -0.3}, kExactSkin);
  ASSERT_TRUE(ball);
  EXPECT_EQ(ball->where.object, 1);
  // Ignoring the sphere's ref, the floor below it is found.
  const TriangleRef exact{1, kExactSurface};
  const auto under = w.world.sweep({0.1, 0.0, 0.9}, {0.1, 0.0, -0.3}, kExactSkin, std::span<const TriangleRef>(&exact, 1));
  ASSERT_TRUE(under);
  EXPECT_EQ(under->where.object, 0);
}

TEST(ExactSweepWorld, TheSupportPlaneIsTangentBelowAnOutsidePointAndAbsentInside) {
  ExactWorld w;
  const auto plane = w.world.support_plane(1, {0.1, 0.2, 0.05});
  ASSERT_TRUE(plane);
  EXPECT_NEAR((plane->normal_W - Eigen::Vector3d::UnitY()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(plane->plane_offset_m, 0.05, 1e-12);
  EXPECT_FALSE(w.world.support_plane(1, {0.1, 0.0, 0.06}));
  EXPECT_FALSE(w.world.support_plane(0, {0.1, 0.2, 0.05}));  // a mesh object has none
}

TEST(ExactSweepWorld, ABadSizeIsRefusedAndAGoodOneAccepted) {
  ExactWorld w;
  EXPECT_THROW(w.world.set_exact_shape(0, sphere(-1.0)), std::invalid_argument);
  EXPECT_THROW(w.world.set_exact_shape(0, capsule(0.01, std::nan(""))), std::invalid_argument);
  EXPECT_THROW(w.world.set_exact_shape(5, sphere(1.0)), std::out_of_range);
  EXPECT_EQ(w.world.exact_shape(0), nullptr);
  w.world.set_exact_shape(0, half_space());
  ASSERT_NE(w.world.exact_shape(0), nullptr);
  EXPECT_EQ(w.world.exact_shape(0)->kind, ExactKind::HalfSpace);
}

}  // namespace
}  // namespace mhd
