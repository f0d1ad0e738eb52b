// The `ros2_pose` tracker against a plain Cyclone DDS peer that knows only ROS 2's topic
// and type names, as a motion-capture system's ROS 2 driver on rmw_cyclonedds would: it
// publishes the base's and the head's geometry_msgs/PoseStamped. In `mhd run` the base
// pose it publishes is MHD's base estimate; opened alone, the plugin drops and counts
// poses in another frame and stale ones.
#include "../sim_backends/plugin_file.h"
#include "dds_common/dds_entity.h"
#include "dds_common/ros2_messages.h"
#include "dds_common/ros2_topics.h"
#include "dds_test_support.h"
#include "hardware_run.h"
#include "support/mhd_run_process.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <csignal>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;
namespace ros2 = mhd::dds::ros2;

/// The mocap driver: at 100 Hz, the base sensor and the head in the POMHI rig's is900
/// frame (x = -z_W, y = x_W, z = 2.624 m - y_W). The base sensor stands at its nominal
/// pose moved 0.3 m along world x, so the base is at (0.3, 0) m heading 0 (scenes/rigs/
/// pomhi.xml); the head is 1.65 m up, 0.9 m in front of the world origin.
class FakeMocap {
 public:
  FakeMocap(std::uint32_t domain, std::string frame_id, std::int64_t stamp_offset_ns = 0)
      : participant_(domain),
        base_topic_(participant_, geometry_msgs_msg_dds__PoseStamped__desc, "rt/mocap/base/pose", ros2::default_qos()),
        base_(participant_.handle(), base_topic_, ros2::default_qos()),
        head_topic_(participant_, geometry_msgs_msg_dds__PoseStamped__desc, "rt/mocap/head/pose", ros2::default_qos()),
        head_(participant_.handle(), head_topic_, ros2::default_qos()),
        frame_id_(std::move(frame_id)),
        stamp_offset_ns_(stamp_offset_ns),
        // rpy 180 0 180 is 180 degrees about y.
        base_pose_(pose_in(frame_id_, {0.206, 0.3, 1.4432}, {0.0, 1.0, 0.0, 0.0})),
        head_pose_(pose_in(frame_id_, {-0.9, 0.0, 0.974}, {0.0, 0.0, 0.0, 1.0})) {}
  FakeMocap(const FakeMocap&) = delete;
  FakeMocap& operator=(const FakeMocap&) = delete;

 private:
  static ros2::PoseStamped pose_in(std::string& frame_id, const geometry_msgs_msg_dds__Point_& p,
                                   const ros2::Quaternion& q) {
    ros2::PoseStamped pose{};
    pose.header.frame_id = frame_id.data();
    pose.pose.position = p;
    pose.pose.orientation = q;
    return pose;
  }

  mhd::dds::Participant participant_;
  mhd::dds::Topic base_topic_;
  mhd::dds::Writer<ros2::PoseStamped> base_;
  mhd::dds::Topic head_topic_;
  mhd::dds::Writer<ros2::PoseStamped> head_;
  std::string frame_id_;
  std::int64_t stamp_offset_ns_;
  ros2::PoseStamped base_pose_;
  ros2::PoseStamped head_pose_;
  mhd::dds::test::Repeating publisher_{std::chrono::milliseconds(10), [this] {
                                         base_pose_.header.stamp = head_pose_.header.stamp =
                                             ros2::ros_time(mhd::dds::realtime_ns() + stamp_offset_ns_);
                                         base_.write(base_pose_);
                                         head_.write(head_pose_);
                                       }};
};

TEST(Ros2Pose, TheMocapsBasePoseIsMhdsBaseEstimate) {
  const std::uint32_t domain = mhd::dds::test::use_loopback_and_unique_domain(11);
  const fs::path dir = mhd::test::scratch_dir("ros2_pose", "run");
  std::ofstream(dir / "scene.xml") << mhd::test::fill_scene_template(
      fs::path(MHD_SOURCE_DIR) / "tests/data/hardware/ros2_pose.xml",
      {{"value=\"DOMAIN\"", "value=\"" + std::to_string(domain) + "\""}});
  FakeMocap mocap(domain, "mocap");
  mhd::test::MhdRunProcess mhd({.argv = {MHD_CLI, "run", (dir / "scene.xml").string(), "--duration", "2", "-q",
                                         "--plugin-path", MHD_SIM_PLUGIN_DIR},
                                .dir = dir});
  const auto status = mhd.wait_for(std::chrono::seconds(30));
  ASSERT_TRUE(status && WIFEXITED(*status)) << mhd.output();
  EXPECT_EQ(WEXITSTATUS(*status), 0) << mhd.output();
  EXPECT_NE(mhd.output().find("ends at (0.300, 0.000) m"), std::string::npos) << mhd.output();
  // Every pose the mocap published was taken (the base stops once, before the first).
  EXPECT_NE(mhd.output().find(" samples, 0 dropped;"), std::string::npos) << mhd.output();
}

/// How a run with the mocap tracker ends: by a signal 2 s in, or by what the scene makes
/// happen (a crashing display, a base driver call that hangs).
struct MocapEndCase {
  const char* name;
  int signal;        ///< 0: none
  int status;        ///< the exit status
  const char* from;  ///< put `to` there in the scene
  const char* to;
  const char* says;
};

class Ros2PoseEnd : public ::testing::TestWithParam<MocapEndCase> {};

TEST_P(Ros2PoseEnd, TheArmIsLeftWithZeroForceAndTheBaseStopped) {
  namespace hw = mhd::test::hardware;
  const MocapEndCase c = GetParam();
  const std::uint32_t domain = mhd::dds::test::use_loopback_and_unique_domain(14);
  const fs::path dir = mhd::test::scratch_dir("ros2_pose_end", c.name);
  std::vector<std::pair<std::string, std::string>> fills{
      {"value=\"DOMAIN\"", "value=\"" + std::to_string(domain) + "\""}};
  if (c.from != nullptr) fills.emplace_back(c.from, c.to);
  std::ofstream(dir / "scene.xml") << mhd::test::fill_scene_template(
      fs::path(MHD_SOURCE_DIR) / "tests/data/hardware/ros2_pose.xml", fills);
  FakeMocap mocap(domain, "mocap");
  mhd::test::MhdRunProcess mhd({.argv = {MHD_CLI, "run", (dir / "scene.xml").string(), "--duration", "30", "-q",
                                         "--plugin-path", MHD_FAULT_INJECTION_PLUGIN_DIR, "--plugin-path",
                                         MHD_SIM_PLUGIN_DIR},
                                .dir = dir});
  if (c.signal != 0) {
    std::this_thread::sleep_for(std::chrono::seconds(2));
    mhd.signal(c.signal);
  }
  EXPECT_EQ(hw::exit_status(mhd), c.status) << mhd.output();
  EXPECT_TRUE(hw::has(mhd.output(), c.says)) << mhd.output();
  // The mocap's base pose was taken before the end: the base estimate moved off the start.
  EXPECT_FALSE(hw::has(mhd.output(), "tracker: 0 samples")) << mhd.output();
  hw::expect_last_command_zero(dir / "device.csv", mhd.output());
  // A base driver stuck for good gets no further command: its own command timeout must
  // stop it (docs/reliability.md, the fault matrix), and the run says so.
  if (c.from != nullptr && std::string(c.to).find("fi_omni3") != std::string::npos) {
    EXPECT_TRUE(hw::has(mhd.output(), "BASE STOP NOT CONFIRMED")) << mhd.output();
  } else {
    hw::expect_last_command_zero(dir / "base.csv", mhd.output());
  }
}

INSTANTIATE_TEST_SUITE_P(
    Ros2Pose, Ros2PoseEnd,
    ::testing::Values(
        MocapEndCase{"SIGINT", SIGINT, 0, nullptr, nullptr, "stopped by SIGINT"},
        MocapEndCase{"SIGTERM", SIGTERM, 0, nullptr, nullptr, "stopped by SIGTERM"},
        MocapEndCase{"SIGHUP", SIGHUP, 128 + SIGHUP, nullptr, nullptr, "stopped by SIGHUP"},
        // fi_crash's 150th frame: 2.5 s in, at 60 Hz.
        MocapEndCase{"crashed_plugin", 0, 4, "<!--EXTRA-->",
                "<plugin kind=\"display\" name=\"fi_crash\"><param name=\"crash\" value=\"abort\"/>"
                "<param name=\"crash_on_call\" value=\"150\"/></plugin>",
                "last gasp: zero torque sent, base stop sent"},
        // The base's driver hangs 2 s in: the call watchdog ends the run with zero force.
        MocapEndCase{"watchdog", 0, 3, "<plugin kind=\"base\" name=\"sim_omni3\">",
                     "<plugin kind=\"base\" name=\"fi_omni3\"><param name=\"fault\" value=\"hang\"/>"
                     "<param name=\"fault_call\" value=\"base_read\"/><param name=\"fault_after_s\" value=\"2\"/>",
                     "base_read has not returned"}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

/// The plugin opened alone; reads for `duration`, then its counters by name.
std::map<std::string, std::uint64_t> read_alone(std::uint32_t domain, std::chrono::milliseconds duration,
                                                std::size_t& samples) {
  mhd::test::PluginFile file(MHD_ROS2_POSE_PLUGIN);
  mhd::test::FakeHost host;
  mhd::test::StartedPlugin plugin(file.api(), host.host, {{"domain_id", std::to_string(domain).c_str()}});
  samples = 0;
  const auto end = std::chrono::steady_clock::now() + duration;
  while (std::chrono::steady_clock::now() < end) {
    std::array<mhd_tracker_sample, 16> out{};
    std::size_t count = 0;
    mhd_error err{};
    const mhd_status s = file.api().tracker_read(plugin.get(), out.data(), out.size(), &count, &err);
    EXPECT_TRUE(s == MHD_OK || s == MHD_NO_DATA) << err.message;
    samples += count;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::array<mhd_counter, 16> counters{};
  std::size_t n = 0;
  mhd_error err{};
  EXPECT_EQ(file.api().counters(plugin.get(), counters.data(), counters.size(), &n, &err), MHD_OK);
  std::map<std::string, std::uint64_t> by_name;
  for (std::size_t i = 0; i < n && i < counters.size(); ++i) by_name[counters[i].name] = counters[i].value;
  return by_name;
}

TEST(Ros2Pose, PosesInTheirFrameAreTakenAsTheirRolesSensors) {
  const std::uint32_t domain = mhd::dds::test::use_loopback_and_unique_domain(12);
  FakeMocap mocap(domain, "mocap");
  std::size_t samples = 0;
  const auto c = read_alone(domain, std::chrono::milliseconds(600), samples);
  EXPECT_GT(samples, 20u);
  EXPECT_EQ(c.at("accepted"), samples);
  EXPECT_EQ(c.at("dropped_wrong_frame"), 0u);
}

struct DroppedCase {
  const char* name;
  const char* frame_id;
  std::int64_t stamp_offset_ns;
  const char* counter;
};

class Ros2PoseDropped : public ::testing::TestWithParam<DroppedCase> {};

TEST_P(Ros2PoseDropped, NoPoseIsTakenAndEachIsCountedByItsReason) {
  const DroppedCase c = GetParam();
  const std::uint32_t domain = mhd::dds::test::use_loopback_and_unique_domain(13);
  FakeMocap mocap(domain, c.frame_id, c.stamp_offset_ns);
  std::size_t samples = 0;
  const auto counts = read_alone(domain, std::chrono::milliseconds(600), samples);
  EXPECT_EQ(samples, 0u);
  EXPECT_GT(counts.at(c.counter), 20u);
  EXPECT_EQ(counts.at("accepted"), 0u);
}

INSTANTIATE_TEST_SUITE_P(Ros2Pose, Ros2PoseDropped,
                         ::testing::Values(DroppedCase{"another_frame", "world", 0, "dropped_wrong_frame"},
                                           DroppedCase{"stamped_half_a_second_ago", "mocap", -500'000'000,
                                                       "dropped_stale"}),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

}  // namespace
