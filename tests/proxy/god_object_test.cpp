#include "proxy/god_object.h"

#include "proxy_test_rig.h"

#include "geometry/primitive_mesh.h"

#include <gtest/gtest.h>

#include <random>

namespace mhd {
namespace {

using V = Eigen::Vector3d;

using test::quad;
using test::stiff;
using Rig = test::ProxyRig;

TEST(GodObject, FreeSpaceProxyFollowsTheHipWithZeroForce) {
  Rig rig;
  rig.add(quad(V(-1, -1, 0), V(1, -1, 0), V(1, 1, 0), V(-1, 1, 0)), stiff(1000));
  reset_proxy(rig.state, V(0, 0, 0.1));
  const auto out = rig.move(V(0, 0, 0.1), V(0.05, 0.02, 0.05), 10);
  EXPECT_FALSE(out.in_contact);
  EXPECT_EQ(out.force_W, V::Zero());
  EXPECT_TRUE(out.proxy_W.isApprox(V(0.05, 0.02, 0.05)));
}

TEST(GodObject, WallForceIsStiffnessTimesDepthAlongTheNormal) {
  Rig rig;
  rig.settings.max_force_N = 100;
  rig.add(quad(V(-1, -1, 0), V(1, -1, 0), V(1, 1, 0), V(-1, 1, 0)), stiff(1200));
  reset_proxy(rig.state, V(0.1, 0.2, 0.01));
  for (double depth : {0.001, 0.004, 0.0075}) {
    const auto out = rig.move(V(0.1, 0.2, 0.01), V(0.1, 0.2, -depth), 20);
    ASSERT_TRUE(out.in_contact);
    EXPECT_EQ(out.plane_count, 1);
    // The proxy rests one skin above the surface, straight above the HIP.
    EXPECT_NEAR(out.proxy_W.z(), rig.settings.skin_m, 1e-12);
    EXPECT_NEAR(out.force_W.z(), 1200 * (depth + rig.settings.skin_m), 1e-9);
    EXPECT_NEAR(out.force_W.x(), 0.0, 1e-9);
    EXPECT_NEAR(out.force_W.y(), 0.0, 1e-9);
    rig.move(V(0.1, 0.2, -depth), V(0.1, 0.2, 0.01), 20);
  }
}

TEST(GodObject, ProxySlidesAlongAFrictionlessWall) {
  Rig rig;
  rig.add(quad(V(-1, -1, 0), V(1, -1, 0), V(1, 1, 0), V(-1, 1, 0)), stiff(1000));
  reset_proxy(rig.state, V(0, 0, 0.01));
  rig.move(V(0, 0, 0.01), V(0, 0, -0.005), 15);
  const auto out = rig.move(V(0, 0, -0.005), V(0.05, 0, -0.005), 100);
  EXPECT_NEAR(out.proxy_W.x(), 0.05, 1e-9);
  EXPECT_NEAR(out.force_W.x(), 0.0, 1e-9);
}

TEST(GodObject, ContactPlanesAreRebuiltWhenTheObjectMoves) {
  // Last tick's contact plane seeds the next tick; it must come from the triangle's
  // current pose, so a wall that moves away is followed, not a stale plane.
  Rig rig;
  rig.settings.max_force_N = 100;
  rig.add(quad(V(-1, -1, 0), V(1, -1, 0), V(1, 1, 0), V(-1, 1, 0)), stiff(1000));
  reset_proxy(rig.state, V(0, 0, 0.01));
  const V hip(0, 0, -0.004);
  ASSERT_TRUE(rig.move(V(0, 0, 0.01), hip, 14).in_contact);
  Pose lowered = Pose::Identity();
  lowered.translation() = V(0, 0, -0.001);
  rig.world.set_pose(0, lowered);
  const auto out = rig.step(hip);
  EXPECT_NEAR(out.proxy_W.z(), -0.001 + rig.settings.skin_m, 1e-12);
  EXPECT_NEAR(out.force_W.z(), 1000 * (0.003 + rig.settings.skin_m), 1e-9);
}

TEST(GodObject, ForceIsClampedToTheMaximum) {
  Rig rig;
  rig.settings.max_force_N = 3.0;
  rig.add(quad(V(-1, -1, 0), V(1, -1, 0), V(1, 1, 0), V(-1, 1, 0)), stiff(2000));
  reset_proxy(rig.state, V(0, 0, 0.01));
  const auto out = rig.move(V(0, 0, 0.01), V(0, 0, -0.05), 60);
  EXPECT_TRUE(out.force_clamped);
  EXPECT_NEAR(out.force_W.norm(), 3.0, 1e-12);
  EXPECT_GT(out.force_W.z(), 0.0);
}

TEST(GodObject, NonFiniteHipGivesZeroForceAndHoldsTheProxy) {
  Rig rig;
  rig.add(quad(V(-1, -1, 0), V(1, -1, 0), V(1, 1, 0), V(-1, 1, 0)), stiff(1000));
  reset_proxy(rig.state, V(0, 0, 0.01));
  const auto before = rig.move(V(0, 0, 0.01), V(0, 0, -0.004), 10);
  ASSERT_TRUE(before.in_contact);
  const auto out = rig.step(V(std::nan(""), 0, 0));
  EXPECT_EQ(out.force_W, V::Zero());
  EXPECT_EQ(out.proxy_W, before.proxy_W);
  const auto inf = rig.step(V(0, std::numeric_limits<double>::infinity(), 0));
  EXPECT_EQ(inf.force_W, V::Zero());
}

TEST(GodObject, ConcaveCornerSolvesAllThreePlanesWithinOneTick) {
  // Inside corner of a room: floor z = 0, walls x = 0 and y = 0, free space at x, y, z > 0.
  Rig rig;
  rig.settings.max_force_N = 100;
  rig.add(quad(V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0)), stiff(1000));
  rig.add(quad(V(0, 0, 0), V(0, 1, 0), V(0, 1, 1), V(0, 0, 1)), stiff(1000));
  rig.add(quad(V(0, 0, 0), V(0, 0, 1), V(1, 0, 1), V(1, 0, 0)), stiff(1000));
  reset_proxy(rig.state, V(0.05, 0.05, 0.05));
  // One tick takes the HIP from free space deep behind all three planes.
  const auto out = rig.step(V(-0.002, -0.003, -0.004));
  EXPECT_EQ(out.plane_count, 3);
  const double s = rig.settings.skin_m;
  EXPECT_TRUE(out.proxy_W.isApprox(V(s, s, s), 1e-9)) << out.proxy_W.transpose();
  EXPECT_TRUE(out.force_W.isApprox(1000 * (V(s, s, s) - V(-0.002, -0.003, -0.004)), 1e-9));
}

TEST(GodObject, ProxyEnteringThroughABoxFaceStaysOnThatFace) {
  // The god-object is history-dependent: pressed in through the top face, the proxy
  // stays on it even where the side face is nearer the HIP.
  Rig rig;
  rig.settings.max_force_N = 100;
  rig.add(make_box_mesh(V(0.2, 0.2, 0.2)), stiff(1000));  // faces at +-0.1
  reset_proxy(rig.state, V(0.0995, 0.0, 0.12));
  const auto out = rig.move(V(0.0995, 0.0, 0.12), V(0.0995, 0.0, 0.097), 10);
  EXPECT_NEAR(out.proxy_W.z(), 0.1 + rig.settings.skin_m, 1e-12);
  EXPECT_NEAR(out.proxy_W.x(), 0.0995, 1e-12);
  EXPECT_NEAR(out.force_W.x(), 0.0, 1e-9);
}

// Roof ridge along y at x = z = 0, faces sloping down 14 degrees to either side: an
// obtuse convex edge like those between the facets of a smooth mesh.
TriangleMesh roof() {
  TriangleMesh m;
  m.vertices_m = {V(0, -1, 0), V(0, 1, 0), V(1, 1, -0.25), V(1, -1, -0.25), V(-1, 1, -0.25), V(-1, -1, -0.25)};
  m.triangles = {{0, 3, 2}, {0, 2, 1}, {0, 1, 4}, {0, 4, 5}};
  return m;
}

// Height of the roof's surface above x.
double roof_z(double x) { return -0.25 * std::abs(x); }

TEST(GodObject, ProxyLeavesAFaceAtItsConvexEdgeWithinTheSameTick) {
  Rig rig;
  rig.settings.max_force_N = 100;
  rig.add(roof(), stiff(1000));
  auto under_surface = [](double x) { return V(x, 0, roof_z(x) - 0.003); };
  reset_proxy(rig.state, V(0.05, 0, 0.01));
  rig.move(V(0.05, 0, 0.01), under_surface(0.05), 20);
  double max_magnitude_jump = 0.0;
  double last_magnitude = rig.step(under_surface(0.05)).force_W.norm();
  for (int i = 1; i <= 1000; ++i) {
    const auto out = rig.step(under_surface(0.05 - 1e-4 * i));  // 0.1 m/s over the ridge
    ASSERT_TRUE(out.in_contact);
    // Always resting on the surface (one skin above a face), never floating on the
    // extension of a face it has slid off.
    const double gap = (out.proxy_W.z() - roof_z(out.proxy_W.x())) / std::sqrt(1 + 0.25 * 0.25);
    ASSERT_NEAR(gap, rig.settings.skin_m, 1e-9) << "tick " << i << " proxy " << out.proxy_W.transpose();
    max_magnitude_jump = std::max(max_magnitude_jump, std::abs(out.force_W.norm() - last_magnitude));
    last_magnitude = out.force_W.norm();
  }
  // The proxy keeps to face A until A's projection of the HIP passes the ridge, so the
  // force grows to the HIP's depth below A's plane (3.3 N) before dropping to its depth
  // below B (2.9 N): the god-object's hysteresis at a 28-degree edge, and no more.
  EXPECT_LT(max_magnitude_jump, 0.45);
  EXPECT_GT(max_magnitude_jump, 0.3);
}

TEST(GodObject, ForceShadingMakesTheForceContinuousOverAFacetEdge) {
  auto max_force_jump = [](bool shading) {
    Rig rig;
    rig.settings.max_force_N = 100;
    HapticMaterial mat = stiff(1000);
    mat.force_shading = shading;
    rig.add(roof(), mat);
    auto under_surface = [](double x) { return V(x, 0, roof_z(x) - 0.003); };
    reset_proxy(rig.state, V(0.05, 0, 0.01));
    rig.move(V(0.05, 0, 0.01), under_surface(0.05), 20);
    V last = rig.step(under_surface(0.05)).force_W;
    double jump = 0.0;
    for (int i = 1; i <= 1000; ++i) {
      const auto out = rig.step(under_surface(0.05 - 1e-4 * i));
      jump = std::max(jump, (out.force_W - last).norm());
      last = out.force_W;
    }
    return jump;
  };
  // Faces 28 degrees apart at ~3 N: without shading the direction flips (~1.5 N jump);
  // with vertex normals interpolated only the hysteresis step in magnitude is left.
  const double unshaded = max_force_jump(false);
  const double shaded = max_force_jump(true);
  EXPECT_GT(unshaded, 1.3);
  EXPECT_LT(shaded, 0.45);
}

TEST(GodObject, StaticFrictionHoldsUntilTheConeIsLeftThenSlidesAtTheDynamicRim) {
  Rig rig;
  rig.settings.max_force_N = 100;
  HapticMaterial mat = stiff(1000);
  mat.static_friction = 0.5;
  mat.dynamic_friction = 0.3;
  rig.add(quad(V(-1, -1, 0), V(1, -1, 0), V(1, 1, 0), V(-1, 1, 0)), mat);
  reset_proxy(rig.state, V(0, 0, 0.01));
  const double depth = 0.004;
  rig.move(V(0, 0, 0.01), V(0, 0, -depth), 14);
  const V anchor = rig.step(V(0, 0, -depth)).proxy_W;
  // Drag sideways 0.1 mm per tick: the proxy stays while the tangential force is below
  // mu_s * normal force, and slips the first time it would exceed it.
  double max_ratio_while_stuck = 0.0;
  bool slipped = false;
  for (int i = 1; i <= 60 && !slipped; ++i) {
    const auto out = rig.step(V(1e-4 * i, 0, -depth));
    const double ratio = std::abs(out.force_W.x()) / out.force_W.z();
    if (out.sticking) {
      EXPECT_EQ(out.proxy_W, anchor);
      max_ratio_while_stuck = std::max(max_ratio_while_stuck, ratio);
    } else {
      slipped = true;
      EXPECT_GT(1e-4 * i, 0.5 * depth);            // it held until the static cone was left
      EXPECT_NEAR(ratio, 0.3, 1e-6);               // and slides on the dynamic rim
    }
  }
  EXPECT_TRUE(slipped);
  EXPECT_LE(max_ratio_while_stuck, 0.5 + 1e-9);
  EXPECT_GT(max_ratio_while_stuck, 0.4);
}

TEST(GodObject, DampingResistsPenetrationButNeverPullsIn) {
  Rig rig;
  rig.settings.max_force_N = 100;
  HapticMaterial mat = stiff(1000);
  mat.damping_Ns_per_m = 5.0;
  rig.add(quad(V(-1, -1, 0), V(1, -1, 0), V(1, 1, 0), V(-1, 1, 0)), mat);
  reset_proxy(rig.state, V(0, 0, 0.01));
  const auto pushing = rig.move(V(0, 0, 0.01), V(0, 0, -0.002), 12);  // 1 m/s inwards
  EXPECT_GT(pushing.force_W.z(), 1000 * 0.002);
  const auto leaving = rig.step(V(0, 0, -0.0001));  // jumps out fast
  EXPECT_GE(leaving.force_W.z(), 0.0);
}

TEST(GodObject, ThinSheetHoldsTheProxyOnTheSideItCameFrom) {
  Rig rig;
  rig.settings.max_force_N = 100;
  rig.add(quad(V(-1, -1, 0), V(1, -1, 0), V(1, 1, 0), V(-1, 1, 0)), stiff(500));
  reset_proxy(rig.state, V(0.0, 0.0, -0.01));  // below the sheet
  const auto out = rig.move(V(0, 0, -0.01), V(0, 0, 0.02), 30);  // through and 2 cm past
  EXPECT_LT(out.proxy_W.z(), 0.0);
  EXPECT_LT(out.force_W.z(), 0.0);  // pushes back down
}

TEST(GodObject, FastStrokesNeverPassThroughAFineMeshOfTinyTriangles) {
  // A 2 mm square tiled with 20 µm quads (triangles of 2e-10 m²).
  TriangleMesh mesh;
  const int n = 100;
  const double cell = 2e-5;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) mesh.vertices_m.emplace_back(i * cell - 1e-3, j * cell - 1e-3, 0.0);
  auto id = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  Rig rig;
  rig.settings.max_force_N = 1e6;
  rig.add(std::move(mesh), stiff(1000));
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-9e-4, 9e-4);
  int ended_below = 0;
  for (int stroke = 0; stroke < 300; ++stroke) {
    // Start above; pass through the sheet at up to ~1 m/s with random grazing angles.
    const V start(u(rng), u(rng), 1e-3);
    const V end(u(rng), u(rng), -1e-3);
    reset_proxy(rig.state, start);
    const auto out = rig.move(start, end, 3);
    if (out.proxy_W.z() <= 0.0) ++ended_below;
  }
  EXPECT_EQ(ended_below, 0);
}

}  // namespace
}  // namespace mhd
