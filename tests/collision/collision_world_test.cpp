#include "collision/collision_world.h"

#include <gtest/gtest.h>

#include <numbers>

namespace mhd {
namespace {

std::shared_ptr<const MeshBvh> unit_square() {
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices_m = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh->triangles = {{0, 1, 2}, {0, 2, 3}};
  compute_vertex_normals(*mesh);
  return std::make_shared<MeshBvh>(mesh);
}

TEST(CollisionWorld, SweepFindsTheSurfaceInTheObjectsPose) {
  CollisionWorld world;
  // Square turned to face +x, moved to x = 2.
  Pose X_WO = pose_from_xyz_rpy(Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(0, std::numbers::pi / 2, 0));
  const int id = world.add_object(unit_square(), X_WO);
  const Eigen::Vector3d a(3, 0.5, -0.5), b(1, 0.5, -0.5);
  const auto hit = world.sweep(a, b, 1e-6);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->where.object, id);
  EXPECT_NEAR(hit->normal_W.x(), 1.0, 1e-12);
  EXPECT_NEAR(hit->plane_offset_m, 2.0, 1e-12);
  const Eigen::Vector3d stop = a + hit->t_stop * (b - a);
  EXPECT_NEAR(stop.x(), 2.0 + 1e-6, 1e-12);
}

TEST(CollisionWorld, AFrontOnlySheetBlocksFromTheFrontAndIsPassedFromBehind) {
  // The square faces +z (counter-clockwise seen from above). Turned over by its pose, its
  // front faces -z: the side is the triangle's, wherever the object is placed.
  for (const bool turned : {false, true}) {
    SCOPED_TRACE(turned ? "turned over" : "as built");
    CollisionWorld world;
    const Pose X_WO = turned ? pose_from_xyz_rpy(Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(std::numbers::pi, 0, 0))
                             : Pose::Identity();
    const int id = world.add_object(unit_square(), X_WO);
    const Eigen::Vector3d front(0.5, 0.5, turned ? -1.0 : 1.0), back(0.5, 0.5, turned ? 1.0 : -1.0);
    const Eigen::Vector3d on_plane_front = front * 1e-9 + Eigen::Vector3d(0.5, 0.5, 0) * (1 - 1e-9);
    EXPECT_EQ(world.touchable(id), TouchableFaces::Both);
    ASSERT_TRUE(world.sweep(front, back, 1e-6));  // both sides by default
    ASSERT_TRUE(world.sweep(back, front, 1e-6));

    world.set_touchable(id, TouchableFaces::Front);
    const auto from_front = world.sweep(front, back, 1e-6);
    ASSERT_TRUE(from_front);
    EXPECT_GT(from_front->normal_W.dot(front - back), 0.0);  // pushes back out to the front
    EXPECT_FALSE(world.sweep(back, front, 1e-6)) << "a front-only face blocked a move from behind";
    EXPECT_FALSE(world.sweep_triangle(TriangleRef{id, 0}, back, front, 1e-6));
    EXPECT_TRUE(world.sweep_triangle(TriangleRef{id, 0}, front, back, 1e-6));
    // Resting a hair in front of it, the surface still holds.
    EXPECT_TRUE(world.sweep(on_plane_front, back, 1e-6));

    world.set_touchable(id, TouchableFaces::Back);
    EXPECT_FALSE(world.sweep(front, back, 1e-6));
    EXPECT_TRUE(world.sweep(back, front, 1e-6));
  }
}

TEST(CollisionWorld, MovingAnObjectMovesItsSurfaceNotItsTree) {
  CollisionWorld world;
  const auto shape = unit_square();
  const int id = world.add_object(shape, Pose::Identity());
  const btOptimizedBvh* tree_before = const_cast<btBvhTriangleMeshShape&>(world.shape(id).shape()).getOptimizedBvh();
  ASSERT_TRUE(world.sweep(Eigen::Vector3d(0.5, 0.5, 1), Eigen::Vector3d(0.5, 0.5, -1), 1e-6));
  Pose moved = Pose::Identity();
  moved.translation() = Eigen::Vector3d(5, 0, 0);
  world.set_pose(id, moved);
  EXPECT_FALSE(world.sweep(Eigen::Vector3d(0.5, 0.5, 1), Eigen::Vector3d(0.5, 0.5, -1), 1e-6));
  EXPECT_TRUE(world.sweep(Eigen::Vector3d(5.5, 0.5, 1), Eigen::Vector3d(5.5, 0.5, -1), 1e-6));
  EXPECT_EQ(const_cast<btBvhTriangleMeshShape&>(world.shape(id).shape()).getOptimizedBvh(), tree_before);
}

TEST(CollisionWorld, SweepObjectSeesOnlyThatObject) {
  // Two parallel squares at z = 0 and z = -1: a segment through both hits the nearer one
  // in sweep(), and each square alone in sweep_object().
  CollisionWorld world;
  const int near = world.add_object(unit_square(), Pose::Identity());
  Pose below = Pose::Identity();
  below.translation() = Eigen::Vector3d(0, 0, -1);
  const int far = world.add_object(unit_square(), below);
  const Eigen::Vector3d a(0.5, 0.5, 1), b(0.5, 0.5, -2);
  ASSERT_TRUE(world.sweep(a, b, 1e-6));
  EXPECT_EQ(world.sweep(a, b, 1e-6)->where.object, near);
  const auto only_far = world.sweep_object(far, a, b, 1e-6);
  ASSERT_TRUE(only_far);
  EXPECT_EQ(only_far->where.object, far);
  EXPECT_NEAR((a + only_far->t_stop * (b - a)).z(), -1.0 + 1e-6, 1e-12);
  EXPECT_EQ(world.sweep_object(near, a, b, 1e-6)->where.object, near);
  // A segment that misses the object asked about is free, whatever else it crosses.
  EXPECT_FALSE(world.sweep_object(far, a, Eigen::Vector3d(0.5, 0.5, -0.5), 1e-6));
  EXPECT_THROW((void)world.sweep_object(2, a, b, 1e-6), std::out_of_range);
}

TEST(CollisionWorld, IgnoredTrianglesAreSkipped) {
  CollisionWorld world;
  world.add_object(unit_square(), Pose::Identity());
  const Eigen::Vector3d a(0.7, 0.2, 1), b(0.7, 0.2, -1);  // over triangle 0 only
  const auto hit = world.sweep(a, b, 1e-6);
  ASSERT_TRUE(hit);
  const TriangleRef ignore[] = {hit->where};
  EXPECT_FALSE(world.sweep(a, b, 1e-6, ignore));
}

TEST(CollisionWorld, OnlyTheIgnoredTriangleIsSkippedNotOneSharingItsIndexBits) {
  // The sweep's quick filter keys on the triangle index mod 64: a triangle 64 (or 128) on,
  // or the same index in another object, is not ignored for it.
  CollisionWorld world;
  world.add_object(unit_square(), Pose::Identity());
  world.add_object(unit_square(), pose_from_xyz_rpy(Eigen::Vector3d(0, 0, -0.5), Eigen::Vector3d::Zero()));
  const Eigen::Vector3d a(0.7, 0.2, 1), b(0.7, 0.2, -1);  // over triangle 0 of each
  const TriangleRef others[] = {{0, 64}, {0, 128}, {1, 0}};
  const auto hit = world.sweep(a, b, 1e-6, others);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->where, (TriangleRef{0, 0}));
  const TriangleRef first[] = {{0, 64}, {0, 0}};
  const auto next = world.sweep(a, b, 1e-6, first);
  ASSERT_TRUE(next);
  EXPECT_EQ(next->where, (TriangleRef{1, 0}));
}

TEST(CollisionWorld, ShadedNormalBlendsVertexNormals) {
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices_m = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh->triangles = {{0, 1, 2}};
  mesh->vertex_normals = {Eigen::Vector3f(0, 0, 1), Eigen::Vector3f(1, 0, 1).normalized(), Eigen::Vector3f(0, 0, 1)};
  CollisionWorld world;
  world.add_object(std::make_shared<MeshBvh>(mesh), Pose::Identity());
  const auto at_vertex1 = world.shaded_normal_W({0, 0}, Eigen::Vector3d(1, 0, 0));
  // Vertex normals are single precision: each direction within a few float roundings.
  EXPECT_TRUE(at_vertex1.isApprox(Eigen::Vector3d(1, 0, 1).normalized(), 1e-6));
  const auto at_vertex0 = world.shaded_normal_W({0, 0}, Eigen::Vector3d(0, 0, 0));
  EXPECT_TRUE(at_vertex0.isApprox(Eigen::Vector3d(0, 0, 1), 1e-12));
  EXPECT_NEAR(world.shaded_normal_W({0, 0}, Eigen::Vector3d(0.5, 0, 0)).norm(), 1.0, 1e-12);
}

TEST(CollisionWorld, ShadingNormalsOfAnObjectOverrideItsVertexNormalsInItsPose) {
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices_m = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh->triangles = {{0, 1, 2}};
  compute_vertex_normals(*mesh);  // all +z
  CollisionWorld world;
  // Turned a quarter round x: the object's +z is the world's -y.
  const int id = world.add_object(std::make_shared<MeshBvh>(mesh),
                                  pose_from_xyz_rpy(Eigen::Vector3d(0, 0, 2), Eigen::Vector3d(std::numbers::pi / 2, 0, 0)));
  EXPECT_EQ(world.shading_normals(id), nullptr);
  auto normals = std::make_shared<ShadingNormals>();
  normals->corner_normals_O = {{Eigen::Vector3f(0, 0, 1), Eigen::Vector3f(1, 0, 1).normalized(), Eigen::Vector3f(0, 0, 1)}};
  world.set_shading_normals(id, normals);
  EXPECT_EQ(world.shading_normals(id), normals.get());
  const Eigen::Vector3d vertex1_W = world.pose(id) * Eigen::Vector3d(1, 0, 0);
  EXPECT_TRUE(world.shaded_normal_W({id, 0}, vertex1_W).isApprox(Eigen::Vector3d(1, -1, 0).normalized(), 1e-7));
  world.set_shading_normals(id, nullptr);
  EXPECT_TRUE(world.shaded_normal_W({id, 0}, vertex1_W).isApprox(Eigen::Vector3d(0, -1, 0), 1e-12));
  // One entry per triangle, or the per-tick lookups would read past the end.
  auto too_few = std::make_shared<ShadingNormals>();
  EXPECT_THROW(world.set_shading_normals(id, too_few), std::invalid_argument);
}

}  // namespace
}  // namespace mhd
