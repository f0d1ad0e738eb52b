#include "proxy/constraint_projection.h"

#include <Eigen/LU>
#include <gtest/gtest.h>

#include <cstring>
#include <random>

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

TEST(ProjectOntoHalfSpaces, ThreePlanesSolveBitForBitAsPartialPivLU) {
  // Unit normals at random (ties of the pivot included: axis-aligned and repeated
  // magnitudes), random offsets: the same bits as Eigen's own solver, or the projection's
  // answers would change.
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> pick(0, 3);
  int compared = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    Eigen::Matrix3d n;
    for (int r = 0; r < 3; ++r) {
      Eigen::Vector3d v(u(rng), u(rng), u(rng));
      if (pick(rng) == 0) v = Eigen::Vector3d::Unit(pick(rng) % 3) * (u(rng) < 0 ? -1.0 : 1.0);
      if (pick(rng) == 0) v = V(0.5, u(rng) < 0 ? -0.5 : 0.5, 0.5);
      if (!(v.norm() > 1e-3)) v = V(0, 0, 1);
      n.row(r) = v.normalized().transpose();
    }
    if (!(std::abs(n.determinant()) > 1e-9)) continue;
    const Eigen::Vector3d d(u(rng), u(rng), u(rng));
    const Eigen::Vector3d eigen = n.partialPivLu().solve(d);
    const Eigen::Vector3d ours = solve_three_planes_like_lu(n, d);
    ASSERT_EQ(std::memcmp(eigen.data(), ours.data(), sizeof(double) * 3), 0) << "trial " << trial;
    ++compared;
  }
  EXPECT_GT(compared, 100000);
}

}  // namespace
}  // namespace mhd
