// scenes/moving_objects.xml through XML -> compiled scene -> moving world -> proxy, a still
// hand in the way of each moving object, judged by verify::drive_moving_proxy (the exact
// oracle in each object's frame): never a crossing or a proxy inside, and the dual, never
// a proxy held off a hand it could reach, nor a force with the hand in view.

#include "support/scene_fixture.h"
#include "verification/moving_drive.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mhd::test {
namespace {

class MovingObjectsScene : public SceneFixture {
 protected:
  void SetUp() override { ASSERT_NO_FATAL_FAILURE(load("scenes/moving_objects.xml")); }

  // A hand held still at p_W for duration_s, at 1 kHz.
  MovingDrive hold_hand(const Eigen::Vector3d& p_W, double duration_s) {
    const std::vector<Eigen::Vector3d> path(static_cast<std::size_t>(duration_s * 1000.0) + 1, p_W);
    return drive_moving_proxy(scene().world, scene().motions, scene().materials, scene().proxy, path, 1000.0);
  }

  static void expect_contract(const MovingDrive& d) {
    EXPECT_EQ(d.crossings, 0u);
    EXPECT_EQ(d.inside, 0u);
    EXPECT_EQ(d.not_followed, 0u);
    EXPECT_EQ(d.free_force, 0u);
    EXPECT_EQ(d.squeezes, 0u);
  }
  // The output of the tick at t_s (ticks are numbered from 1 at 1 ms).
  static const ProxyOutput& at(const MovingDrive& d, double t_s) {
    return d.out.at(static_cast<std::size_t>(t_s * 1000.0 + 0.5) - 1);
  }
};

TEST_F(MovingObjectsScene, EveryObjectMovesAndTheStillOnesStay) {
  for (std::size_t i = 0; i < scene().object_names.size(); ++i) {
    EXPECT_EQ(scene().motions[i].has_value(), scene().object_names[i] != "floor") << scene().object_names[i];
  }
}

TEST_F(MovingObjectsScene, ThePaddlePushesAStillHandAndLetsItGo) {
  // The paddle's front face reaches z = -0.45 m at 1.06 s on its way out and leaves it
  // at 1.54 s on its way back.
  const MovingDrive d = hold_hand(Eigen::Vector3d(0.0, 1.0, -0.45), 2.2);
  expect_contract(d);
  EXPECT_GT(d.pushes, 0u);
  EXPECT_FALSE(at(d, 0.9).in_contact);
  EXPECT_EQ(at(d, 0.9).force_W, Eigen::Vector3d::Zero());
  ASSERT_TRUE(at(d, 1.3).in_contact);
  EXPECT_GT(at(d, 1.3).force_W.z(), 8.0);  // towards the user, at the 8.5 N limit
  EXPECT_LE(at(d, 1.3).force_W.norm(), scene().proxy.max_force_N + 1e-9);
  EXPECT_FALSE(at(d, 2.0).in_contact);
  EXPECT_EQ(at(d, 2.0).force_W, Eigen::Vector3d::Zero());
}

TEST_F(MovingObjectsScene, TheSpinnersCornersSweepPastAHandBesideIt) {
  // 70 mm off the axis: the corners (85 mm) reach the hand four times a turn (4 s).
  const MovingDrive d = hold_hand(Eigen::Vector3d(0.37, 1.0, -0.45), 4.0);
  expect_contract(d);
  EXPECT_GT(d.contact_ticks, 200u);
  EXPECT_LT(d.contact_ticks, 3800u);
}

TEST_F(MovingObjectsScene, TheBobberLiftsAHandAboveIt) {
  // The sphere's top rises from 1.06 m to 1.12 m and back each 2 s; the hand at 1.09 m.
  const MovingDrive d = hold_hand(Eigen::Vector3d(-0.3, 1.09, -0.45), 2.5);
  expect_contract(d);
  EXPECT_FALSE(at(d, 0.3).in_contact);
  ASSERT_TRUE(at(d, 1.0).in_contact);
  EXPECT_GT(at(d, 1.0).force_W.y(), 8.0);
  EXPECT_FALSE(at(d, 2.0).in_contact);
}

}  // namespace
}  // namespace mhd::test
