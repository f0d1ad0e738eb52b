// The followed volume (simulate_volume): its vertical reach is the rig's; a hand within
// the arm's fixed reach is followed as in the planar map, one beyond it never is without a
// lift and is with one; and the lift's volume holds the fixed arm's.
#include "plan_sim.h"

#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace mhd::plan_sim {
namespace {

const Lift kLift{-0.7, 0.9, 0.3, 1.5};

/// A coarse map around the start: enough cells to tell volumes apart, quick to simulate.
MapSpec coarse() {
  MapSpec spec;
  spec.half_size_m = 0.6;
  spec.cell_m = 0.1;
  return spec;
}

TEST(PlanSimVolume, TheDefaultReachIsThePomhiRigsUsableWorkspaceInHeight) {
  const auto read = read_scene_file(std::string(MHD_SOURCE_DIR) + "/scenes/rigs/pomhi.xml");
  ASSERT_TRUE(read.ok()) << read.error_text();
  const Rig rig = Rig::from_scene(*read).value();
  const WorkspaceBox box = rig.device().usable_workspace();
  double low = std::numeric_limits<double>::infinity(), high = -low;
  const Pose X_W_P = rig.X_W_phantom(rig.X_W_robot_from_base({}));
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p_P((corner & 1) ? box.max_P_m.x() : box.min_P_m.x(),
                              (corner & 2) ? box.max_P_m.y() : box.min_P_m.y(),
                              (corner & 4) ? box.max_P_m.z() : box.min_P_m.z());
    low = std::min(low, (X_W_P * p_P).y());
    high = std::max(high, (X_W_P * p_P).y());
  }
  EXPECT_NEAR(VerticalReach{}.low_m, low, 1e-4);
  EXPECT_NEAR(VerticalReach{}.high_m, high, 1e-4);
}

TEST(PlanSimVolume, AHandWithinTheFixedReachIsFollowedAsOnTheFloorMap) {
  for (const PlannerKind kind : {PlannerKind::Seed, PlannerKind::Predictive}) {
    const FollowMap planar = simulate_map(kind, PlannerSettings{}, coarse());
    MapSpec spec = coarse();
    spec.vertical = VerticalReach{};
    const FollowMap fixed = simulate_map(kind, PlannerSettings{}, spec);  // the hand at 1.1 m, inside the reach
    EXPECT_GT(planar.followed_cells, 0);
    EXPECT_EQ(fixed.followed, planar.followed);
    EXPECT_EQ(fixed.follow_time_s, planar.follow_time_s);
  }
}

TEST(PlanSimVolume, AHandBeyondTheFixedReachIsNeverFollowedWithoutALiftAndIsWithOne) {
  for (const double height_m : {0.3, 1.9}) {
    MapSpec spec = coarse();
    spec.hand_height_m = height_m;
    spec.vertical = VerticalReach{};
    EXPECT_EQ(simulate_map(PlannerKind::Predictive, PlannerSettings{}, spec).followed_cells, 0) << height_m;
    // 0.8 m away from the reach: the lift (0.3 m/s) needs about 2.9 s.
    spec.vertical->lift = kLift;
    EXPECT_EQ(simulate_map(PlannerKind::Predictive, PlannerSettings{}, spec).followed_cells, 0) << height_m;
    spec.horizon_s = 4.0;
    EXPECT_GT(simulate_map(PlannerKind::Predictive, PlannerSettings{}, spec).followed_cells, 0) << height_m;
  }
}

TEST(PlanSimVolume, TheLiftsVolumeHoldsTheFixedArmsAndMore) {
  MapSpec spec = coarse();
  spec.horizon_s = 2.0;
  const std::vector<double> heights{0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.4};
  const FollowVolume fixed = simulate_volume(PlannerKind::Predictive, PlannerSettings{}, spec, heights);
  spec.vertical = VerticalReach{};
  spec.vertical->lift = kLift;
  const FollowVolume lifted = simulate_volume(PlannerKind::Predictive, PlannerSettings{}, spec, heights);
  ASSERT_EQ(fixed.followed_cells.size(), heights.size());
  for (std::size_t i = 0; i < heights.size(); ++i) {
    const bool within = heights[i] >= VerticalReach{}.low_m && heights[i] <= VerticalReach{}.high_m;
    EXPECT_EQ(fixed.followed_cells[i] > 0, within) << heights[i];
    EXPECT_GE(lifted.followed_cells[i], fixed.followed_cells[i]) << heights[i];
  }
  EXPECT_GT(lifted.followed_volume_m3(), 2.0 * fixed.followed_volume_m3());
  int cells = 0;
  for (const int n : fixed.followed_cells) cells += n;
  EXPECT_NEAR(fixed.followed_volume_m3(), cells * 0.1 * 0.1 * 0.1, 1e-12);  // cell area times the height step
}

}  // namespace
}  // namespace mhd::plan_sim
