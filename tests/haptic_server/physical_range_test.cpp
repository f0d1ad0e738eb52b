// The physical-range checks on both sides of each bound: a reading
// just inside the device's workspace plus the margin, or the tracking range, passes; just
// outside, or not finite, fails.
#include "haptic_server/physical_range.h"

#include <gtest/gtest.h>

#include <limits>

namespace {

using namespace mhd;

/// Two boxes, as a device whose workspace is an L reports it.
DeviceInfo info() {
  DeviceInfo d{};
  d.max_force_N = 8.5;
  d.max_stiffness_N_per_m = 1000.0;
  d.dof_in = d.dof_out = 3;
  d.workspace_box_count = 2;
  d.workspace[0] = WorkspaceBoxD{{-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1}};
  d.workspace[1] = WorkspaceBoxD{{0.1, -0.1, -0.1}, {0.3, 0.0, 0.1}};
  return d;
}

TEST(PhysicalRange, ToolPositionsWithinTheWorkspacePlusTheMarginPass) {
  const double m = kWorkspaceMargin_m, e = 1e-9;
  EXPECT_TRUE(tool_position_plausible(info(), {0.0, 0.0, 0.0}));
  EXPECT_TRUE(tool_position_plausible(info(), {0.25, -0.05, 0.0}));      // in the second box only
  EXPECT_TRUE(tool_position_plausible(info(), {0.0, 0.1 + m - e, 0.0}));  // past the box, within the margin
  EXPECT_TRUE(tool_position_plausible(info(), {0.3 + m - e, -0.05, 0.0}));
}

TEST(PhysicalRange, ToolPositionsPastTheMarginOrNotFiniteFail) {
  const double m = kWorkspaceMargin_m, e = 1e-9;
  EXPECT_FALSE(tool_position_plausible(info(), {0.0, 0.1 + m + e, 0.0}));
  EXPECT_FALSE(tool_position_plausible(info(), {0.25, 0.0 + m + e, 0.0}));  // above the second box, beside the first
  EXPECT_FALSE(tool_position_plausible(info(), {0.3 + m + e, -0.05, 0.0}));
  EXPECT_FALSE(tool_position_plausible(info(), {0.0, 1e30, 0.0}));
  EXPECT_FALSE(tool_position_plausible(info(), {0.0, std::numeric_limits<double>::quiet_NaN(), 0.0}));
  EXPECT_EQ(tool_position_fault({0.0, 1e30, 0.2}),
            "device_read returned the tool at (0, 1e+30, 0.2) m, outside the device's workspace by more than 0.1 m");
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

TEST(PhysicalRange, BasePositionsWithinTheRangePassBeyondItFail) {
  BaseState s{};
  s.x_m = 3.0;
  s.z_m = 4.0;
  EXPECT_TRUE(base_position_plausible(s, 5.0));  // exactly at the range
  s.z_m = 4.001;
  EXPECT_FALSE(base_position_plausible(s, 5.0));
  s.x_m = 1e308;
  EXPECT_FALSE(base_position_plausible(s, 50.0));
  s.x_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(base_position_plausible(s, 50.0));
  s.x_m = 1e308;
  s.z_m = 0.0;
  EXPECT_EQ(base_position_fault(s, 50.0),
            "base_read returned the base at (1e+308, 0) m, farther than the tracking range of 50 m");
}

}  // namespace
