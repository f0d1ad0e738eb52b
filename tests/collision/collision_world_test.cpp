#include "collision/collision_world.h"

#include "geometry/primitive_mesh.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>
#include <vector>

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

// A bumpy sheet of n x n squares (two triangles each) on [0, 1]^2, heights from `rng`.
std::shared_ptr<const MeshBvh> bumpy_sheet(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> bump(-0.02, 0.02);
  auto mesh = std::make_shared<TriangleMesh>();
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) mesh->vertices_m.emplace_back(double(i) / n, double(j) / n, bump(rng));
  }
  const auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      mesh->triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh->triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  compute_vertex_normals(*mesh);
  return std::make_shared<MeshBvh>(mesh);
}

TEST(CollisionWorld, FirstMetAnswersAsItsTrianglesSweptOneByOne) {
  // Two sheets in different poses (one touchable from the front only) and an exact sphere;
  // lists that mix them, so the segment is taken into one frame after another; segments
  // that cross faces, stop short of them, and end just past an edge within the sweep's
  // growth but not the graze's (a graze: met by sweep_triangle, not for real).
  std::mt19937 rng(20261201);
  CollisionWorld world;
  const int flat = world.add_object(bumpy_sheet(6, rng), Pose::Identity());
  const int turned = world.add_object(
      bumpy_sheet(6, rng), pose_from_xyz_rpy(Eigen::Vector3d(0.3, -0.2, 0.1), Eigen::Vector3d(0.4, -0.3, 0.9)));
  world.set_touchable(turned, TouchableFaces::Front);
  const int ball = world.add_object(unit_square(), pose_from_xyz_rpy(Eigen::Vector3d(0.5, 0.5, 0.3), Eigen::Vector3d::Zero()));
  world.set_exact_shape(ball, ExactShape{ExactKind::Sphere, 0.1, 0.0, Eigen::Vector3d::Zero()});
  const double skin_m = 1e-3;
  const double graze_m = 1e-6 * skin_m;
  const double inflate_m = 1e-2 * skin_m;  // the sweep's own growth (collision_world.cpp)
  const int objects[2] = {flat, turned};
  std::uniform_int_distribution<int> pick_object(0, 1);
  std::uniform_int_distribution<std::uint32_t> pick_triangle(0, 71);
  std::uniform_int_distribution<int> pick_count(1, 8);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int hits = 0;
  int grazes = 0;
  int exact_hits = 0;
  for (int k = 0; k < 4000; ++k) {
    std::vector<TriangleRef> ts;
    const int count = pick_count(rng);
    for (int i = 0; i < count; ++i) ts.push_back(TriangleRef{objects[pick_object(rng)], pick_triangle(rng)});
    if (k % 5 == 0) ts.insert(ts.begin() + (k % count), TriangleRef{ball, kExactSurface});
    // A segment down through a point of the first triangle, or just past one of its edges.
    const TriangleRef& aim = ts.front().triangle == kExactSurface ? ts.back() : ts.front();
    const auto v = world.triangle_W(aim);
    const Eigen::Vector3d n = (v[1] - v[0]).cross(v[2] - v[0]).normalized();
    Eigen::Vector3d target;
    if (k % 3 == 0) {
      const int e = k % 2;
      const Eigen::Vector3d mid = 0.5 * (v[static_cast<std::size_t>(e)] + v[static_cast<std::size_t>(e + 1)]);
      const Eigen::Vector3d edge = v[static_cast<std::size_t>(e + 1)] - v[static_cast<std::size_t>(e)];
      Eigen::Vector3d outward = edge.cross(n).normalized();
      if (outward.dot(mid - v[static_cast<std::size_t>(2 - e)]) < 0.0) outward = -outward;
      target = mid + 0.5 * inflate_m * outward;
    } else {
      const double r = unit(rng), s = unit(rng) * (1.0 - r);
      target = v[0] + r * (v[1] - v[0]) + s * (v[2] - v[0]);
    }
    const double side = k % 7 == 0 ? -1.0 : 1.0;  // from behind now and then
    Eigen::Vector3d a_W = target + side * (0.01 + 0.02 * unit(rng)) * n;
    Eigen::Vector3d b_W = target - side * (k % 4 == 0 ? -0.5 * skin_m : 0.005) * n;
    if (k % 10 == 0) {  // down onto the ball instead
      const Eigen::Vector3d off(0.05 * unit(rng), 0.05 * unit(rng), 0.0);
      a_W = Eigen::Vector3d(0.5, 0.5, 0.6) + off;
      b_W = Eigen::Vector3d(0.5, 0.5, 0.3) + off;
    }

    std::optional<SweepHit> expected;
    for (const TriangleRef& t : ts) {
      auto hit = world.sweep_triangle(t, a_W, b_W, skin_m);
      if (!hit || (expected && !(hit->t_stop < expected->t_stop))) continue;
      if (t.triangle != kExactSurface && !world.meets_triangle_grown_by(t, a_W, b_W, skin_m, graze_m)) {
        ++grazes;
        continue;
      }
      expected = hit;
    }
    int tests = 3;
    const auto got = world.first_met(ts, a_W, b_W, skin_m, graze_m, tests);
    ASSERT_EQ(tests, 3 + count + (k % 5 == 0 ? 1 : 0)) << "case " << k;
    ASSERT_EQ(got.has_value(), expected.has_value()) << "case " << k;
    if (!got) continue;
    ++hits;
    if (got->where.triangle == kExactSurface) ++exact_hits;
    EXPECT_EQ(got->where, expected->where) << "case " << k;
    EXPECT_EQ(got->t_stop, expected->t_stop) << "case " << k;
    EXPECT_EQ(got->normal_W, expected->normal_W) << "case " << k;
    EXPECT_EQ(got->plane_offset_m, expected->plane_offset_m) << "case " << k;
  }
  // The cases reached every branch: hits of each kind and grazes passed over.
  EXPECT_GT(hits, 500);
  EXPECT_GT(exact_hits, 0);
  EXPECT_GT(grazes, 50);
}

// What a sweep of the whole world must answer: the earliest of its sweeps of each object
// alone (which visit no tree of objects). Random shapes and segments make ties unlikely.
std::optional<SweepHit> earliest_object_by_object(const CollisionWorld& world, const Eigen::Vector3d& a,
                                                  const Eigen::Vector3d& b, double skin_m) {
  std::optional<SweepHit> first;
  for (int j = 0; j < world.object_count(); ++j) {
    const auto hit = world.sweep_object(j, a, b, skin_m);
    if (hit && (!first || hit->t_stop < first->t_stop)) first = hit;
  }
  return first;
}

Pose random_pose(std::mt19937_64& rng, double spread_m) {
  std::uniform_real_distribution<double> at(-spread_m, spread_m);
  std::normal_distribution<double> gauss;
  const Eigen::Quaterniond turn(gauss(rng), gauss(rng), gauss(rng), gauss(rng));
  Pose X = Pose::Identity();
  X.linear() = turn.normalized().toRotationMatrix();
  X.translation() = Eigen::Vector3d(at(rng), at(rng), at(rng));
  return X;
}

TEST(CollisionWorld, ASweepAmongManyObjectsMeetsWhatEachObjectSweptAloneMeets) {
  std::mt19937_64 rng(5122026);
  std::uniform_real_distribution<double> size(0.05, 0.4);
  // With every object in the tree of objects, and with the later half added after it.
  for (const bool indexed : {true, false}) {
    SCOPED_TRACE(indexed ? "indexed" : "added after the index");
    CollisionWorld world;
    for (int i = 0; i < 300; ++i) {
      const auto box = std::make_shared<TriangleMesh>(make_box_mesh(Eigen::Vector3d(size(rng), size(rng), size(rng))));
      const int id = world.add_object(std::make_shared<MeshBvh>(box), random_pose(rng, 1.5));
      if (i % 10 == 3) world.set_exact_shape(id, ExactShape{ExactKind::Sphere, 0.1, 0.0, Eigen::Vector3d::Zero()});
      if (i % 10 == 7) {
        world.set_exact_shape(id, ExactShape{ExactKind::Capsule, 0.03, 0.1, Eigen::Vector3d::Zero()});
      }
      if (i == 150 && indexed) world.index_objects();
    }
    // The floor: a half-space (z <= 0 in its frame), unbounded, 3 m down.
    const int floor = world.add_object(std::make_shared<MeshBvh>(std::make_shared<TriangleMesh>(
                                           make_box_mesh(Eigen::Vector3d(1, 1, 1)))),
                                       pose_from_xyz_rpy(Eigen::Vector3d(0, 0, -3), Eigen::Vector3d::Zero()));
    world.set_exact_shape(floor, ExactShape{ExactKind::HalfSpace, 0.0, 0.0, Eigen::Vector3d::Zero()});
    if (indexed) world.index_objects();
    std::uniform_real_distribution<double> at(-2.0, 2.0);
    std::uniform_real_distribution<double> length(0.0, 1.0);
    int hits = 0;
    for (int round = 0; round < 2; ++round) {
      for (int k = 0; k < 2000; ++k) {
        const Eigen::Vector3d a(at(rng), at(rng), at(rng));
        const Eigen::Vector3d b = a + (k % 4 == 0 ? 3.0 : 0.6) * length(rng) * Eigen::Vector3d::Random();
        const auto hit = world.sweep(a, b, 1e-6);
        const auto expected = earliest_object_by_object(world, a, b, 1e-6);
        ASSERT_EQ(hit.has_value(), expected.has_value()) << "round " << round << " segment " << k;
        if (!hit) continue;
        ++hits;
        EXPECT_EQ(hit->where, expected->where) << "round " << round << " segment " << k;
        EXPECT_EQ(hit->t_stop, expected->t_stop) << "round " << round << " segment " << k;
      }
      // Everything moves (the tree is refitted, not rebuilt), and the floor rises.
      for (int i = 0; i < world.object_count(); ++i) {
        world.set_pose(i, i == floor ? pose_from_xyz_rpy(Eigen::Vector3d(0, 0, -2), Eigen::Vector3d(0.1, 0, 0))
                                     : random_pose(rng, 1.5));
      }
    }
    EXPECT_GT(hits, 400);  // the sweeps met objects, not only empty space
  }
}

TEST(CollisionWorld, ATriangleFarFromTheRestOfItsMeshIsSweptLikeTheRest) {
  // A 0.2 m sheet of 2 mm quads (20,000 triangles) and one 1 cm triangle 1000 km away in
  // the same mesh. Sweeps through the sheet test a few triangles, not the sheet (the
  // tree's grid spans the sheet, not the 1000 km), and the far triangle still stops a
  // sweep through it: from the tree, and from the candidate list.
  auto mesh = std::make_shared<TriangleMesh>();
  const int n = 100;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) mesh->vertices_m.emplace_back(0.2 * i / n, 0.2 * j / n, 0.0);
  const auto id = [](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      mesh->triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh->triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  const double far_m = 1e6;
  const auto first = static_cast<std::uint32_t>(mesh->vertices_m.size());
  mesh->vertices_m.emplace_back(far_m, 0.0, 0.0);
  mesh->vertices_m.emplace_back(far_m + 0.01, 0.0, 0.0);
  mesh->vertices_m.emplace_back(far_m, 0.01, 0.0);
  mesh->triangles.push_back({first, first + 1, first + 2});
  const auto far_triangle = static_cast<std::uint32_t>(mesh->triangles.size() - 1);
  CollisionWorld world;
  world.add_object(std::make_shared<MeshBvh>(mesh), Pose::Identity());
  SweepCandidates near;
  for (SweepCandidates* list : {static_cast<SweepCandidates*>(nullptr), &near, &near}) {
    SweepWork work;
    const auto on_sheet = world.sweep(Eigen::Vector3d(0.1011, 0.1013, 0.0005), Eigen::Vector3d(0.1011, 0.1013, -0.0005),
                                      1e-6, {}, &work, list);
    ASSERT_TRUE(on_sheet);
    EXPECT_NE(on_sheet->where.triangle, far_triangle);
    EXPECT_LE(work.triangle_tests, 64);
    const auto at_far = world.sweep(Eigen::Vector3d(far_m + 0.002, 0.002, 0.0005),
                                    Eigen::Vector3d(far_m + 0.002, 0.002, -0.0005), 1e-6, {}, &work, list);
    ASSERT_TRUE(at_far);
    EXPECT_EQ(at_far->where.triangle, far_triangle);
  }
}

// A fan of slivers round one vertex, as at a fine uv-sphere's pole: every sliver's box holds
// the apex, so a sweep there meets all of their leaves.
std::shared_ptr<const MeshBvh> sliver_fan(int slivers) {
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices_m.emplace_back(0.0, 0.0, 0.0);
  for (int j = 0; j < slivers; ++j) {
    const double a = 2.0 * std::numbers::pi * j / slivers;
    mesh->vertices_m.emplace_back(1e-4 * std::cos(a), 1e-4 * std::sin(a), -1e-9);
  }
  for (int j = 0; j < slivers; ++j) {
    mesh->triangles.push_back(
        {0, static_cast<std::uint32_t>(1 + j), static_cast<std::uint32_t>(1 + (j + 1) % slivers)});
  }
  return std::make_shared<MeshBvh>(mesh);
}

TEST(CollisionWorld, ASweepOutOfItsBudgetStopsWalkingTheTree) {
  const int slivers = 20000;
  CollisionWorld world;
  world.add_object(sliver_fan(slivers), Pose::Identity());
  const Eigen::Vector3d above(1e-7, 2e-7, 5e-4);
  const Eigen::Vector3d below(1e-7, 2e-7, -5e-4);
  // Out of its budget: the sweep says so, and its walk went no further than it could test.
  SweepWork out;
  out.max_triangle_tests = 500;
  EXPECT_FALSE(world.sweep(above, below, 1e-6, {}, &out));
  EXPECT_TRUE(out.exhausted);
  EXPECT_EQ(out.triangle_tests, 500);
  EXPECT_LE(out.leaves_reached, 501);
  // The dual: within its budget the walk reaches every sliver, and the sweep stops on the fan.
  SweepWork whole;
  const auto hit = world.sweep(above, below, 1e-6, {}, &whole);
  ASSERT_TRUE(hit);
  EXPECT_FALSE(whole.exhausted);
  EXPECT_GE(whole.leaves_reached, slivers);
  EXPECT_EQ(whole.triangle_tests, whole.leaves_reached);
  EXPECT_NEAR(hit->t_stop * 1e-3, 5e-4 - 1e-6, 1e-8);
}

TEST(CollisionWorld, ALongSweepFromAFineMeshsPoleClearsItsFirstPieces) {
  // A uv-sphere's polar cap, flattened: a fan of 1,000 slivers 63 µm long round the pole,
  // then a band of 2,000 out to 126 µm. From the pole, half a skin above the cap, a sweep 5
  // mm long over more leaves than its budget allows runs out, but with fine pieces only
  // after the pieces nearest its start: on a mesh this fine they are a few vertex spacings
  // long, not a millimetre, whose box would hold the whole cap.
  const int segments = 1000;
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices_m.emplace_back(0.0, 0.0, 0.0);
  for (const double r_m : {63e-6, 126e-6}) {
    for (int j = 0; j < segments; ++j) {
      const double a = 2.0 * std::numbers::pi * j / segments;
      mesh->vertices_m.emplace_back(r_m * std::cos(a), r_m * std::sin(a), 0.0);
    }
  }
  const auto ring = [&](int r, int j) { return static_cast<std::uint32_t>(1 + r * segments + j % segments); };
  for (int j = 0; j < segments; ++j) {
    mesh->triangles.push_back({0, ring(0, j), ring(0, j + 1)});
    mesh->triangles.push_back({ring(0, j), ring(1, j), ring(1, j + 1)});
    mesh->triangles.push_back({ring(0, j), ring(1, j + 1), ring(0, j + 1)});
  }
  CollisionWorld world;
  world.add_object(std::make_shared<MeshBvh>(mesh), Pose::Identity());
  const double skin_m = 1e-6;
  const Eigen::Vector3d from(1e-7, 2e-7, 0.5 * skin_m);
  const Eigen::Vector3d to(3e-3, 4e-3, 0.5 * skin_m);
  SweepWork work;
  work.max_triangle_tests = 1500;
  work.fine_pieces = true;
  EXPECT_FALSE(world.sweep(from, to, skin_m, {}, &work));
  ASSERT_TRUE(work.exhausted);
  const double clear_m = work.clear_fraction * (to - from).norm();
  EXPECT_GE(clear_m, 1e-5);
  EXPECT_LT(clear_m, 126e-6);  // not past the cap it did not finish
  // Without fine pieces, the first piece is a millimetre, which holds the whole cap.
  SweepWork coarse;
  coarse.max_triangle_tests = 1500;
  EXPECT_FALSE(world.sweep(from, to, skin_m, {}, &coarse));
  EXPECT_TRUE(coarse.exhausted);
  EXPECT_EQ(coarse.clear_fraction, 0.0);
  // Within a budget that holds the cap, the sweep clears the whole way.
  SweepWork whole;
  EXPECT_FALSE(world.sweep(from, to, skin_m, {}, &whole));
  EXPECT_FALSE(whole.exhausted);
}

}  // namespace
}  // namespace mhd
