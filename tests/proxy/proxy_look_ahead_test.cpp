// The look-ahead between ticks (proxy/proxy_look_ahead.h): it does the next tick's work on
// a copy, so that tick finds its data in the cache, and it changes nothing the proxy renders.
// Both halves are checked on a concave corner of a box, where one tick slides over three
// faces: with the HIP moving at a constant, exactly representable velocity the prediction
// is exact, so the look-ahead must end where the next tick ends, with as many sweeps; and a
// rig that looks ahead must render, tick for tick, bit for bit, what a rig that does not renders.
// On a fine slope, a candidate list the look-ahead gathered is the next tick's.
#include "proxy/proxy_look_ahead.h"

#include "proxy_test_rig.h"

#include <gtest/gtest.h>

#include <array>

namespace mhd {
namespace {

using test::ProxyRig;

// Powers of two: the HIPs below and their extrapolations are exact in double.
constexpr double kStep_m = 1.0 / 1024.0;  // about 1 mm a tick

// An inside corner: a floor (y = 0), a wall at x = 0 facing +x and a wall at z = 0 facing +z.
void add_corner(ProxyRig& rig) {
  const double s = 0.25;
  rig.add(test::quad({0, 0, 0}, {0, 0, s}, {s, 0, s}, {s, 0, 0}));  // floor, faces +y
  rig.add(test::quad({0, 0, 0}, {0, s, 0}, {0, s, s}, {0, 0, s}));  // wall, faces +x
  rig.add(test::quad({0, 0, 0}, {s, 0, 0}, {s, s, 0}, {0, s, 0}));  // wall, faces +z
}

// The HIP of tick i: from above the floor, in and down towards the corner at a constant velocity.
Eigen::Vector3d hip_at(int i) {
  const Eigen::Vector3d start(0.0625, 0.03125, 0.0625);
  const Eigen::Vector3d step(-kStep_m, -kStep_m, -kStep_m);
  return start + static_cast<double>(i) * step;
}

TEST(ProxyLookAhead, PredictsTheNextHipFromTheLastTwo) {
  ProxyRig rig;
  add_corner(rig);
  ProxyLookAhead look_ahead;
  (void)rig.step(hip_at(0));
  // One HIP seen: nothing to extrapolate, it looks at the HIP where it is.
  EXPECT_EQ(look_ahead.run(rig.world, rig.materials, rig.settings, rig.state, test::kProxyTestDt_s).p_W_hip, hip_at(0));
  (void)rig.step(hip_at(1));
  EXPECT_EQ(look_ahead.run(rig.world, rig.materials, rig.settings, rig.state, test::kProxyTestDt_s).p_W_hip, hip_at(2));
  // A proxy not started yet has nothing to look ahead for, and the prediction starts again.
  ProxyState fresh;
  EXPECT_FALSE(look_ahead.run(rig.world, rig.materials, rig.settings, fresh, test::kProxyTestDt_s).ran);
  (void)rig.step(hip_at(2));
  EXPECT_EQ(look_ahead.run(rig.world, rig.materials, rig.settings, rig.state, test::kProxyTestDt_s).p_W_hip, hip_at(2));
}

TEST(ProxyLookAhead, DoesTheNextTicksWorkAndChangesNothingTheProxyRenders) {
  ProxyRig looking;
  ProxyRig plain;
  add_corner(looking);
  add_corner(plain);
  ProxyLookAhead look_ahead;
  int ticks_in_contact = 0;
  int ticks_with_three_planes = 0;
  for (int i = 0; i < 90; ++i) {
    const ProxyOutput a = looking.step(hip_at(i));
    const ProxyOutput b = plain.step(hip_at(i));
    ASSERT_EQ(a.proxy_W, b.proxy_W) << "tick " << i;
    ASSERT_EQ(a.force_W, b.force_W) << "tick " << i;
    ASSERT_EQ(a.sweeps, b.sweeps) << "tick " << i;
    ASSERT_EQ(a.plane_count, b.plane_count) << "tick " << i;
    if (a.in_contact) ++ticks_in_contact;
    if (a.plane_count == 3) ++ticks_with_three_planes;

    const ProxyState before = looking.state;
    const LookAheadReport ahead =
        look_ahead.run(looking.world, looking.materials, looking.settings, looking.state, test::kProxyTestDt_s);
    // Nothing of the state moved.
    ASSERT_EQ(looking.state.proxy_W, before.proxy_W);
    ASSERT_EQ(looking.state.p_W_hip, before.p_W_hip);
    ASSERT_EQ(looking.state.hip_velocity_W, before.hip_velocity_W);
    ASSERT_EQ(looking.state.plane_count, before.plane_count);
    // Only the list of triangles near the proxy may have grown (what the copy gathered).
    ASSERT_GE(looking.state.near.gathers(), before.near.gathers());

    // From the second tick the prediction is the next HIP, so the look-ahead is the next tick.
    if (i >= 1 && i + 1 < 90) {
      ProxyState copy = plain.state;
      const ProxyOutput n =
          step_proxy(plain.world, plain.materials, plain.settings, copy, hip_at(i + 1), test::kProxyTestDt_s);
      EXPECT_EQ(ahead.p_W_hip, hip_at(i + 1)) << "tick " << i;
      EXPECT_EQ(ahead.proxy_W, n.proxy_W) << "tick " << i;
      EXPECT_EQ(ahead.sweeps, n.sweeps) << "tick " << i;
    }
  }
  // The path reaches the corner: contact on the floor, then the three faces at once.
  EXPECT_GT(ticks_in_contact, 30);
  EXPECT_GT(ticks_with_three_planes, 10);
}

// An n x n grid of 2 n^2 triangles over x, z in [0, size_m], on the plane y = x (facing
// up and towards -x): fine enough that the proxy sliding over it leaves the box of its
// list every few ticks, and sloped so that a sweep hovering just above it has triangles in
// its box.
TriangleMesh fine_slope(int n, double size_m) {
  TriangleMesh mesh;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const double x = size_m * i / n;
      mesh.vertices_m.emplace_back(x, x, size_m * j / n);
    }
  }
  auto id = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      mesh.triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
    }
  }
  return mesh;
}

TEST(ProxyLookAhead, TheNextTickFindsTheTrianglesItGatheredListed) {
  ProxyRig looking;
  ProxyRig plain;
  looking.add(fine_slope(200, 0.1));
  plain.add(fine_slope(200, 0.1));
  ProxyLookAhead look_ahead;
  // From 1 mm above the slope to 1 mm into it, sliding up it 0.5 mm a tick, then lifted to
  // hover 0.2 mm above it and moving on: one free-space sweep a tick, beside it.
  constexpr int kSlideEnd = 140;
  const Eigen::Vector3d up_slope = Eigen::Vector3d(1.0, 1.0, 0.0).normalized();
  const Eigen::Vector3d normal = Eigen::Vector3d(-1.0, 1.0, 0.0).normalized();
  const auto hip = [&](int i) {
    const double height_m = i < 20 ? 0.001 - 0.0001 * i : (i < kSlideEnd ? -0.001 : 0.0002);
    const double along_m = i < 20 ? 0.0 : 0.0005 * (i - 20);
    return Eigen::Vector3d(Eigen::Vector3d(0.02, 0.02, 0.05) + along_m * up_slope + height_m * normal);
  };
  // Gathers made within the ticks (not between them), sliding and hovering.
  std::array<int, 2> plain_gathers{};
  std::array<int, 2> looking_gathers{};
  int ticks_in_contact = 0;
  for (int i = 0; i < kSlideEnd + 60; ++i) {
    const int plain_before = plain.state.near.gathers();
    const int looking_before = looking.state.near.gathers();
    const ProxyOutput a = looking.step(hip(i));
    const ProxyOutput b = plain.step(hip(i));
    const std::size_t phase = i < kSlideEnd ? 0 : 1;
    plain_gathers[phase] += plain.state.near.gathers() - plain_before;
    looking_gathers[phase] += looking.state.near.gathers() - looking_before;
    // The list changes what a sweep costs, never its answer.
    ASSERT_EQ(a.proxy_W, b.proxy_W) << "tick " << i;
    ASSERT_EQ(a.force_W, b.force_W) << "tick " << i;
    ASSERT_EQ(a.sweeps, b.sweeps) << "tick " << i;
    ASSERT_EQ(a.triangle_tests, b.triangle_tests) << "tick " << i;
    if (a.in_contact) ++ticks_in_contact;
    ASSERT_TRUE(i < kSlideEnd || !a.in_contact) << "tick " << i;
    (void)look_ahead.run(looking.world, looking.materials, looking.settings, looking.state, test::kProxyTestDt_s);
  }
  EXPECT_GT(ticks_in_contact, 100);
  // Sliding 60 mm, the proxy leaves many lists' boxes; the plain rig gathers each in a tick.
  EXPECT_GT(plain_gathers[0], 20);
  // With the look-ahead the next tick finds its triangles listed: the gathers happened
  // between ticks.
  EXPECT_LE(looking_gathers[0] * 10, plain_gathers[0]);
  // Hovering, a tick's one sweep gathers no more often for the look-ahead's walks.
  EXPECT_LE(looking_gathers[1], plain_gathers[1]);
}

}  // namespace
}  // namespace mhd
