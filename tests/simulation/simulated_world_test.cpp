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

TEST(SimulatedWorld, ReadsWhatWasWrittenAndKnowsWhenAHandWasPlaced) {
  SimulatedWorld world;
  world.set_base_pose({1.5, -2.0, 0.25});
  EXPECT_EQ(world.base_pose().x_m, 1.5);
  EXPECT_EQ(world.base_pose().z_m, -2.0);
  EXPECT_EQ(world.base_pose().heading_rad, 0.25);

  // No hand until someone places one (a simulated device then rests its own).
  EXPECT_FALSE(world.has_hand());
  world.set_hand({0.4, 1.1, -0.3});
  EXPECT_TRUE(world.has_hand());
  EXPECT_EQ(world.hand(), Eigen::Vector3d(0.4, 1.1, -0.3));

  // A quaternion of norm 2 is stored normalised.
  world.set_head({Eigen::Vector3d(0.1, 1.65, 0.2), Eigen::Quaterniond(0.0, 0.0, 2.0, 0.0)});
  EXPECT_EQ(world.head().p_W_m.y(), 1.65);
  EXPECT_DOUBLE_EQ(world.head().q_W.y(), 1.0);
  EXPECT_EQ(world.head().q_W.w(), 0.0);
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
