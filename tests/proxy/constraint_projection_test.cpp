#include "proxy/constraint_projection.h"

#include <gtest/gtest.h>

namespace mhd {
namespace {

using V = Eigen::Vector3d;

TEST(ProjectOntoHalfSpaces, FeasibleGoalIsKept) {
  const HalfSpace hs[] = {{V(0, 0, 1), 0.0}};
  EXPECT_EQ(*project_onto_half_spaces(V(1, 2, 3), hs, 1e-12), V(1, 2, 3));
}

TEST(ProjectOntoHalfSpaces, OnePlane) {
  const HalfSpace hs[] = {{V(0, 0, 1), 0.5}};
  EXPECT_TRUE(project_onto_half_spaces(V(1, 2, -3), hs, 1e-12)->isApprox(V(1, 2, 0.5)));
}

TEST(ProjectOntoHalfSpaces, ConcaveEdgeGivesTheLine) {
  const HalfSpace hs[] = {{V(0, 0, 1), 0.0}, {V(1, 0, 0), 0.0}};
  EXPECT_TRUE(project_onto_half_spaces(V(-1, 2, -3), hs, 1e-12)->isApprox(V(0, 2, 0)));
}

TEST(ProjectOntoHalfSpaces, ConcaveCornerGivesThePoint) {
  const HalfSpace hs[] = {{V(0, 0, 1), 0.1}, {V(1, 0, 0), 0.2}, {V(0, 1, 0), 0.3}};
  EXPECT_TRUE(project_onto_half_spaces(V(-1, -2, -3), hs, 1e-12)->isApprox(V(0.2, 0.3, 0.1)));
}

TEST(ProjectOntoHalfSpaces, InactivePlaneIsDropped) {
  // The goal lies beyond plane 0 only; plane 1 must not pull the answer onto itself.
  const HalfSpace hs[] = {{V(0, 0, 1), 0.0}, {V(1, 0, 0), 0.0}};
  EXPECT_TRUE(project_onto_half_spaces(V(2, 0, -1), hs, 1e-12)->isApprox(V(2, 0, 0)));
}

TEST(ProjectOntoHalfSpaces, ConvexWedgeProjectsOntoTheEdgeFromInside) {
  // Two faces of a box meeting at a convex edge along y; free space is outside either.
  // Planes taken from inside the wedge region both face away from the goal.
  const HalfSpace hs[] = {{V(0, 0, 1), 0.0}, {V(1, 0, 0), 0.0}};
  const auto x = project_onto_half_spaces(V(-0.1, 0.5, -0.1), hs, 1e-12);
  ASSERT_TRUE(x);
  EXPECT_TRUE(x->isApprox(V(0, 0.5, 0)));
}

TEST(ProjectOntoHalfSpaces, ParallelOpposedPlanesWithAGapHaveNoSolution) {
  const HalfSpace hs[] = {{V(0, 0, 1), 1.0}, {V(0, 0, -1), 0.0}};  // z >= 1 and z <= 0
  EXPECT_FALSE(project_onto_half_spaces(V(0, 0, 0.5), hs, 1e-12));
}

}  // namespace
}  // namespace mhd
