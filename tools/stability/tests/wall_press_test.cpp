// The sampled wall and the impedance hand: a wall well inside Colgate and Schenkel's
// passivity bound settles, one well beyond it oscillates, at 1 kHz and at 10 kHz; a soft
// wall settles where the hand's spring and the wall's share the press.
#include "wall_press.h"

#include <gtest/gtest.h>

namespace mhd::stability {
namespace {

TEST(PassivityBound, IsTwiceThePhysicalDampingLessTheVirtualOverThePeriod) {
  EXPECT_DOUBLE_EQ(passivity_bound_N_per_m(6.5, 0.0, 1e-3), 13000.0);
  EXPECT_DOUBLE_EQ(passivity_bound_N_per_m(6.5, -1.0, 1e-4), 110000.0);
}

class WallPressAtRate : public ::testing::TestWithParam<double> {};

TEST_P(WallPressAtRate, SettlesInsideThePassivityBoundAndOscillatesWellBeyondIt) {
  WallPressSettings s;
  s.rate_hz = GetParam();
  const double bound = passivity_bound_N_per_m(s.hand.damping_Ns_per_m, 0.0, 1.0 / s.rate_hz);
  s.wall_stiffness_N_per_m = 0.5 * bound;
  const WallPressFigures inside = press_wall(s);
  EXPECT_TRUE(inside.stable) << inside.force_ptp_previous_N << " then " << inside.force_ptp_last_N;
  EXPECT_LT(inside.force_ptp_last_N, 0.1 * inside.force_ptp_previous_N + 1e-3);  // decays quickly
  s.wall_stiffness_N_per_m = 3.0 * bound;
  const WallPressFigures beyond = press_wall(s);
  EXPECT_FALSE(beyond.stable) << beyond.force_ptp_previous_N << " then " << beyond.force_ptp_last_N;
  EXPECT_GT(beyond.force_ptp_last_N, 1.0);
}

INSTANTIATE_TEST_SUITE_P(Rates, WallPressAtRate, ::testing::Values(1000.0, 10000.0));

TEST(WallPress, ASoftWallSharesThePressWithTheHandsSpring) {
  WallPressSettings s;
  s.wall_stiffness_N_per_m = 600.0;  // the dolphin's skin
  const WallPressFigures r = press_wall(s);
  ASSERT_TRUE(r.stable);
  // Springs in series: F = k_hand K / (k_hand + K) x depth.
  const double k = s.hand.stiffness_N_per_m;
  EXPECT_NEAR(r.mean_force_last_N, k * 600.0 / (k + 600.0) * s.press_depth_m, 0.01);
}

}  // namespace
}  // namespace mhd::stability
