// The other rigs on the floor, from the io thread's side: which sensor feeds which disc,
// and the velocity over a window of samples rather than from one sample to the next.
#include "haptic_server/floor_tracker.h"

#include <gtest/gtest.h>

namespace {

using namespace mhd;

OtherRigSensorList two_rigs() {
  OtherRigSensorList list;
  list.rigs[0] = OtherRigSensors{2, 3};
  list.rigs[1] = OtherRigSensors{7, 6};
  list.count = 2;
  return list;
}

TEST(FloorTracker, EachOtherSensorFeedsItsRigsUserOrBase) {
  const FloorTracker floor(two_rigs());
  EXPECT_EQ(floor.view().count, 2u);
  ASSERT_TRUE(floor.slot_of(2));
  EXPECT_EQ(floor.slot_of(2)->rig, 0u);
  EXPECT_FALSE(floor.slot_of(2)->base);
  EXPECT_TRUE(floor.slot_of(3)->base);
  EXPECT_EQ(floor.slot_of(6)->rig, 1u);
  EXPECT_TRUE(floor.slot_of(6)->base);
  EXPECT_FALSE(floor.slot_of(7)->base);
  EXPECT_FALSE(floor.slot_of(0));  // the rig's own sensors are not the floor's
  EXPECT_FALSE(floor.slot_of(4));
}

TEST(FloorTracker, TheVelocityIsTheDisplacementOverAWindowNotOneSample) {
  FloorTracker floor(two_rigs());
  const FloorSlot user{0, false};
  // 120 Hz samples of a user walking at (0.6, -0.3) m/s, with +-2 mm of alternating noise.
  for (int i = 0; i <= 60; ++i) {
    const double t = 10.0 + i / 120.0;
    const double noise = (i % 2 == 0 ? 0.002 : -0.002);
    floor.take(user, t, Eigen::Vector2d(1.0 + 0.6 * (t - 10.0) + noise, 2.0 - 0.3 * (t - 10.0)));
  }
  const TrackedDisc& d = floor.view().rigs[0].user;
  ASSERT_TRUE(d.known);
  EXPECT_DOUBLE_EQ(d.t_s, 10.5);
  EXPECT_NEAR(d.v_W.x(), 0.6, 0.05);  // sample to sample, the noise alone would be 0.48 m/s
  EXPECT_NEAR(d.v_W.y(), -0.3, 0.05);
  EXPECT_FALSE(floor.view().rigs[0].base.known);  // nothing came from its base
  EXPECT_FALSE(floor.view().rigs[1].user.known);
}

TEST(FloorTracker, AnOlderSampleThanTheNewestIsIgnored) {
  FloorTracker floor(two_rigs());
  const FloorSlot base{1, true};
  floor.take(base, 5.0, Eigen::Vector2d(1.0, 1.0));
  floor.take(base, 4.9, Eigen::Vector2d(9.0, 9.0));
  EXPECT_DOUBLE_EQ(floor.view().rigs[1].base.t_s, 5.0);
  EXPECT_EQ(floor.view().rigs[1].base.p_W, Eigen::Vector2d(1.0, 1.0));
  floor.take(base, 5.2, Eigen::Vector2d(1.1, 1.0));  // dual: a newer one is taken
  EXPECT_EQ(floor.view().rigs[1].base.p_W, Eigen::Vector2d(1.1, 1.0));
  EXPECT_NEAR(floor.view().rigs[1].base.v_W.x(), 0.5, 1e-9);
}

}  // namespace
