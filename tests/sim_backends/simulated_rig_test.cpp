// The simulated base, tracker and user on one simulated world, shared by the plugins
// through their library (libs/sim_world), never through the host: the tracker sees
// the base that the base plugin moves and the head of the user it moves itself.

#include "plugin_file.h"
#include "simulation/simulated_user.h"

#include <gtest/gtest.h>

#include <vector>

namespace mhd::test {
namespace {

TEST(SimulatedRig, TheTrackerSeesTheBaseMoveAndTheUserWalk) {
  const PluginFile base_file(MHD_SIM_OMNI3_PLUGIN);
  const PluginFile tracker_file(MHD_SIM_IS900_PLUGIN);
  const mhd_plugin_api& base_api = base_file.api();
  const mhd_plugin_api& tracker_api = tracker_file.api();
  FakeHost h;
  const Opened base = open_plugin(base_api, h.host, {});
  const Opened tracker = open_plugin(tracker_api, h.host, {{"seed", "5"}});
  ASSERT_NE(base.instance, nullptr) << base.error;
  ASSERT_NE(tracker.instance, nullptr) << tracker.error;

  // The scene's user, as the session reads it from <simulated_user>; nobody but the
  // tracker plugin moves it from here on.
  simulation::SimulatedUserConfig user_config;
  user_config.path = simulation::parse_waypoints("0 -1 0; 3 -1 0.5");  // 0.5 m/s along +x
  h.session->set_user(user_config, 0.0);

  mhd_error err{};
  ASSERT_EQ(base_api.start(base.instance, &err), MHD_OK) << err.message;
  ASSERT_EQ(tracker_api.start(tracker.instance, &err), MHD_OK) << err.message;

  std::vector<mhd_tracker_sample> samples;
  std::vector<mhd_tracker_sample> chunk(64);
  for (int ms = 1; ms <= 3000; ++ms) {
    h.now_s = ms * 1e-3;
    if (ms % 100 == 0) {  // 10 Hz: 0.3 m/s ahead until 2 s, then stop
      const mhd_base_command command{h.now_s, h.now_s < 2.0 ? 0.3 : 0.0, 0.0, 0.0, 0.0};
      ASSERT_EQ(base_api.base_write(base.instance, &command, &err), MHD_OK) << err.message;
    }
    ASSERT_EQ(base_api.simulate_until(base.instance, h.now_s, &err), MHD_OK) << err.message;
    ASSERT_EQ(tracker_api.simulate_until(tracker.instance, h.now_s, &err), MHD_OK) << err.message;
    std::size_t count = 0;
    if (tracker_api.tracker_read(tracker.instance, chunk.data(), chunk.size(), &count, &err) == MHD_OK) {
      samples.insert(samples.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(count));
    }
  }
  ASSERT_GT(samples.size(), 2u * 530u);

  // The base moved from the first command (0.1 s) to the stop (2.0 s): 1.9 s at 0.3 m/s.
  const simulation::PlanarPose base_pose = h.world.base_pose();
  EXPECT_NEAR(base_pose.x_m, 0.57, 1e-9);
  // Samples are in the IS-900 frame of scenes/rigs/pomhi.xml (the plugin's default); the
  // host's rig maps them back into the world with the same transform. In the base frame
  // the base sensor is 1.1808 m up and 0.206 m to the left (-z).
  const Eigen::Isometry3d X_W_is900 = Eigen::Translation3d(0.0, 2.624, 0.0) * Eigen::Quaterniond(0.5, 0.5, 0.5, -0.5);
  int base_seen = 0;
  int head_seen = 0;
  for (const auto& s : samples) {
    const Eigen::Vector3d p = X_W_is900 * Eigen::Vector3d(s.p_T_m[0], s.p_T_m[1], s.p_T_m[2]);
    if (s.sensor_id == 0 && s.timestamp_s > 2.5) {
      EXPECT_LT((p - Eigen::Vector3d(0.57, 1.1808, -0.206)).norm(), 0.015);  // ~6 sigma of 2.5 mm per axis
      ++base_seen;
    }
    if (s.sensor_id == 1) {
      EXPECT_LT((p - Eigen::Vector3d(0.5 * s.timestamp_s, 1.65, -1.0)).norm(), 0.015) << "at " << s.timestamp_s;
      ++head_seen;
    }
  }
  EXPECT_GT(base_seen, 80);
  EXPECT_GT(head_seen, 530);

  ASSERT_EQ(base_api.stop(base.instance, &err), MHD_OK);
  ASSERT_EQ(tracker_api.stop(tracker.instance, &err), MHD_OK);
  base_api.close(base.instance);
  tracker_api.close(tracker.instance);
}

}  // namespace
}  // namespace mhd::test
