#include "scene_fixture.h"
#include "verification/test_meshes.h"

#include "collision/collision_world.h"

#include <gtest/gtest.h>

#include <memory>

namespace mhd::test {
namespace {

using Eigen::Vector3d;

// tests/data/scenes/valid/minimal.xml: one sphere of radius 0.1 m at the origin.
constexpr const char* kBallScene = "tests/data/scenes/valid/minimal.xml";

TEST(SurfaceCrossingOracleWorld, SnapshotMatchesTheCollisionWorld) {
  auto mesh = std::make_shared<const TriangleMesh>(make_test_box({-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1}));
  CollisionWorld world;
  world.add_object(std::make_shared<const MeshBvh>(mesh), Pose::Identity());
  world.add_object(std::make_shared<const MeshBvh>(mesh),
                   pose_from_xyz_rpy(Vector3d(0.5, 0.0, 0.2), Vector3d(0.3, -0.2, 1.0)));
  const SurfaceCrossingOracle oracle(world);
  ASSERT_EQ(oracle.object_count(), 2);
  ASSERT_EQ(oracle.triangle_count(), 24U);
  for (std::size_t i = 0; i < oracle.triangle_count(); ++i) {
    const auto expected = world.triangle_W(oracle.triangle_ref(i));
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR((oracle.triangle_W(i)[static_cast<std::size_t>(k)] - expected[static_cast<std::size_t>(k)]).norm(),
                  0.0, 1e-15);
    }
  }
  EXPECT_TRUE(oracle.is_closed(0));
  EXPECT_TRUE(oracle.point_inside_closed_mesh(Vector3d(0.5, 0.0, 0.2)));
  // Moving an object later does not change the snapshot.
  world.set_pose(1, Pose::Identity());
  EXPECT_TRUE(oracle.point_inside_closed_mesh(Vector3d(0.5, 0.0, 0.2)));
}

class SceneFixtureTest : public SceneFixture {};

TEST_F(SceneFixtureTest, LoadsAndBuildsTheOracle) {
  ASSERT_NO_FATAL_FAILURE(load(kBallScene));
  EXPECT_EQ(scene().world.object_count(), 1);
  EXPECT_GT(oracle().triangle_count(), 100U);
  EXPECT_TRUE(oracle().is_closed(0));
  EXPECT_TRUE(oracle().point_inside_closed_mesh(Vector3d::Zero()));
  EXPECT_FALSE(oracle().point_inside_closed_mesh(Vector3d(0.2, 0.0, 0.0)));
}

TEST_F(SceneFixtureTest, DriveRecordsEveryTick) {
  ASSERT_NO_FATAL_FAILURE(load(kBallScene));
  // Straight down onto the top of the ball, 5 mm in, and back out.
  const std::vector<Vector3d> corners{{0.001, 0.002, 0.13}, {0.001, 0.002, 0.095}, {0.001, 0.002, 0.13}};
  const std::vector<Vector3d> path = sample_polyline(corners, 0.1, 1000.0);
  const TickRecord records = drive(path, 1000.0);
  ASSERT_EQ(records.size(), path.size());
  bool touched = false;
  for (std::size_t k = 0; k < records.size(); ++k) {
    const TickSample& s = records[k];
    EXPECT_EQ(s.p_W_hip, path[k]);
    ASSERT_GE(s.path_points, 1);
    ASSERT_LE(s.path_points, kMaxProxyPath);
    EXPECT_TRUE(s.force_W.allFinite());
    touched = touched || s.in_contact;
    if (s.in_contact) {
      EXPECT_GE(s.plane_count, 1);
      EXPECT_GT(s.force_W.z(), 0.0);  // pushed back up, out of the ball
    }
  }
  EXPECT_TRUE(touched);
  EXPECT_FALSE(records.back().in_contact);
  EXPECT_EQ(count_crossings(records), 0U);
  EXPECT_EQ(count_ticks_inside(records), 0U);
}

TEST_F(SceneFixtureTest, CountCrossingsSeesAProxyThatJumpsThrough) {
  ASSERT_NO_FATAL_FAILURE(load(kBallScene));
  TickRecord records(3);
  records[0].proxy_W = Vector3d(0.0, 0.0, 0.15);
  records[0].path_W[0] = records[0].proxy_W;
  records[0].path_points = 1;
  // Tick 1's recorded path goes into the ball.
  records[1].path_W[0] = records[0].proxy_W;
  records[1].path_W[1] = Vector3d(0.0, 0.0, 0.12);
  records[1].path_W[2] = Vector3d(0.0, 0.0, 0.05);
  records[1].path_points = 3;
  records[1].proxy_W = records[1].path_W[2];
  // Tick 2 starts elsewhere than tick 1 ended and records no path at all.
  records[2].path_points = 0;
  records[2].proxy_W = Vector3d(0.0, 0.0, 0.2);
  const std::vector<Crossing> crossings = find_crossings(records);
  ASSERT_EQ(crossings.size(), 2U);
  EXPECT_EQ(crossings[0].tick, 1U);
  EXPECT_EQ(crossings[0].leg, 1);  // path_W[1] -> path_W[2]
  EXPECT_NEAR(crossings[0].first_hit.t, 0.3, 0.03);  // the ball's top is near z = 0.1
  EXPECT_EQ(crossings[1].tick, 2U);
  EXPECT_EQ(count_ticks_inside(records), 1U);
}

TEST_F(SceneFixtureTest, AnchorStrokesOnTheBallDoNotPopThrough) {
  ASSERT_NO_FATAL_FAILURE(load(kBallScene));
  const StrokeSet set = anchor_strokes(2024, 20);
  ASSERT_EQ(set.strokes.size(), 20U);
  std::size_t contact_ticks = 0;
  for (std::size_t i = 0; i < set.strokes.size(); ++i) {
    SCOPED_TRACE("stroke " + std::to_string(i));
    const TickRecord records = drive(set.strokes[i].p_W_hip, 1000.0);
    ASSERT_EQ(records.size(), set.strokes[i].p_W_hip.size());
    for (const TickSample& s : records) contact_ticks += s.in_contact ? 1U : 0U;
    EXPECT_EQ(count_crossings(records), 0U);
    EXPECT_EQ(count_ticks_inside(records), 0U);
  }
  // On a 0.1 m ball the HIP leaves the surface ~31 mm into the slide: ~70 contact ticks.
  EXPECT_GT(contact_ticks, 20U * 50U);
}

}  // namespace
}  // namespace mhd::test
