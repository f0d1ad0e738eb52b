// usable_device_workspace (haptic_server/scene_planner.h): the box the scene's planner
// keeps the HIP in, from what the device reports. One box: that box moved in by the
// margin; several: the largest (it lies inside their union, which may not be convex);
// nothing usable (no box, or one thinner than twice the margin): none, so that the
// server refuses the run rather than plan around a box that is not there.

#include "haptic_server/scene_planner.h"

#include <gtest/gtest.h>

namespace mhd {
namespace {

void set_box(WorkspaceBoxD& b, const Eigen::Vector3d& min_m, const Eigen::Vector3d& max_m) {
  for (int i = 0; i < 3; ++i) {
    b.min_m[i] = min_m[i];
    b.max_m[i] = max_m[i];
  }
}

TEST(DeviceWorkspace, OneBoxIsMovedInByTheMargin) {
  DeviceInfo info{};
  info.workspace_box_count = 1;
  set_box(info.workspace[0], Eigen::Vector3d(-0.1, 0.0, -0.05), Eigen::Vector3d(0.1, 0.2, 0.05));
  const std::optional<WorkspaceBox> usable = usable_device_workspace(info, 0.01);
  ASSERT_TRUE(usable);
  EXPECT_TRUE(usable->min_P_m.isApprox(Eigen::Vector3d(-0.09, 0.01, -0.04)));
  EXPECT_TRUE(usable->max_P_m.isApprox(Eigen::Vector3d(0.09, 0.19, 0.04)));
}

TEST(DeviceWorkspace, OfSeveralBoxesTheLargestIsUsed) {
  DeviceInfo info{};
  info.workspace_box_count = 3;
  set_box(info.workspace[0], Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(0.1, 0.1, 0.1));   // 1e-3 m^3
  set_box(info.workspace[1], Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(0.3, 0.2, 0.1));   // 6e-3 m^3
  set_box(info.workspace[2], Eigen::Vector3d(-0.5, 0.0, 0.0), Eigen::Vector3d(0.5, 0.01, 0.5));  // 5e-3 m^3
  const std::optional<WorkspaceBox> usable = usable_device_workspace(info, 0.0);
  ASSERT_TRUE(usable);
  EXPECT_EQ(usable->max_P_m, Eigen::Vector3d(0.3, 0.2, 0.1));
}

TEST(DeviceWorkspace, NoBoxOrOneThinnerThanTwiceTheMarginGivesNone) {
  DeviceInfo info{};
  EXPECT_FALSE(usable_device_workspace(info, 0.01)) << "no box reported";
  info.workspace_box_count = 1;
  set_box(info.workspace[0], Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(0.3, 0.02, 0.3));
  EXPECT_FALSE(usable_device_workspace(info, 0.01)) << "2 cm thick, 1 cm margin on each side";
  EXPECT_TRUE(usable_device_workspace(info, 0.009));
}

}  // namespace
}  // namespace mhd
