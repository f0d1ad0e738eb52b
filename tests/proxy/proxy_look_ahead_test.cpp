// The look-ahead between ticks (proxy/proxy_look_ahead.h): it does the next tick's work on
// a copy, so that tick finds its data in the cache, and it changes nothing the proxy renders.
// Both halves are checked on a concave corner of a box, where one tick slides over three
// faces: with the HIP moving at a constant, exactly representable velocity the prediction
// is exact, so the look-ahead must end where the next tick ends, with as many sweeps; and a
// rig that looks ahead must render, tick for tick, bit for bit, what a rig that does not renders.
#include "proxy/proxy_look_ahead.h"

#include "proxy_test_rig.h"

#include <gtest/gtest.h>

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
    ASSERT_EQ(looking.state.near.gathers(), before.near.gathers());
    ASSERT_EQ(looking.state.near.size(), before.near.size());

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

}  // namespace
}  // namespace mhd
