// The physical-range checks (issue 14, item 5) on both sides of each bound: a reading
// just inside the joint limits plus the margin, or the tracking range, passes; just
// outside, or not finite, fails.
#include "haptic_server/physical_range.h"

#include <gtest/gtest.h>

#include <limits>

namespace {

using namespace mhd;

PhantomJointLimits limits() {
  PhantomJointLimits l;
  l.lower_rad = Eigen::Vector3d(-1.0, -0.2, -0.5);
  l.upper_rad = Eigen::Vector3d(1.0, 1.5, 1.2);
  l.min_link_difference_rad = -0.6;
  l.max_link_difference_rad = 0.9;
  return l;
}

TEST(PhysicalRange, JointAnglesWithinTheLimitsPlusTheMarginPass) {
  const double m = kJointLimitMargin_rad, e = 1e-9;
  EXPECT_TRUE(joint_angles_plausible(limits(), {0.0, 0.3, 0.2}));
  EXPECT_TRUE(joint_angles_plausible(limits(), {1.0 + m - e, 0.3, 0.2}));   // past the limit, within the margin
  EXPECT_TRUE(joint_angles_plausible(limits(), {-1.0 - m + e, 0.3, 0.2}));
  EXPECT_TRUE(joint_angles_plausible(limits(), {0.0, 0.3, 0.3 + 0.9 + m - e}));  // theta3 - theta2 at its bound
}

TEST(PhysicalRange, JointAnglesPastTheMarginOrNotFiniteFail) {
  const double m = kJointLimitMargin_rad, e = 1e-9;
  EXPECT_FALSE(joint_angles_plausible(limits(), {1.0 + m + e, 0.3, 0.2}));
  EXPECT_FALSE(joint_angles_plausible(limits(), {0.0, -0.2 - m - e, -0.2}));
  EXPECT_FALSE(joint_angles_plausible(limits(), {0.0, 0.3, 0.3 + 0.9 + m + e}));
  EXPECT_FALSE(joint_angles_plausible(limits(), {0.0, 0.3, 0.3 - 0.6 - m - e}));
  EXPECT_FALSE(joint_angles_plausible(limits(), {0.0, 1e30, 0.2}));
  EXPECT_FALSE(joint_angles_plausible(limits(), {0.0, std::numeric_limits<double>::quiet_NaN(), 0.2}));
  EXPECT_EQ(joint_angles_fault({0.0, 1e30, 0.2}),
            "device_read returned joint angles (0, 1e+30, 0.2) rad, outside the joint limits by more than 0.35 rad");
}

TEST(PhysicalRange, TrackedPositionsWithinTheRangePassBeyondItFail) {
  EXPECT_TRUE(tracked_position_plausible({3.0, 4.0, 0.0}, 5.0));  // exactly at the range
  EXPECT_TRUE(tracked_position_plausible({-20.0, 2.0, 30.0}, 50.0));
  EXPECT_FALSE(tracked_position_plausible({3.0, 4.0, 0.001}, 5.0));
  EXPECT_FALSE(tracked_position_plausible({1e9, 0.0, 0.0}, 50.0));
  EXPECT_FALSE(tracked_position_plausible({std::numeric_limits<double>::infinity(), 0.0, 0.0}, 50.0));
  EXPECT_EQ(tracked_position_fault(0, {1e9, 0.0, 0.0}, 50.0),
            "tracker_read returned sensor 0 at 1e+09 m from the tracker, beyond its tracking range of 50 m");
}

}  // namespace
