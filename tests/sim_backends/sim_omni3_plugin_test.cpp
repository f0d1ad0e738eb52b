#include "command_log_expectations.h"
#include "command_log_file.h"
#include "plugin_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <unistd.h>

namespace mhd::test {
namespace {

TEST(SimOmni3Plugin, TheTableIdentifiesABase) {
  const PluginFile file(MHD_SIM_OMNI3_PLUGIN);
  EXPECT_EQ(file.entry(MHD_PLUGIN_ABI_VERSION + 1), nullptr);
  const mhd_plugin_api& api = file.api();
  EXPECT_EQ(api.abi_version, MHD_PLUGIN_ABI_VERSION);
  EXPECT_EQ(api.struct_size, sizeof(mhd_plugin_api));
  EXPECT_EQ(api.kind, MHD_KIND_BASE);
  EXPECT_STREQ(api.name, "sim_omni3");
  EXPECT_NE(api.base_read, nullptr);
  EXPECT_NE(api.base_write, nullptr);
  EXPECT_NE(api.simulate_until, nullptr);
  EXPECT_EQ(api.device_read, nullptr);
  EXPECT_EQ(api.tracker_read, nullptr);
}

TEST(SimOmni3Plugin, OpenRejectsUnknownAndMalformedParameters) {
  const PluginFile file(MHD_SIM_OMNI3_PLUGIN);
  FakeHost h;
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"speed", "1"}}).error,
            "unknown parameter 'speed' (known: base_radius_m, wheel_radius_m, max_speed_mps, max_omega_degps, "
            "control_rate_hz, motor_time_constant_s, max_wheel_accel_mps2, slip_fraction, command_timeout_s, seed, x_m, "
            "z_m, heading_deg, command_log, lift, lift_min_m...)");  // cut at the ABI's message size
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"max_speed_mps", "fast"}}).error,
            "parameter 'max_speed_mps' must be a number in [0.001, 10] (m/s), got 'fast'");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"slip_fraction", "1.5"}}).error,
            "parameter 'slip_fraction' must be a number in [0, 1), got '1.5'");
  mhd_host old_host = h.host;
  old_host.abi_version = 0;
  EXPECT_EQ(open_plugin(file.api(), old_host, {}).error, "host ABI version 0 is not " + std::to_string(MHD_PLUGIN_ABI_VERSION));
}

TEST(SimOmni3Plugin, DrivesTheBaseAndMovesItInTheSimulatedWorld) {
  const PluginFile file(MHD_SIM_OMNI3_PLUGIN);
  const mhd_plugin_api& api = file.api();
  FakeHost h;
  h.world.set_base_pose({1.0, 2.0, 0.0});  // the plugin starts where the world has the base
  const Opened opened = open_plugin(api, h.host, {{"seed", "3"}, {"heading_deg", "0"}});
  ASSERT_NE(opened.instance, nullptr) << opened.error;
  mhd_plugin_instance* base = opened.instance;
  mhd_error err{};
  ASSERT_EQ(api.start(base, &err), MHD_OK) << err.message;

  mhd_base_state state{};
  ASSERT_EQ(api.base_read(base, &state, &err), MHD_OK) << err.message;
  EXPECT_EQ(state.x_m, 1.0);
  EXPECT_EQ(state.z_m, 2.0);
  EXPECT_EQ(api.base_read(base, &state, &err), MHD_NO_DATA);  // nothing new yet

  // 10 Hz commands of 0.25 m/s ahead for 2 s, simulated at 100 Hz, then a stop.
  for (int k = 0; k <= 20; ++k) {
    h.now_s = 0.1 * k;
    const mhd_base_command command{h.now_s, k < 20 ? 0.25 : 0.0, 0.0, 0.0, 0.0};
    ASSERT_EQ(api.base_write(base, &command, &err), MHD_OK) << err.message;
    for (int i = 1; i <= 10; ++i) ASSERT_EQ(api.simulate_until(base, 0.1 * k + 0.01 * i, &err), MHD_OK);
  }
  ASSERT_EQ(api.simulate_until(base, 3.0, &err), MHD_OK);
  ASSERT_EQ(api.base_read(base, &state, &err), MHD_OK);
  EXPECT_NEAR(state.timestamp_s, 3.0, 1e-12);
  EXPECT_NEAR(state.x_m, 1.5, 1e-9);
  EXPECT_NEAR(state.z_m, 2.0, 1e-12);
  EXPECT_NEAR(state.vx_mps, 0.0, 1e-6);
  const simulation::PlanarPose world_base = h.world.base_pose();
  EXPECT_EQ(world_base.x_m, state.x_m);
  EXPECT_EQ(world_base.z_m, state.z_m);

  const mhd_base_command bad{0.0, std::nan(""), 0.0, 0.0, 0.0};
  EXPECT_EQ(api.base_write(base, &bad, &err), MHD_ERROR);
  EXPECT_STREQ(err.message, "base command has a non-finite value");

  ASSERT_EQ(api.stop(base, &err), MHD_OK);
  EXPECT_EQ(api.base_read(base, &state, &err), MHD_ERROR);
  EXPECT_STREQ(err.message, "sim_omni3 is not started");
  api.close(base);
}

TEST(SimOmni3Plugin, ABaseHasNoLiftUnlessAskedAndDrivesTheOneItHas) {
  const PluginFile file(MHD_SIM_OMNI3_PLUGIN);
  const mhd_plugin_api& api = file.api();
  FakeHost h;
  {
    const Opened plain = open_plugin(api, h.host, {{"lift_min_m", "-0.3"}});  // a range alone is no lift
    ASSERT_NE(plain.instance, nullptr) << plain.error;
    mhd_error err{};
    ASSERT_EQ(api.start(plain.instance, &err), MHD_OK) << err.message;
    mhd_base_state state{};
    ASSERT_EQ(api.base_read(plain.instance, &state, &err), MHD_OK) << err.message;
    EXPECT_EQ(state.has_lift, 0);
    api.close(plain.instance);
  }
  EXPECT_EQ(open_plugin(api, h.host, {{"lift", "on"}, {"lift_min_m", "0"}, {"lift_max_m", "0"}}).error,
            "lift: the range must hold 0 and have min < max");
  EXPECT_EQ(open_plugin(api, h.host, {{"lift", "on"}, {"lift_start_m", "0.8"}}).error,
            "lift: the start height must be within the range");

  const Opened lifted = open_plugin(api, h.host,
                                    {{"lift", "on"},
                                     {"lift_min_m", "-0.2"},
                                     {"lift_max_m", "0.5"},
                                     {"lift_max_speed_mps", "0.25"},
                                     {"lift_start_m", "0.1"}});
  ASSERT_NE(lifted.instance, nullptr) << lifted.error;
  mhd_plugin_instance* base = lifted.instance;
  mhd_error err{};
  ASSERT_EQ(api.start(base, &err), MHD_OK) << err.message;
  mhd_base_state state{};
  ASSERT_EQ(api.base_read(base, &state, &err), MHD_OK) << err.message;
  EXPECT_EQ(state.has_lift, 1);
  EXPECT_EQ(state.lift_m, 0.1);
  EXPECT_EQ(h.world.lift_m(), 0.1);
  // Up at 0.25 m/s for 3 s, commanded at 10 Hz: it climbs to its end stop at 0.5 m and halts.
  for (int k = 0; k < 30; ++k) {
    h.now_s = 0.1 * k;
    mhd_base_command command{};
    command.timestamp_s = h.now_s;
    command.lift_vmps = 0.25;
    ASSERT_EQ(api.base_write(base, &command, &err), MHD_OK) << err.message;
    ASSERT_EQ(api.simulate_until(base, h.now_s + 0.1, &err), MHD_OK);
  }
  ASSERT_EQ(api.base_read(base, &state, &err), MHD_OK);
  EXPECT_NEAR(state.lift_m, 0.5, 1e-12);
  EXPECT_EQ(state.lift_vmps, 0.0);
  EXPECT_EQ(h.world.lift_m(), state.lift_m);  // where the simulated arm reads it
  EXPECT_EQ(state.x_m, 0.0);                  // the base itself never moved

  mhd_base_command bad{};
  bad.lift_vmps = std::nan("");
  EXPECT_EQ(api.base_write(base, &bad, &err), MHD_ERROR);
  EXPECT_STREQ(err.message, "base command has a non-finite value");
  api.close(base);
}

TEST(SimOmni3Plugin, LogsEveryCommandAndItsOwnWatchdogFiring) {
  const PluginFile file(MHD_SIM_OMNI3_PLUGIN);
  const mhd_plugin_api& api = file.api();
  FakeHost h;
  const std::filesystem::path log =
      std::filesystem::temp_directory_path() / ("sim_omni3_log_" + std::to_string(::getpid()) + ".csv");
  const Opened opened = open_plugin(api, h.host, {{"command_log", log.c_str()}});  // command_timeout_s 0.2
  ASSERT_NE(opened.instance, nullptr) << opened.error;
  mhd_error err{};
  ASSERT_EQ(api.start(opened.instance, &err), MHD_OK) << err.message;
  for (int k = 0; k < 3; ++k) {
    h.now_s = 0.1 * k;
    const mhd_base_command command{h.now_s, 0.25, 0.0, 0.1, 0.0};
    ASSERT_EQ(api.base_write(opened.instance, &command, &err), MHD_OK) << err.message;
    for (int i = 1; i <= 10; ++i) ASSERT_EQ(api.simulate_until(opened.instance, 0.1 * k + 0.01 * i, &err), MHD_OK);
  }
  // Commands stop: the last (at 0.2 s) expires at 0.4 s, which the 50 Hz controller sees.
  ASSERT_EQ(api.simulate_until(opened.instance, 1.0, &err), MHD_OK);
  ASSERT_EQ(api.stop(opened.instance, &err), MHD_OK);
  api.close(opened.instance);

  std::string header;
  const std::vector<CommandLogRow> rows = read_command_log(log, &header);
  std::filesystem::remove(log);
  EXPECT_EQ(header, "t_s,event,vx_mps,vz_mps,omega_radps,lift_vmps");
  ASSERT_EQ(rows.size(), 1u + 3u + 1u + 1u);
  EXPECT_EQ(rows[0].event, "start");
  for (int k = 1; k <= 3; ++k) {
    EXPECT_EQ(rows[k].event, "command");
    EXPECT_NEAR(rows[k].t_s, 0.1 * (k - 1), 1e-6);
    EXPECT_EQ(rows[k].values[0], 0.25);
    EXPECT_EQ(rows[k].values[2], 0.1);
  }
  EXPECT_EQ(rows[4].event, "timeout");
  EXPECT_NEAR(rows[4].t_s, 0.4, 1e-6);
  EXPECT_TRUE(rows[4].is_zero());
  EXPECT_EQ(rows[5].event, "stop");
}

TEST(SimOmni3Plugin, ACommandArrivingAfterAControlTickTheHostHasNotSimulatedIsNoTimeout) {
  // The io thread writes before it simulates the time up to the write; the 50 Hz
  // controller's tick in between still saw the previous, fresh command.
  const PluginFile file(MHD_SIM_OMNI3_PLUGIN);
  const mhd_plugin_api& api = file.api();
  FakeHost h;
  const std::filesystem::path log =
      std::filesystem::temp_directory_path() / ("sim_omni3_lag_" + std::to_string(::getpid()) + ".csv");
  const Opened opened = open_plugin(api, h.host, {{"command_log", log.c_str()}});
  ASSERT_NE(opened.instance, nullptr) << opened.error;
  mhd_error err{};
  ASSERT_EQ(api.start(opened.instance, &err), MHD_OK) << err.message;
  for (int k = 0; k < 20; ++k) {
    h.now_s = 0.025 * k;  // a controller tick (every 0.02 s) often lies before it, unsimulated
    const mhd_base_command command{h.now_s, 0.25, 0.0, 0.0, 0.0};
    ASSERT_EQ(api.base_write(opened.instance, &command, &err), MHD_OK) << err.message;
    ASSERT_EQ(api.simulate_until(opened.instance, h.now_s + 0.015, &err), MHD_OK) << err.message;
  }
  ASSERT_EQ(api.stop(opened.instance, &err), MHD_OK);
  api.close(opened.instance);

  const std::vector<CommandLogRow> rows = read_command_log(log);
  std::filesystem::remove(log);
  ASSERT_EQ(rows.size(), 1u + 20u + 1u);
  for (const CommandLogRow& row : rows) EXPECT_NE(row.event, "timeout") << row.t_s;
}

TEST(SimOmni3Plugin, ACommandAfterTheLastOneExpiredFollowsTheWatchdogFiring) {
  // The host froze between simulate_until and base_write: the real base's watchdog fired
  // during the gap, whatever the host's calls saw, so the log says so, in order.
  const PluginFile file(MHD_SIM_OMNI3_PLUGIN);
  const mhd_plugin_api& api = file.api();
  FakeHost h;
  const std::filesystem::path log =
      std::filesystem::temp_directory_path() / ("sim_omni3_gap_" + std::to_string(::getpid()) + ".csv");
  const Opened opened = open_plugin(api, h.host, {{"command_log", log.c_str()}});  // command_timeout_s 0.2
  ASSERT_NE(opened.instance, nullptr) << opened.error;
  mhd_error err{};
  ASSERT_EQ(api.start(opened.instance, &err), MHD_OK) << err.message;
  const mhd_base_command first{h.now_s, 0.25, 0.0, 0.0, 0.0};
  ASSERT_EQ(api.base_write(opened.instance, &first, &err), MHD_OK) << err.message;
  ASSERT_EQ(api.simulate_until(opened.instance, 0.01, &err), MHD_OK) << err.message;
  h.now_s = 1.0;  // frozen, then the next command comes first
  const mhd_base_command next{h.now_s, 0.1, 0.0, 0.0, 0.0};
  ASSERT_EQ(api.base_write(opened.instance, &next, &err), MHD_OK) << err.message;
  ASSERT_EQ(api.simulate_until(opened.instance, 1.0, &err), MHD_OK) << err.message;
  ASSERT_EQ(api.stop(opened.instance, &err), MHD_OK);
  api.close(opened.instance);

  const std::vector<CommandLogRow> rows = read_command_log(log);
  std::filesystem::remove(log);
  expect_timeout_between_two_commands(rows, 0.2, 1.0);
}

}  // namespace
}  // namespace mhd::test
