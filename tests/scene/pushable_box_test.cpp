// scenes/pushable_box.xml through XML -> compiled scene -> moving world -> proxy: a hand
// pushes the box away along the floor, judged by verify::drive_moving_proxy (the exact
// oracle in each object's frame): the box moves with the hand, the proxy never enters
// it or the floor, and once the hand backs off it is at the hand with no force.

#include "support/scene_fixture.h"
#include "verification/moving_drive.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace mhd::test {
namespace {

class PushableBoxScene : public SceneFixture {
 protected:
  void SetUp() override { ASSERT_NO_FATAL_FAILURE(load("scenes/pushable_box.xml")); }
};

TEST_F(PushableBoxScene, TheBoxIsPushableAndTheFloorStill) {
  ASSERT_EQ(scene().object_names.size(), 2u);
  ASSERT_TRUE(scene().dynamics[0].has_value());
  EXPECT_DOUBLE_EQ(scene().dynamics[0]->mass_kg, 0.6);
  EXPECT_DOUBLE_EQ(scene().dynamics[0]->friction, 0.4);
  EXPECT_FALSE(scene().dynamics[1].has_value());
  EXPECT_FALSE(scene().motions[0].has_value());
}

TEST_F(PushableBoxScene, AHandPushesTheBoxAwayAndIsFreeWhenItBacksOff) {
  // The near face is at z = -0.425 m; the hand at 75 mm (mid height) comes from 20 mm
  // before it, pushes along -z at 0.15 m/s for 1.5 s, then backs off at 0.3 m/s.
  const auto hip = [](double t) {
    return Eigen::Vector3d(0.0, 0.075, -0.405 - 0.15 * std::min(t, 1.5) + 0.3 * std::clamp(t - 1.6, 0.0, 1.0));
  };
  std::vector<Eigen::Vector3d> path;
  for (int k = 0; k <= 2700; ++k) path.push_back(hip(k * 1e-3));
  const MovingDrive d =
      drive_moving_proxy(scene().world, scene().motions, scene().materials, scene().proxy, path, 1000.0, scene().dynamics);
  EXPECT_EQ(d.crossings, 0u);
  EXPECT_EQ(d.inside, 0u);
  EXPECT_EQ(d.not_followed, 0u);
  EXPECT_EQ(d.free_force, 0u);
  const double z0_m = -0.5;
  const double z_pushed_m = d.X_WO[1599][0].translation().z();
  EXPECT_LT(z_pushed_m, z0_m - 0.15) << "pushed away about as far as the hand went past the face (0.205 m)";
  EXPECT_GT(z_pushed_m, z0_m - 0.22);
  double max_N = 0.0;
  for (const ProxyOutput& o : d.out) max_N = std::max(max_N, o.force_W.norm());
  EXPECT_GT(max_N, 0.4 * 0.6 * 9.81) << "the hand felt the box's friction";
  EXPECT_LT(max_N, scene().proxy.max_force_N);
  EXPECT_FALSE(d.out.back().in_contact);
  EXPECT_EQ(d.out.back().force_W, Eigen::Vector3d::Zero());
  EXPECT_EQ(d.out.back().proxy_W, hip(2.7));
}

}  // namespace
}  // namespace mhd::test
