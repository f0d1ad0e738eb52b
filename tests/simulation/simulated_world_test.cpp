#include "simulation/simulated_world.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

namespace mhd::simulation {
namespace {

TEST(SimulatedWorld, StartsAtTheOriginUnrotated) {
  const SimulatedWorld world;
  const PlanarPose base = world.base_pose();
  EXPECT_EQ(base.x_m, 0.0);
  EXPECT_EQ(base.z_m, 0.0);
  EXPECT_EQ(base.heading_rad, 0.0);
  EXPECT_TRUE(world.hand().isZero(0.0));
  EXPECT_TRUE(world.head().p_W_m.isZero(0.0));
  EXPECT_EQ(world.head().q_W.w(), 1.0);
}

TEST(SimulatedWorld, TheCTableReadsAndWritesTheSameState) {
  SimulatedWorld world;
  const mhd_sim_world& t = world.table();
  ASSERT_EQ(t.context, &world);

  t.set_base_pose(t.context, 1.5, -2.0, 0.25);
  double x = 0, z = 0, h = 0;
  t.get_base_pose(t.context, &x, &z, &h);
  EXPECT_EQ(x, 1.5);
  EXPECT_EQ(z, -2.0);
  EXPECT_EQ(h, 0.25);
  EXPECT_EQ(world.base_pose().x_m, 1.5);

  const double hand[3] = {0.4, 1.1, -0.3};
  t.set_hand(t.context, hand);
  double hand_out[3] = {};
  t.get_hand(t.context, hand_out);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(hand_out[i], hand[i]);
  EXPECT_EQ(world.hand(), Eigen::Vector3d(0.4, 1.1, -0.3));

  // A quaternion of norm 2 is stored normalised.
  const double p[3] = {0.1, 1.65, 0.2};
  const double q[4] = {0.0, 0.0, 2.0, 0.0};
  t.set_head(t.context, p, q);
  double p_out[3] = {};
  double q_out[4] = {};
  t.get_head(t.context, p_out, q_out);
  EXPECT_EQ(p_out[1], 1.65);
  EXPECT_DOUBLE_EQ(q_out[2], 1.0);
  EXPECT_EQ(q_out[0], 0.0);
}

// Writers store (a, 2a, 3a); a torn read would break the ratio.
TEST(SimulatedWorld, HandReadsAreNeverTorn) {
  SimulatedWorld world;
  world.set_hand({1.0, 2.0, 3.0});
  std::atomic<bool> stop{false};
  std::vector<std::thread> writers;
  for (int w = 0; w < 2; ++w) {
    writers.emplace_back([&, w] {
      for (int i = 1; !stop.load(std::memory_order_relaxed); ++i) {
        const double a = i + 0.5 * w;
        world.set_hand({a, 2.0 * a, 3.0 * a});
      }
    });
  }
  int torn = 0;
  for (int i = 0; i < 200000; ++i) {
    const Eigen::Vector3d p = world.hand();
    if (p[1] != 2.0 * p[0] || p[2] != 3.0 * p[0]) ++torn;
  }
  stop = true;
  for (auto& t : writers) t.join();
  EXPECT_EQ(torn, 0);
}

}  // namespace
}  // namespace mhd::simulation
