// The other rigs' keep-outs at a moment (planner/floor_view.h): extrapolated and grown by
// their age, and not current when one is unknown or old.
#include "planner/floor_view.h"

#include <gtest/gtest.h>

#include <limits>

namespace mhd {
namespace floor_view_test {

FloorView one_rig(double user_t_s, double base_t_s) {
  FloorView view;
  view.count = 1;
  view.rigs[0].user = TrackedDisc{true, user_t_s, {1.0, 2.0}, {0.4, -0.3}};  // 0.5 m/s
  view.rigs[0].base = TrackedDisc{true, base_t_s, {3.0, 0.0}, {0.0, 0.0}};
  return view;
}

TEST(FloorView, NoOtherRigsGiveNoKeepOutsAndAreCurrent) {
  const FloorKeepOuts k = floor_keep_outs(FloorView{}, 7.0, 0.3, PlannerSettings{});
  EXPECT_TRUE(k.keep_outs.empty());
  EXPECT_TRUE(k.current);
}

TEST(FloorView, KeepOutsAreExtrapolatedAndGrownByTheirAge) {
  const PlannerSettings s;
  const FloorKeepOuts k = floor_keep_outs(one_rig(9.9, 9.95), 10.0, 0.3, s);
  EXPECT_TRUE(k.current);
  ASSERT_EQ(k.keep_outs.size(), 2u);
  const KeepOut& user = k.keep_outs.begin()[0];
  EXPECT_EQ(user.kind, KeepOutKind::User);
  EXPECT_NEAR(user.centre_W.x(), 1.0 + 0.1 * 0.4, 1e-12);
  EXPECT_NEAR(user.centre_W.y(), 2.0 - 0.1 * 0.3, 1e-12);
  EXPECT_NEAR(user.radius_m, s.human_radius_m + (0.05 + s.command_period_s) * 0.5, 1e-12);
  const KeepOut& base = k.keep_outs.begin()[1];
  EXPECT_EQ(base.kind, KeepOutKind::Base);
  EXPECT_EQ(base.centre_W, Eigen::Vector2d(3.0, 0.0));
  EXPECT_DOUBLE_EQ(base.radius_m, s.robot_radius_m);  // standing: no growth
}

TEST(FloorView, AnOldOrNeverSeenDiscIsNotCurrentAndAFreshOneIs) {
  const PlannerSettings s;
  EXPECT_FALSE(floor_keep_outs(one_rig(9.6, 9.95), 10.0, 0.3, s).current);   // the user 0.4 s old
  EXPECT_FALSE(floor_keep_outs(one_rig(9.95, 9.69), 10.0, 0.3, s).current);  // the base 0.31 s old
  EXPECT_TRUE(floor_keep_outs(one_rig(9.71, 9.71), 10.0, 0.3, s).current);   // dual: 0.29 s is not too old
  FloorView half = one_rig(9.95, 9.95);
  half.rigs[0].base.known = false;
  const FloorKeepOuts k = floor_keep_outs(half, 10.0, 0.3, s);
  EXPECT_FALSE(k.current);
  EXPECT_EQ(k.keep_outs.size(), 1u);  // the user it has seen is still kept out of
  FloorView nan_time = one_rig(9.95, 9.95);
  nan_time.rigs[0].user.t_s = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(floor_keep_outs(nan_time, 10.0, 0.3, s).current);
}

}  // namespace floor_view_test
}  // namespace mhd
