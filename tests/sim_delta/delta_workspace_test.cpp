#include "delta_workspace.h"

#include <gtest/gtest.h>

namespace mhd::sim_delta {
namespace {

TEST(DeltaWorkspace, TheStatedBoxIsReachedEverywhereOnAFineGrid) {
  const DeltaWorkspaceBox box;
  const WorkspaceSurvey survey = survey_workspace(DeltaGeometry{}, DeltaJointLimits{}, box, 21, 10.0);
  EXPECT_EQ(survey.points, 21u * 21u * 21u);
  EXPECT_EQ(survey.unreached, 0u);
  EXPECT_TRUE(survey.all_reached());
  EXPECT_LE(survey.worst_condition, 10.0);
  EXPECT_GE(survey.worst_condition, 1.0);
  EXPECT_GT(survey.max_jacobian_column_m, 0.0);
}

TEST(DeltaWorkspace, ABoxPastTheReachIsNotReachedEverywhere) {
  DeltaWorkspaceBox box;
  box.max_D_m.z() = 0.17;  // past the upper stop on the axis
  const WorkspaceSurvey deep = survey_workspace(DeltaGeometry{}, DeltaJointLimits{}, box, 9, 10.0);
  EXPECT_GT(deep.unreached, 0u);
  EXPECT_FALSE(deep.all_reached());
  // The same box surveyed with a tighter condition bound loses points too.
  const WorkspaceSurvey strict = survey_workspace(DeltaGeometry{}, DeltaJointLimits{}, DeltaWorkspaceBox{}, 9, 1.01);
  EXPECT_GT(strict.unreached, 0u);
  EXPECT_FALSE(survey_workspace(DeltaGeometry{}, DeltaJointLimits{}, DeltaWorkspaceBox{}, 1, 10.0).all_reached());
}

TEST(DeltaWorkspace, ClampMovesOnlyOutsidePoints) {
  const DeltaWorkspaceBox box;
  bool clamped = false;
  EXPECT_EQ(box.clamp(box.center_D_m(), clamped), box.center_D_m());
  EXPECT_FALSE(clamped);
  const Eigen::Vector3d outside(1.0, 0.0, -1.0);
  const Eigen::Vector3d c = box.clamp(outside, clamped);
  EXPECT_TRUE(clamped);
  EXPECT_EQ(c, Eigen::Vector3d(box.max_D_m.x(), 0.0, box.min_D_m.z()));
  EXPECT_TRUE(box.contains(c));
  EXPECT_FALSE(box.contains(outside));
}

}  // namespace
}  // namespace mhd::sim_delta
