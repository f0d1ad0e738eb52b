#include "collision/segment_triangle.h"

#include <gtest/gtest.h>

namespace mhd {
namespace {

using V = Eigen::Vector3d;
constexpr double kSkin = 1e-6;

TEST(SweepPointTriangle, CrossingTheInteriorHitsAndStopsOneSkinShort) {
  const auto hit = sweep_point_triangle(V(0.1, 0.1, 0.01), V(0.1, 0.1, -0.01), V(0, 0, 0), V(1, 0, 0), V(0, 1, 0),
                                        kSkin, kSkin);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t_plane, 0.5, 1e-15);
  // Stop where the point is exactly one skin above the plane: z = 0.01 - t * 0.02.
  EXPECT_NEAR(0.01 - hit->t_stop * 0.02, kSkin, 1e-15);
  EXPECT_EQ(hit->normal, V(0, 0, 1));
}

TEST(SweepPointTriangle, NormalFacesTheSideTheSegmentComesFrom) {
  const auto hit = sweep_point_triangle(V(0.1, 0.1, -0.01), V(0.1, 0.1, 0.01), V(0, 0, 0), V(1, 0, 0), V(0, 1, 0),
                                        kSkin, kSkin);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->normal, V(0, 0, -1));
}

TEST(SweepPointTriangle, MissesBesideTheTriangle) {
  EXPECT_FALSE(sweep_point_triangle(V(0.8, 0.8, 0.01), V(0.8, 0.8, -0.01), V(0, 0, 0), V(1, 0, 0), V(0, 1, 0),
                                    kSkin, kSkin));
}

TEST(SweepPointTriangle, ParallelAndRecedingSegmentsNeverHit) {
  EXPECT_FALSE(sweep_point_triangle(V(0.1, 0.1, 2e-6), V(0.2, 0.2, 2e-6), V(0, 0, 0), V(1, 0, 0), V(0, 1, 0),
                                    kSkin, kSkin));
  EXPECT_FALSE(sweep_point_triangle(V(0.1, 0.1, 1e-7), V(0.1, 0.1, 0.5), V(0, 0, 0), V(1, 0, 0), V(0, 1, 0),
                                    kSkin, kSkin));
}

TEST(SweepPointTriangle, EndingInsideTheSkinIsAHitWithoutCrossing) {
  const auto hit = sweep_point_triangle(V(0.1, 0.1, 0.01), V(0.1, 0.1, 0.5e-6), V(0, 0, 0), V(1, 0, 0), V(0, 1, 0),
                                        kSkin, kSkin);
  ASSERT_TRUE(hit);
  EXPECT_GT(hit->t_plane, 1.0);
  EXPECT_LT(hit->t_stop, 1.0);
}

TEST(SweepPointTriangle, SegmentThroughASharedEdgeHitsBothNeighbours) {
  // Two triangles sharing the diagonal x == y of the unit square; the segment pierces
  // the diagonal exactly.
  const V a(0.3, 0.3, 0.01), b(0.3, 0.3, -0.01);
  EXPECT_TRUE(sweep_point_triangle(a, b, V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), kSkin, kSkin));
  EXPECT_TRUE(sweep_point_triangle(a, b, V(0, 0, 0), V(1, 1, 0), V(0, 1, 0), kSkin, kSkin));
}

TEST(SweepPointTriangle, SegmentThroughASharedVertexHits) {
  EXPECT_TRUE(sweep_point_triangle(V(0, 0, 1), V(0, 0, -1), V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), kSkin, kSkin));
}

TEST(SweepPointTriangle, TinyTrianglesAreNeverDiscarded) {
  // 1e-7 m legs: area 5e-15 m², far below CHAI3D's absolute cut-off.
  const double s = 1e-7;
  const auto hit = sweep_point_triangle(V(0.2 * s, 0.2 * s, 1e-3), V(0.2 * s, 0.2 * s, -1e-3), V(0, 0, 0),
                                        V(s, 0, 0), V(0, s, 0), kSkin, 0.0);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->normal, V(0, 0, 1));
}

TEST(SweepPointTriangle, ZeroAreaTriangleHasNoSurface) {
  EXPECT_FALSE(sweep_point_triangle(V(0.5, 0, 1), V(0.5, 0, -1), V(0, 0, 0), V(1, 0, 0), V(2, 0, 0), kSkin, kSkin));
}

}  // namespace
}  // namespace mhd
