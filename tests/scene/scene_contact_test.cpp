// Scene-level contact behaviour on the shipped scenes: the wall force law and friction,
// through the XML -> compiled scene -> proxy path.

#include "support/scene_fixture.h"

#include <gtest/gtest.h>

namespace mhd::test {
namespace {

class SceneContact : public SceneFixture {};

TEST_F(SceneContact, CubeWallForceIsStiffnessTimesDepthAlongTheNormal) {
  ASSERT_NO_FATAL_FAILURE(load("scenes/cube_wall.xml"));
  const int cube = 0;
  ASSERT_EQ(scene().object_names[cube], "cube");
  const double k = scene().materials[cube].stiffness_N_per_m;
  const double skin = scene().proxy.skin_m;
  // The face of the cube that faces the user (+z in the world): find it by sweeping.
  const Eigen::AlignedBox3d box = scene().world.shape(cube).bounds();
  const Pose& X_WC = scene().world.pose(cube);
  const Eigen::Vector3d centre_W = X_WC * box.center();
  const Eigen::Vector3d outside_W = centre_W + Eigen::Vector3d(0.01, 0.02, 1.0);
  const auto hit = scene().world.sweep(outside_W, centre_W, skin);
  ASSERT_TRUE(hit);
  const Eigen::Vector3d n = hit->normal_W;
  const Eigen::Vector3d on_face = outside_W + (centre_W - outside_W) * hit->t_stop - skin * n;
  for (double depth : {0.0005, 0.002, 0.003}) {
    const Eigen::Vector3d hip = on_face - depth * n;
    const std::vector<Eigen::Vector3d> path =
        sample_polyline(std::vector<Eigen::Vector3d>{on_face + 0.02 * n, hip}, 0.05, 1000.0);
    const TickRecord record = drive(path, 1000.0);
    ASSERT_FALSE(record.empty());
    const TickSample& last = record.back();
    ASSERT_TRUE(last.in_contact);
    // Damping has died out: the HIP has been still for the last ticks of the path.
    const Eigen::Vector3d expected = k * (depth + skin) * n;
    EXPECT_LT((last.force_W - expected).norm(), 1e-3 * expected.norm() + 0.05)
        << "force " << last.force_W.transpose() << " expected " << expected.transpose();
    EXPECT_EQ(count_crossings(record), 0U);
  }
}

TEST_F(SceneContact, FrictionHoldsUntilTheTangentialForceExceedsMuStaticTimesNormal) {
  ASSERT_NO_FATAL_FAILURE(load("tests/data/scenes/valid/corner_room.xml"));
  // On the floor (y = 0, mu_s = 0.5, mu_d = 0.3), away from the walls and the block.
  const Eigen::Vector3d top(0.25, 0.03, 0.25);
  const Eigen::Vector3d pressed(0.25, -0.004, 0.25);
  std::vector<Eigen::Vector3d> path = sample_polyline(std::vector<Eigen::Vector3d>{top, pressed}, 0.05, 1000.0);
  for (int i = 0; i < 30; ++i) path.push_back(pressed);  // settle
  for (int i = 1; i <= 80; ++i) path.push_back(pressed + Eigen::Vector3d(5e-5 * i, 0, 0));  // drag 5 cm/s
  const TickRecord record = drive(path, 1000.0);
  // Stick-slip: stuck ticks stay inside the static cone; every tick on which the proxy
  // slides puts it on the dynamic cone's rim.
  double max_ratio_stuck = 0.0;
  int sliding_ticks = 0;
  for (std::size_t i = path.size() - 80; i < record.size(); ++i) {
    const Eigen::Vector3d& f = record[i].force_W;
    const double ratio = std::abs(f.x()) / f.y();
    const bool moved = (record[i].proxy_W - record[i - 1].proxy_W).norm() > 1e-9;
    if (moved) {
      ++sliding_ticks;
      EXPECT_NEAR(ratio, 0.3, 1e-3) << "tick " << i;
    } else {
      max_ratio_stuck = std::max(max_ratio_stuck, ratio);
    }
  }
  EXPECT_GE(sliding_ticks, 2);  // each slip jumps (mu_s - mu_d) * depth = 0.8 mm; the drag is 0.05 mm a tick
  EXPECT_GT(max_ratio_stuck, 0.45);        // held right up to the cone...
  EXPECT_LE(max_ratio_stuck, 0.5 + 1e-9);  // ...and never beyond mu_s
  EXPECT_EQ(count_crossings(record), 0U);
}

}  // namespace
}  // namespace mhd::test
