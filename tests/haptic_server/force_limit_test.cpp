// The run's force limit (engine/haptic_server/force_limit.h) on both sides of the rule: a
// scene below the device's limit lowers it, silently; a scene above gets the device's
// limit and a warning naming both.
#include "haptic_server/force_limit.h"

#include <gtest/gtest.h>

namespace {

using mhd::force_limit_for;

TEST(ForceLimit, ASceneBelowTheDevicesLimitLowersItWithoutAWarning) {
  const mhd::ForceLimit l = force_limit_for(3.0, 8.5, "sim_phantom");
  EXPECT_EQ(l.max_force_N, 3.0);
  EXPECT_FALSE(l.warning);
}

TEST(ForceLimit, ASceneAtTheDevicesLimitKeepsItWithoutAWarning) {
  const mhd::ForceLimit l = force_limit_for(8.5, 8.5, "sim_phantom");
  EXPECT_EQ(l.max_force_N, 8.5);
  EXPECT_FALSE(l.warning);
}

TEST(ForceLimit, ASceneAboveTheDevicesLimitGetsTheDevicesLimitAndAWarning) {
  const mhd::ForceLimit l = force_limit_for(8.5, 3.3, "touch");
  EXPECT_EQ(l.max_force_N, 3.3);
  ASSERT_TRUE(l.warning);
  EXPECT_EQ(*l.warning,
            "<haptics max_force_N> is 8.5 N, more than device 'touch' allows (3.3 N, its device_info): forces are "
            "limited to 3.3 N");
}

}  // namespace
