#include "collision/collision_world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace mhd {
namespace {

double wave_height_m(double x_m, double y_m) { return 0.002 * std::sin(90.0 * x_m) * std::cos(70.0 * y_m); }

// An n x n grid over [0, size_m]^2, two triangles a square, at height height_m(x, y).
template <class Height>
std::shared_ptr<TriangleMesh> grid(int n, double size_m, Height height_m) {
  auto mesh = std::make_shared<TriangleMesh>();
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const double x = size_m * i / n, y = size_m * j / n;
      mesh->vertices_m.emplace_back(x, y, height_m(x, y));
    }
  }
  auto id = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      mesh->triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh->triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return mesh;
}

// A wavy grid, 2 mm high waves: fine enough that one gather holds tens of triangles
// (n = 200 over 0.1 m) or overflows the list (n = 600).
std::shared_ptr<TriangleMesh> wavy_grid(int n, double size_m) { return grid(n, size_m, wave_height_m); }

void expect_same(const std::optional<SweepHit>& with_list, const std::optional<SweepHit>& with_tree, int k) {
  ASSERT_EQ(with_list.has_value(), with_tree.has_value()) << "sweep " << k;
  if (!with_tree) return;
  EXPECT_EQ(with_list->where, with_tree->where) << "sweep " << k;
  EXPECT_EQ(with_list->t_stop, with_tree->t_stop) << "sweep " << k;  // bit for bit: the same tests
  EXPECT_EQ(with_list->normal_W, with_tree->normal_W) << "sweep " << k;
  EXPECT_EQ(with_list->plane_offset_m, with_tree->plane_offset_m) << "sweep " << k;
}

// A proxy-like walk over the surface: short sweeps from points that drift slowly, in and
// out of the surface, now and then a jump elsewhere or a long sweep, some with triangles
// ignored. With a candidate list kept from sweep to sweep, every answer and every count of
// triangles tested must be the tree's own.
void sweep_like_a_proxy(const CollisionWorld& world, std::uint64_t seed, SweepCandidates& near, int& hits) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double skin_m = 1e-6;
  Eigen::Vector3d p(0.05, 0.05, 0.001);
  for (int k = 0; k < 3000; ++k) {
    if (u(rng) < 0.01) p = Eigen::Vector3d(0.1 * u(rng), 0.1 * u(rng), 0.004 * u(rng) - 0.002);
    p += Eigen::Vector3d(u(rng) - 0.5, u(rng) - 0.5, 0.0) * 0.0004;
    const double reach_m = u(rng) < 0.1 ? 0.02 : 0.0015 * u(rng);
    const Eigen::Vector3d dir = Eigen::Vector3d(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5).normalized();
    const Eigen::Vector3d b = p + reach_m * dir;
    std::vector<TriangleRef> ignore;
    if (k % 3 == 0) {
      if (const auto first = world.sweep(p, b, skin_m)) ignore.push_back(first->where);
    }
    SweepWork listed, walked;
    const auto with_list = world.sweep(p, b, skin_m, ignore, &listed, &near);
    const auto with_tree = world.sweep(p, b, skin_m, ignore, &walked);
    expect_same(with_list, with_tree, k);
    EXPECT_EQ(listed.triangle_tests, walked.triangle_tests) << "sweep " << k;
    hits += with_tree ? 1 : 0;
  }
}

TEST(SweepCandidates, SweepsFromTheListAnswerExactlyAsTheTreeDoes) {
  CollisionWorld world;
  world.add_object(std::make_shared<MeshBvh>(wavy_grid(200, 0.1)), Pose::Identity());
  // A second object, turned and shifted so that it crosses the first.
  world.add_object(std::make_shared<MeshBvh>(wavy_grid(100, 0.1)),
                   pose_from_xyz_rpy(Eigen::Vector3d(0.0, 0.05, 0.05), Eigen::Vector3d(-1.2, 0.0, 0.0)));
  SweepCandidates near;
  int hits = 0;
  sweep_like_a_proxy(world, 5, near, hits);
  EXPECT_GT(hits, 200);
  EXPECT_GT(near.gathers(), 20);  // the list was used, and gathered again as the point moved
  EXPECT_GT(near.size(), 0);
}

TEST(SweepCandidates, WhereAGatherWouldOverflowTheSweepsWalkTheTree) {
  // 720,000 triangles over 0.1 m: a gather round a point holds far more than the list.
  CollisionWorld world;
  world.add_object(std::make_shared<MeshBvh>(wavy_grid(600, 0.1)), Pose::Identity());
  SweepCandidates near;
  int hits = 0;
  sweep_like_a_proxy(world, 6, near, hits);
  EXPECT_GT(hits, 200);
  EXPECT_GT(near.gathers(), 0);
  EXPECT_EQ(near.size(), 0);  // no gather fitted
}

TEST(SweepCandidates, AListGatheredInAnotherWorldIsNotUsed) {
  // The same surface twice, its triangles numbered in reverse in the second world: same
  // bounds, same quantization, so only the world's name tells the lists apart.
  const auto mesh = wavy_grid(200, 0.1);
  auto reversed = std::make_shared<TriangleMesh>(*mesh);
  std::reverse(reversed->triangles.begin(), reversed->triangles.end());
  CollisionWorld first, second;
  first.add_object(std::make_shared<MeshBvh>(mesh), Pose::Identity());
  second.add_object(std::make_shared<MeshBvh>(reversed), Pose::Identity());
  const Eigen::Vector3d a(0.0503, 0.0497, 0.0025), b(0.0503, 0.0497, 0.0012);  // hits in its first piece
  SweepCandidates near;
  for (int i = 0; i < 3; ++i) (void)first.sweep(a, b, 1e-6, {}, nullptr, &near);  // gathers
  ASSERT_GT(near.size(), 0);
  const auto hit = second.sweep(a, b, 1e-6, {}, nullptr, &near);
  const auto expected = second.sweep(a, b, 1e-6);
  ASSERT_TRUE(expected);
  expect_same(hit, expected, 0);
  // A copy of a world shares its shapes, and its list.
  const CollisionWorld copy = second;
  EXPECT_EQ(copy.geometry_id(), second.geometry_id());
  EXPECT_NE(first.geometry_id(), second.geometry_id());
}

TEST(SweepCandidates, AListOutlivesAMoveOfItsObjectAndStillGivesTheTreesAnswers) {
  // Lists are kept in the object's own frame: after set_pose the same sweeps, relative to
  // the moved object, must hit the same triangles at the same fractions with the list as
  // without it.
  CollisionWorld world;
  world.add_object(std::make_shared<MeshBvh>(wavy_grid(200, 0.1)), Pose::Identity());
  const Eigen::Vector3d a(0.0503, 0.0497, 0.0025), b(0.0503, 0.0497, 0.0012);
  SweepCandidates near;
  for (int i = 0; i < 3; ++i) (void)world.sweep(a, b, 1e-6, {}, nullptr, &near);
  ASSERT_GT(near.size(), 0);
  const std::uint64_t id = world.geometry_id();
  Pose X = Pose::Identity();
  X.translate(Eigen::Vector3d(0.3, -0.2, 0.1));
  X.rotate(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()));
  world.set_pose(0, X);
  EXPECT_EQ(world.geometry_id(), id);
  for (double dx : {0.0, 0.0004, -0.0007}) {
    const Eigen::Vector3d a_W = X * Eigen::Vector3d(a + Eigen::Vector3d(dx, 0, 0));
    const Eigen::Vector3d b_W = X * Eigen::Vector3d(b + Eigen::Vector3d(dx, 0, 0));
    const auto with_list = world.sweep(a_W, b_W, 1e-6, {}, nullptr, &near);
    const auto from_tree = world.sweep(a_W, b_W, 1e-6);
    ASSERT_TRUE(from_tree);
    expect_same(with_list, from_tree, 0);
  }
}

// Every triangle of every object swept one by one (CollisionWorld::sweep_triangle): the
// earliest stop, or none.
std::optional<double> earliest_stop_of_all(const CollisionWorld& world, const Eigen::Vector3d& a,
                                           const Eigen::Vector3d& b, double skin_m) {
  std::optional<double> earliest;
  for (int o = 0; o < world.object_count(); ++o) {
    const auto n = static_cast<std::uint32_t>(world.shape(o).mesh().triangles.size());
    for (std::uint32_t t = 0; t < n; ++t) {
      const auto hit = world.sweep_triangle(TriangleRef{o, t}, a, b, skin_m);
      if (hit && (!earliest || hit->t_stop < *earliest)) earliest = hit->t_stop;
    }
  }
  return earliest;
}

TEST(SweepCandidates, ListAndTreeStopWhereEveryTriangleSweptOneByOneWould) {
  // The dual of the tests above, which hold the list to the tree: both to the whole mesh.
  // A walk that skipped a triangle the segment reaches would show here as a later stop or
  // none. On the surface in a turned pose, and with one triangle 1 km away, which leaves
  // the tree's grid over the surface alone (tree_grid.h) and that triangle's box clamped.
  for (const double stray_m : {0.0, 1000.0}) {
    SCOPED_TRACE(stray_m);
    auto mesh = wavy_grid(60, 0.1);
    if (stray_m > 0.0) {
      const auto first = static_cast<std::uint32_t>(mesh->vertices_m.size());
      mesh->vertices_m.emplace_back(stray_m, 0.0, 0.0);
      mesh->vertices_m.emplace_back(stray_m + 0.01, 0.0, 0.0);
      mesh->vertices_m.emplace_back(stray_m, 0.01, 0.0);
      mesh->triangles.push_back({first, first + 1, first + 2});
    }
    const Pose X_WO = pose_from_xyz_rpy(Eigen::Vector3d(0.3, -0.2, 0.9), Eigen::Vector3d(0.4, -0.3, 1.1));
    CollisionWorld world;
    world.add_object(std::make_shared<MeshBvh>(mesh), X_WO);
    std::mt19937_64 rng(314159);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    SweepCandidates near;
    int hits = 0;
    for (int k = 0; k < 1000; ++k) {
      // From within half a millimetre of the waves, most towards them, under a millimetre
      // long (one piece, so the stop is the triangle's own, bit for bit); now and then
      // along an axis of the mesh's frame, or of no length.
      const double x = 0.1 * u(rng), y = 0.1 * u(rng);
      const double above_m = 0.001 * u(rng) - 0.0005;
      const Eigen::Vector3d a_O(x, y, wave_height_m(x, y) + above_m);
      Eigen::Vector3d d_O(u(rng) - 0.5, u(rng) - 0.5, (u(rng) - 0.8) * (above_m > 0.0 ? 1.0 : -1.0));
      if (k % 10 == 0) d_O[k % 3] = 0.0;
      if (k % 25 == 0) d_O.setZero();
      const Eigen::Vector3d b_O = a_O + (d_O.norm() > 0.0 ? Eigen::Vector3d(0.0009 * u(rng) * d_O.normalized()) : d_O);
      const Eigen::Vector3d a = X_WO * a_O, b = X_WO * b_O;
      const std::optional<double> all = earliest_stop_of_all(world, a, b, 1e-6);
      for (SweepCandidates* list : {static_cast<SweepCandidates*>(nullptr), &near}) {
        SweepWork work;
        const auto hit = world.sweep(a, b, 1e-6, {}, &work, list);
        ASSERT_EQ(hit.has_value(), all.has_value()) << "sweep " << k;
        if (hit) {
          EXPECT_EQ(hit->t_stop, *all) << "sweep " << k;
        }
      }
      hits += all ? 1 : 0;
    }
    EXPECT_GT(hits, 300);
    EXPECT_GT(near.gathers(), 0);
  }
}

// A slide along a fine mesh, one skin over it, tests more triangles than the sweep's list
// of tested ones holds. The list must then keep the face under the slide's end, where the
// proxy looks for the face beyond an edge (first_met from the end towards the hand); a
// slide that tests few keeps every one.
TEST(SweepCandidates, ASlideOverAFineMeshKeepsTheFaceUnderItsEndAmongTheTested) {
  const double skin_m = 1e-6;
  CollisionWorld world;
  // Flat: 50 um squares over 10 mm.
  world.add_object(std::make_shared<MeshBvh>(grid(200, 0.01, [](double, double) { return 0.0; })),
                   Pose::Identity());
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(0.002, 0.008);
  std::uniform_real_distribution<double> turn(0.0, 2.0 * std::numbers::pi);
  int overflowing = 0;
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector3d a(u(rng), u(rng), skin_m);
    const double length_m = k % 2 == 0 ? 0.0005 : 0.00002;  // long slides and short ones
    const double angle = turn(rng);
    const Eigen::Vector3d b = a + length_m * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0);
    SweepWork work;
    EXPECT_FALSE(world.sweep(a, b, skin_m, {}, &work)) << "slide " << k;  // along the surface
    if (work.triangle_tests <= SweepWork::kMaxTested) {
      EXPECT_EQ(work.tested_count, work.triangle_tests) << "slide " << k;
      continue;
    }
    ++overflowing;
    ASSERT_EQ(work.tested_count, SweepWork::kMaxTested) << "slide " << k;
    int tests = 0;
    const auto beyond =
        world.first_met(std::span<const TriangleRef>(work.tested.data(), static_cast<std::size_t>(work.tested_count)),
                        b, b - Eigen::Vector3d(0.0, 0.0, 0.001), skin_m, 1e-6 * skin_m, tests);
    ASSERT_TRUE(beyond) << "slide " << k << ": the face under its end is not among the triangles kept";
    EXPECT_TRUE(world.projects_onto_triangle(beyond->where, b, 1e-9)) << "slide " << k;
  }
  EXPECT_GT(overflowing, 50);
}

}  // namespace
}  // namespace mhd
