// The built libmhd_sim_phantom.so through the real dlopen path, with a fake host clock and
// a SimulatedWorld; the world's hand is placed with the rig read from scenes/rigs/pomhi.xml.
#include "command_log_expectations.h"
#include "command_log_file.h"
#include "plugin_file.h"

#include "kinematics/rig.h"
#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <unistd.h>
#include <thread>
#include <chrono>

namespace mhd::test {
namespace {

Eigen::Vector3d hip_of(const mhd_device_state& s) { return {s.p_D_tool_m[0], s.p_D_tool_m[1], s.p_D_tool_m[2]}; }

/// A force command in the device frame P, as the ABI 3 host sends it.
mhd_device_command force_command(double t_s, const Eigen::Vector3d& F_P_N) {
  return mhd_device_command{t_s, {F_P_N[0], F_P_N[1], F_P_N[2]}, {0.0, 0.0, 0.0}};
}

Rig pomhi_rig() {
  const Result<SceneDescription> read = read_scene_file(std::filesystem::path(MHD_SOURCE_DIR) / "scenes/rigs/pomhi.xml");
  EXPECT_TRUE(read.ok());
  Result<Rig, std::vector<RigError>> built = Rig::from_scene(read.value_or(SceneDescription{}));
  EXPECT_TRUE(built.ok());
  return *built;
}

TEST(SimPhantomPlugin, TheTableIdentifiesADevice) {
  // What `mhd plugins` lists: the entry's table, checked as the host checks it.
  const PluginFile file(MHD_SIM_PHANTOM_PLUGIN);
  EXPECT_EQ(file.entry(MHD_PLUGIN_ABI_VERSION + 1), nullptr);
  const mhd_plugin_api& api = file.api();
  EXPECT_EQ(api.abi_version, MHD_PLUGIN_ABI_VERSION);
  EXPECT_EQ(api.struct_size, sizeof(mhd_plugin_api));
  EXPECT_EQ(api.kind, MHD_KIND_DEVICE);
  EXPECT_STREQ(api.name, "sim_phantom");
  EXPECT_STREQ(api.version, "3.0.0");
  EXPECT_NE(api.description, nullptr);
  EXPECT_NE(api.device_info, nullptr);
  EXPECT_GT(api.param_count, 0u);
  EXPECT_NE(api.device_read, nullptr);
  EXPECT_NE(api.device_write, nullptr);
  EXPECT_NE(api.simulate_until, nullptr);
  EXPECT_EQ(api.base_read, nullptr);
  EXPECT_EQ(api.tracker_read, nullptr);
  EXPECT_EQ(api.display_write, nullptr);
}

TEST(SimPhantomPlugin, OpenRejectsUnknownAndMalformedParameters) {
  const PluginFile file(MHD_SIM_PHANTOM_PLUGIN);
  FakeHost h;
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"stiffness", "1"}}).error,
            "unknown parameter 'stiffness' (known: hand_model, hand_mass_kg, hand_stiffness_N_per_m, "
            "hand_damping_Ns_per_m, command_timeout_s, position_resolution_m, phantom_position_m, phantom_rpy_deg, "
            "base_position_m, base_rpy_deg, hand_P_m, command_log)");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"hand_model", "spring"}}).error,
            "parameter 'hand_model' must be one of kinematic|impedance, got 'spring'");
  // The mass and damping belong to the impedance hand only.
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"hand_mass_kg", "0.5"}}).error,
            "parameter 'hand_mass_kg' applies only to hand_model 'impedance'");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"hand_model", "impedance"}, {"hand_damping_Ns_per_m", "0"}}).error,
            "parameter 'hand_damping_Ns_per_m' must be a number in (0, 10000] (N s/m), got '0'");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"command_log", "/nonexistent/dir/log.csv"}}).error,
            "cannot write the command log '/nonexistent/dir/log.csv': No such file or directory");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"command_timeout_s", "0"}}).error,
            "parameter 'command_timeout_s' must be a number in [0.001, 1] (s), got '0'");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"hand_stiffness_N_per_m", "-5"}}).error,
            "parameter 'hand_stiffness_N_per_m' must be a number in (0, 1e+06] (N/m), got '-5'");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"position_resolution_m", "fine"}}).error,
            "parameter 'position_resolution_m' must be a number in [0, 0.01] (m), got 'fine'");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"hand_P_m", "0 0.1"}}).error,
            "parameter 'hand_P_m' must be three numbers 'x y z', each in [-10, 10] (m), got '0 0.1'");
  mhd_host old_host = h.host;
  old_host.abi_version = 0;
  EXPECT_EQ(open_plugin(file.api(), old_host, {}).error, "host ABI version 0 is not " + std::to_string(MHD_PLUGIN_ABI_VERSION));
}

TEST(SimPhantomPlugin, FollowsTheWorldsHandAndIsPushedByTorques) {
  const PluginFile file(MHD_SIM_PHANTOM_PLUGIN);
  const mhd_plugin_api& api = file.api();
  const Rig rig = pomhi_rig();
  FakeHost h;
  const BasePose base{0.5, -0.3, 0.4};
  h.world.set_base_pose({base.x_m, base.z_m, base.heading_rad});
  const Pose X_W_P = rig.X_W_phantom(rig.X_W_robot_from_base(base));
  const Eigen::Vector3d hand_P(0.03, 0.12, -0.02);
  h.world.set_hand(X_W_P * hand_P);

  const Opened opened = open_plugin(api, h.host, {{"position_resolution_m", "0"}});
  ASSERT_NE(opened.instance, nullptr) << opened.error;
  mhd_plugin_instance* device = opened.instance;
  mhd_error err{};
  mhd_device_info info{};
  ASSERT_EQ(api.device_info(device, &info, &err), MHD_OK) << err.message;
  EXPECT_EQ(info.max_force_N, 8.5);
  EXPECT_EQ(info.max_torque_Nm, 0.0);
  EXPECT_EQ(info.dof_in, 3u);
  EXPECT_EQ(info.dof_out, 3u);
  ASSERT_EQ(info.workspace_box_count, 1u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(info.workspace[0].min_m[i], rig.device().workspace.min_P_m[i]);
    EXPECT_EQ(info.workspace[0].max_m[i], rig.device().workspace.max_P_m[i]);
  }

  h.now_s = 1.0;
  ASSERT_EQ(api.start(device, &err), MHD_OK) << err.message;
  mhd_device_state state{};
  ASSERT_EQ(api.device_read(device, &state, &err), MHD_OK) << err.message;
  EXPECT_EQ(state.timestamp_s, 1.0);
  EXPECT_LT((hip_of(state) - hand_P).norm(), 1e-9);
  EXPECT_EQ(api.device_read(device, &state, &err), MHD_NO_DATA);

  // The hand moves in the world.
  const Eigen::Vector3d hand2_P(-0.05, 0.16, 0.03);
  h.world.set_hand(X_W_P * hand2_P);
  ASSERT_EQ(api.simulate_until(device, 1.001, &err), MHD_OK) << err.message;
  ASSERT_EQ(api.device_read(device, &state, &err), MHD_OK);
  EXPECT_EQ(state.timestamp_s, 1.001);
  EXPECT_LT((hip_of(state) - hand2_P).norm(), 1e-9);

  // A force of (2, 0, -1) N in P, as the host commands it; the plugin maps it to its
  // motors (tau = J^T F), and the motors push the tool by F over the hand's stiffness.
  const Eigen::Vector3d F(2.0, 0.0, -1.0);
  h.now_s = 1.001;
  const mhd_device_command command = force_command(h.now_s, F);
  ASSERT_EQ(api.device_write(device, &command, &err), MHD_OK) << err.message;
  ASSERT_EQ(api.simulate_until(device, 1.002, &err), MHD_OK);
  ASSERT_EQ(api.device_read(device, &state, &err), MHD_OK);
  EXPECT_LT((hip_of(state) - (hand2_P + F / 2000.0)).norm(), 1e-9);

  // The host stalls: 20 ms later (command_timeout_s) the force is gone.
  ASSERT_EQ(api.simulate_until(device, 1.2, &err), MHD_OK);
  ASSERT_EQ(api.device_read(device, &state, &err), MHD_OK);
  EXPECT_LT((hip_of(state) - hand2_P).norm(), 1e-9);

  const mhd_device_command bad = force_command(h.now_s, Eigen::Vector3d(0.0, std::nan(""), 0.0));
  EXPECT_EQ(api.device_write(device, &bad, &err), MHD_ERROR);
  EXPECT_STREQ(err.message, "device_write: the force is not finite");

  ASSERT_EQ(api.stop(device, &err), MHD_OK);
  EXPECT_EQ(api.device_read(device, &state, &err), MHD_ERROR);
  EXPECT_STREQ(err.message, "sim_phantom is not started");
  api.close(device);
}

TEST(SimPhantomPlugin, TheImpedanceHandIsPushedBackByTheForceAndSettlesAtForceOverItsStiffness) {
  const PluginFile file(MHD_SIM_PHANTOM_PLUGIN);
  const mhd_plugin_api& api = file.api();
  const Rig rig = pomhi_rig();
  FakeHost h;
  const BasePose base{0.5, -0.3, 0.4};  // turned: the hand integrates in W, the force comes in P
  h.world.set_base_pose({base.x_m, base.z_m, base.heading_rad});
  const Pose X_W_P = rig.X_W_phantom(rig.X_W_robot_from_base(base));
  const Eigen::Vector3d hand_P(0.03, 0.12, -0.02);
  h.world.set_hand(X_W_P * hand_P);
  const Opened opened = open_plugin(api, h.host,
                                    {{"position_resolution_m", "0"}, {"hand_model", "impedance"},
                                     {"hand_mass_kg", "0.5"}, {"hand_stiffness_N_per_m", "200"},
                                     {"hand_damping_Ns_per_m", "8"}});
  ASSERT_NE(opened.instance, nullptr) << opened.error;
  mhd_plugin_instance* device = opened.instance;
  mhd_error err{};
  h.now_s = 1.0;
  ASSERT_EQ(api.start(device, &err), MHD_OK) << err.message;
  mhd_device_state state{};
  ASSERT_EQ(api.device_read(device, &state, &err), MHD_OK) << err.message;
  EXPECT_LT((hip_of(state) - hand_P).norm(), 1e-9);  // the hand starts where it is meant to be

  // The host holds 2 N along P's (1, 0, -1) direction, re-sent every millisecond.
  const Eigen::Vector3d F_P = 2.0 * Eigen::Vector3d(1.0, 0.0, -1.0).normalized();
  double after_one_tick_m = 0.0;
  for (int tick = 1; tick <= 3000; ++tick) {
    const mhd_device_command command = force_command(h.now_s, F_P);
    ASSERT_EQ(api.device_write(device, &command, &err), MHD_OK) << err.message;
    h.now_s = 1.0 + 0.001 * tick;
    ASSERT_EQ(api.simulate_until(device, h.now_s, &err), MHD_OK) << err.message;
    ASSERT_EQ(api.device_read(device, &state, &err), MHD_OK) << err.message;
    if (tick == 1) after_one_tick_m = (hip_of(state) - hand_P).norm();
  }
  // The hand has mass: one millisecond of 2 N moves it by F t^2 / 2m = 2 µm, not F / k = 10 mm.
  EXPECT_NEAR(after_one_tick_m, 2.0 * 1e-6 / (2.0 * 0.5), 0.2e-6);
  // Settled against the arm's spring, the tool sits F / k from where the user means the hand.
  EXPECT_LT((hip_of(state) - (hand_P + F_P / 200.0)).norm(), 20e-6);
  ASSERT_EQ(api.stop(device, &err), MHD_OK);
  api.close(device);
}

TEST(SimPhantomPlugin, RigTransformsCanBeOverridden) {
  const PluginFile file(MHD_SIM_PHANTOM_PLUGIN);
  const mhd_plugin_api& api = file.api();
  FakeHost h;
  const BasePose base{-0.4, 0.2, -1.1};
  h.world.set_base_pose({base.x_m, base.z_m, base.heading_rad});
  // Robot 0.9 m above the floor, the device 0.1 m ahead of the robot, turned 20 deg about P's y.
  const Pose X_robot_base = pose_from_xyz_rpy(Eigen::Vector3d(0.0, 0.0, -0.9), Eigen::Vector3d(std::numbers::pi / 2, 0.0, 0.0));
  const Pose X_robot_phantom =
      pose_from_xyz_rpy(Eigen::Vector3d(0.1, 0.0, 0.05), Eigen::Vector3d(std::numbers::pi / 2, 0.0, 0.0)) *
      pose_from_xyz_rpy(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 20.0 * std::numbers::pi / 180.0, 0.0));
  const Pose X_W_P = pose_from_base(base) * X_robot_base.inverse(Eigen::Isometry) * X_robot_phantom;
  const Eigen::Vector3d hand_P(0.02, 0.11, 0.01);
  h.world.set_hand(X_W_P * hand_P);
  const Eigen::Vector3d rpy_deg = X_robot_phantom.linear().eulerAngles(2, 1, 0).reverse() * (180.0 / std::numbers::pi);
  const std::string rpy = std::to_string(rpy_deg.x()) + " " + std::to_string(rpy_deg.y()) + " " + std::to_string(rpy_deg.z());
  const Opened opened = open_plugin(api, h.host,
                                    {{"position_resolution_m", "0"},
                                     {"phantom_position_m", "0.1 0 0.05"},
                                     {"phantom_rpy_deg", rpy.c_str()},
                                     {"base_position_m", "0 0 -0.9"},
                                     {"base_rpy_deg", "90 0 0"}});
  ASSERT_NE(opened.instance, nullptr) << opened.error;
  mhd_error err{};
  ASSERT_EQ(api.start(opened.instance, &err), MHD_OK) << err.message;
  mhd_device_state state{};
  ASSERT_EQ(api.device_read(opened.instance, &state, &err), MHD_OK);
  // rpy printed with 6 decimals: 1e-6 deg of rotation error over ~1.3 m.
  EXPECT_LT((hip_of(state) - hand_P).norm(), 1e-6);
  api.close(opened.instance);
}

TEST(SimPhantomPlugin, UntilTheWorldHasAHandItRestsAtHandPThenItFollowsTheWorlds) {
  const PluginFile file(MHD_SIM_PHANTOM_PLUGIN);
  const mhd_plugin_api& api = file.api();
  FakeHost h;
  ASSERT_FALSE(h.world.has_hand());
  const Opened opened = open_plugin(api, h.host, {{"hand_P_m", "0.01 0.1 0.02"}});
  ASSERT_NE(opened.instance, nullptr) << opened.error;
  mhd_error err{};
  ASSERT_EQ(api.start(opened.instance, &err), MHD_OK) << err.message;
  ASSERT_EQ(api.simulate_until(opened.instance, 0.5, &err), MHD_OK) << err.message;
  mhd_device_state state{};
  ASSERT_EQ(api.device_read(opened.instance, &state, &err), MHD_OK);
  EXPECT_EQ(state.timestamp_s, 0.5);
  // Default resolution 0.03 mm: within 1.5 resolution steps.
  EXPECT_LT((hip_of(state) - Eigen::Vector3d(0.01, 0.1, 0.02)).norm(), 1.5 * 0.03e-3);

  // The dual: a hand placed in the world (at its origin, far below the device) is the
  // one the tool follows from then on.
  h.world.set_hand(Eigen::Vector3d::Zero());
  ASSERT_EQ(api.simulate_until(opened.instance, 1.0, &err), MHD_OK) << err.message;
  ASSERT_EQ(api.device_read(opened.instance, &state, &err), MHD_OK);
  EXPECT_GT((hip_of(state) - Eigen::Vector3d(0.01, 0.1, 0.02)).norm(), 0.01);
  api.close(opened.instance);
}

TEST(SimPhantomPlugin, LogsEveryCommandAndItsOwnWatchdogFiring) {
  const PluginFile file(MHD_SIM_PHANTOM_PLUGIN);
  const mhd_plugin_api& api = file.api();
  FakeHost h;
  const std::filesystem::path log =
      std::filesystem::temp_directory_path() / ("sim_phantom_log_" + std::to_string(::getpid()) + ".csv");
  const Opened opened = open_plugin(api, h.host, {{"command_log", log.c_str()}, {"command_timeout_s", "0.02"}});
  ASSERT_NE(opened.instance, nullptr) << opened.error;
  mhd_error err{};
  h.now_s = 1.0;
  ASSERT_EQ(api.start(opened.instance, &err), MHD_OK) << err.message;
  for (int k = 1; k <= 5; ++k) {
    h.now_s = 1.0 + 0.001 * k;
    ASSERT_EQ(api.simulate_until(opened.instance, h.now_s, &err), MHD_OK) << err.message;
    const mhd_device_command command = force_command(h.now_s, Eigen::Vector3d(0.1 * k, -0.2, 0.0));
    ASSERT_EQ(api.device_write(opened.instance, &command, &err), MHD_OK) << err.message;
  }
  // Commands stop; the device's watchdog fires 20 ms after the last one, once.
  h.now_s = 1.1;
  ASSERT_EQ(api.simulate_until(opened.instance, 1.05, &err), MHD_OK);
  ASSERT_EQ(api.simulate_until(opened.instance, 1.1, &err), MHD_OK);
  ASSERT_EQ(api.stop(opened.instance, &err), MHD_OK);
  api.close(opened.instance);

  std::string header;
  const std::vector<CommandLogRow> rows = read_command_log(log, &header);
  std::filesystem::remove(log);
  EXPECT_EQ(header, "t_s,event,force_x_N,force_y_N,force_z_N");
  ASSERT_EQ(rows.size(), 1u + 5u + 1u + 1u);
  EXPECT_EQ(rows[0].event, "start");
  EXPECT_DOUBLE_EQ(rows[0].t_s, 1.0);
  for (int k = 1; k <= 5; ++k) {
    EXPECT_EQ(rows[k].event, "command");
    EXPECT_NEAR(rows[k].t_s, 1.0 + 0.001 * k, 1e-6);
    EXPECT_NEAR(rows[k].values[0], 0.1 * k, 1e-9);
    EXPECT_EQ(rows[k].values[1], -0.2);
  }
  EXPECT_EQ(rows[6].event, "timeout");
  EXPECT_NEAR(rows[6].t_s, 1.025, 1e-6);
  EXPECT_TRUE(rows[6].is_zero());
  EXPECT_EQ(rows[7].event, "stop");
}

TEST(SimPhantomPlugin, ACommandAfterTheLastOneExpiredFollowsTheWatchdogFiring) {
  // The host froze between simulate_until and device_write: the real device's watchdog
  // fired during the gap, whatever the host's calls saw, so the log says so, in order.
  const PluginFile file(MHD_SIM_PHANTOM_PLUGIN);
  const mhd_plugin_api& api = file.api();
  FakeHost h;
  const std::filesystem::path log =
      std::filesystem::temp_directory_path() / ("sim_phantom_gap_" + std::to_string(::getpid()) + ".csv");
  const Opened opened = open_plugin(api, h.host, {{"command_log", log.c_str()}, {"command_timeout_s", "0.02"}});
  ASSERT_NE(opened.instance, nullptr) << opened.error;
  mhd_error err{};
  h.now_s = 1.0;
  ASSERT_EQ(api.start(opened.instance, &err), MHD_OK) << err.message;
  h.now_s = 1.001;
  ASSERT_EQ(api.simulate_until(opened.instance, h.now_s, &err), MHD_OK) << err.message;
  const mhd_device_command first = force_command(h.now_s, Eigen::Vector3d(0.5, 0.0, 0.0));
  ASSERT_EQ(api.device_write(opened.instance, &first, &err), MHD_OK) << err.message;
  ASSERT_EQ(api.simulate_until(opened.instance, 1.002, &err), MHD_OK) << err.message;
  h.now_s = 1.5;  // frozen for half a second, then the next command comes first
  const mhd_device_command next = force_command(h.now_s, Eigen::Vector3d(0.3, 0.0, 0.0));
  ASSERT_EQ(api.device_write(opened.instance, &next, &err), MHD_OK) << err.message;
  ASSERT_EQ(api.simulate_until(opened.instance, h.now_s, &err), MHD_OK) << err.message;
  ASSERT_EQ(api.stop(opened.instance, &err), MHD_OK);
  api.close(opened.instance);

  const std::vector<CommandLogRow> rows = read_command_log(log);
  std::filesystem::remove(log);
  expect_timeout_between_two_commands(rows, 1.021, 1.5);
}

TEST(SimPhantomPlugin, FlushesTheCommandLogWhileOpen) {
  const PluginFile file(MHD_SIM_PHANTOM_PLUGIN);
  const mhd_plugin_api& api = file.api();
  FakeHost h;
  const std::filesystem::path log =
      std::filesystem::temp_directory_path() / ("sim_phantom_flush_" + std::to_string(::getpid()) + ".csv");
  const Opened opened = open_plugin(api, h.host, {{"command_log", log.c_str()}});
  ASSERT_NE(opened.instance, nullptr) << opened.error;
  mhd_error err{};
  ASSERT_EQ(api.start(opened.instance, &err), MHD_OK) << err.message;
  const mhd_device_command command = force_command(0.0, Eigen::Vector3d::Zero());
  ASSERT_EQ(api.device_write(opened.instance, &command, &err), MHD_OK) << err.message;
  // Within 50 ms (generously waited for) the row is in the file without a close.
  std::size_t rows = 0;
  for (int i = 0; i < 200 && rows < 2; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    rows = read_command_log(log).size();
  }
  EXPECT_EQ(rows, 2u);
  api.close(opened.instance);
  std::filesystem::remove(log);
}

}  // namespace
}  // namespace mhd::test
