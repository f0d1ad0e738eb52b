#include "plugin_file.h"

#include <gtest/gtest.h>

#include <vector>

namespace mhd::test {
namespace {

TEST(SimIs900Plugin, TheTableIdentifiesATracker) {
  const PluginFile file(MHD_SIM_IS900_PLUGIN);
  const mhd_plugin_api& api = file.api();
  EXPECT_EQ(api.abi_version, MHD_PLUGIN_ABI_VERSION);
  EXPECT_EQ(api.struct_size, sizeof(mhd_plugin_api));
  EXPECT_EQ(api.kind, MHD_KIND_TRACKER);
  EXPECT_STREQ(api.name, "sim_is900");
  EXPECT_NE(api.tracker_read, nullptr);
  EXPECT_NE(api.simulate_until, nullptr);
  EXPECT_EQ(api.base_read, nullptr);
}

TEST(SimIs900Plugin, OpenNeedsValidParameters) {
  const PluginFile file(MHD_SIM_IS900_PLUGIN);
  FakeHost h;
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"rate_hz", "abc"}}).error,
            "parameter 'rate_hz' must be a number in [1, 10000] (Hz), got 'abc'");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"base_sensor_id", "1"}}).error,
            "parameters 'base_sensor_id' and 'head_sensor_id' must differ, both are 1");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"tracker_position_m", "0 2.624"}}).error,
            "parameter 'tracker_position_m' must be three numbers 'x y z', each in [-1000, 1000] (m), got '0 2.624'");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"buffer_capacity", "0"}}).error,
            "parameter 'buffer_capacity' must be a non-negative integer in [1, 1048576], got '0'");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"noise", "0"}}).error,
            "unknown parameter 'noise' (known: rate_hz, latency_s, position_sigma_m, angle_sigma_deg, base_sensor_id, "
            "head_sensor_id, base_sensor_position_m, base_sensor_rpy_deg, base_sensor_quaternion_wxyz, "
            "tracker_position_m, tracker_rpy_deg, tracker_quaternion_...)");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"tracker_rpy_deg", "0 0 90"}, {"tracker_quaternion_wxyz", "1 0 0 0"}}).error,
            "parameters 'tracker_rpy_deg' and 'tracker_quaternion_wxyz' exclude each other");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"dropout_sensor", "hand"}}).error,
            "parameter 'dropout_sensor' must be one of head|base|bystander_head|bystander_base, got 'hand'");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"bystander", "on"}, {"bystander_head_sensor_id", "1"}}).error,
            "the four sensors (base, head, the bystander's head and base) need different ids");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"bystander", "on"}, {"bystander_base_sensor_id", "2"}}).error,
            "the four sensors (base, head, the bystander's head and base) need different ids");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"dropout_sensor", "bystander_base"}}).error,
            "parameter 'dropout_sensor' is 'bystander_base' but there is no bystander");
  EXPECT_EQ(open_plugin(file.api(), h.host,
                        {{"bystander", "on"}, {"bystander_base_position_m", "nan 0 0"}})
                .error,
            "parameter 'bystander_base_position_m' must be three numbers 'x y z', each in [-1000, 1000] (m), got 'nan 0 0'");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"dropout_duration_s", "-1"}}).error,
            "parameter 'dropout_duration_s' must be a number in [0, 86400] (s), got '-1'");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"base_sensor_quaternion_wxyz", "0 0 0 0"}}).error,
            "parameter 'base_sensor_quaternion_wxyz' must be four numbers 'w x y z' of non-zero norm, got '0 0 0 0'");
}

TEST(SimIs900Plugin, ReportsAStandingBystanderRigBesideItsOwnSensors) {
  const PluginFile file(MHD_SIM_IS900_PLUGIN);
  const mhd_plugin_api& api = file.api();
  FakeHost h;
  const Opened opened = open_plugin(api, h.host,
                                    {{"position_sigma_m", "0"},
                                     {"angle_sigma_deg", "0"},
                                     {"tracker_position_m", "0 0 0"},  // tracker frame = world
                                     {"base_sensor_position_m", "0 0.5 0"},
                                     {"bystander", "on"},  // its sensors 2 and 3 by default
                                     {"bystander_head_position_m", "1 1.6 2"},
                                     {"bystander_base_position_m", "3 0 -1"},
                                     {"dropout_sensor", "bystander_base"},
                                     {"dropout_start_s", "0.05"},
                                     {"dropout_duration_s", "1"}});
  ASSERT_NE(opened.instance, nullptr) << opened.error;
  mhd_error err{};
  ASSERT_EQ(api.start(opened.instance, &err), MHD_OK) << err.message;
  ASSERT_EQ(api.simulate_until(opened.instance, 0.1, &err), MHD_OK) << err.message;
  std::vector<mhd_tracker_sample> samples(256);
  std::size_t count = 0;
  ASSERT_EQ(api.tracker_read(opened.instance, samples.data(), samples.size(), &count, &err), MHD_OK);
  int head = 0, base = 0, own = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const mhd_tracker_sample& s = samples[i];
    const Eigen::Vector3d p(s.p_T_m[0], s.p_T_m[1], s.p_T_m[2]);
    if (s.sensor_id == 2) {
      ++head;
      EXPECT_TRUE(p.isApprox(Eigen::Vector3d(1.0, 1.6, 2.0), 1e-12));
    } else if (s.sensor_id == 3) {
      ++base;
      EXPECT_TRUE(p.isApprox(Eigen::Vector3d(3.0, 0.5, -1.0), 1e-12));
      EXPECT_LT(s.timestamp_s, 0.05);  // its dropout from 0.05 s on
    } else {
      ++own;
    }
  }
  EXPECT_EQ(head, 18);  // k = 0..17 by 0.1 s, as the rig's own sensors
  EXPECT_EQ(base, 9);   // k = 0..8, before the dropout
  EXPECT_EQ(own, 36);
  ASSERT_EQ(api.stop(opened.instance, &err), MHD_OK);
  api.close(opened.instance);
}

TEST(SimIs900Plugin, ReportsTheWorldsBaseAndHead) {
  const PluginFile file(MHD_SIM_IS900_PLUGIN);
  const mhd_plugin_api& api = file.api();
  FakeHost h;
  h.world.set_base_pose({1.0, 2.0, 0.0});
  h.world.set_head({Eigen::Vector3d(0.2, 1.65, -0.4), Eigen::Quaterniond::Identity()});
  const Opened opened = open_plugin(api, h.host,
                                    {{"position_sigma_m", "0"},
                                     {"angle_sigma_deg", "0"},
                                     {"tracker_position_m", "0 0 0"},  // tracker frame = world
                                     {"base_sensor_position_m", "0 0.5 0"},
                                     {"base_sensor_id", "4"},
                                     {"head_sensor_id", "7"}});
  ASSERT_NE(opened.instance, nullptr) << opened.error;
  mhd_plugin_instance* tracker = opened.instance;
  mhd_error err{};
  ASSERT_EQ(api.start(tracker, &err), MHD_OK) << err.message;
  ASSERT_EQ(api.simulate_until(tracker, 0.1, &err), MHD_OK) << err.message;

  // Measured at k / 180 s, readable 4 ms later: k = 0..17 for both sensors by 0.1 s.
  std::vector<mhd_tracker_sample> samples;
  std::vector<mhd_tracker_sample> chunk(10);
  std::size_t count = 0;
  while (api.tracker_read(tracker, chunk.data(), chunk.size(), &count, &err) == MHD_OK) {
    samples.insert(samples.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(count));
  }
  EXPECT_EQ(count, 0u);
  ASSERT_EQ(samples.size(), 36u);
  for (const auto& s : samples) {
    ASSERT_TRUE(s.sensor_id == 4 || s.sensor_id == 7);
    const Eigen::Vector3d p(s.p_T_m[0], s.p_T_m[1], s.p_T_m[2]);
    EXPECT_TRUE(p.isApprox(s.sensor_id == 4 ? Eigen::Vector3d(1.0, 0.5, 2.0) : Eigen::Vector3d(0.2, 1.65, -0.4), 1e-12));
  }
  EXPECT_EQ(samples.back().sequence, 17u);

  ASSERT_EQ(api.stop(tracker, &err), MHD_OK);
  EXPECT_EQ(api.tracker_read(tracker, chunk.data(), chunk.size(), &count, &err), MHD_ERROR);
  EXPECT_STREQ(err.message, "sim_is900 is not started");
  api.close(tracker);
}

}  // namespace
}  // namespace mhd::test
