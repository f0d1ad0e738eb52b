// The `ros2_base` plugin against a plain Cyclone DDS peer that knows only ROS 2's topic and
// type names, as a ROS 2 base driver on rmw_cyclonedds would: it reads the twists on
// "rt/cmd_vel" and publishes odometry on "rt/odom". In `mhd run`, what the driver received
// is the hardware's view: the planner's twists, and a zero twist last. Opened alone
// (through dlopen), the plugin turns the driver's odometry into MHD's base state, and
// drops and counts what fails its checks.
#include "dds_common/dds_entity.h"
#include "dds_common/ros2_messages.h"
#include "dds_common/ros2_mobile_base.h"
#include "dds_common/ros2_topics.h"
#include "dds_test_support.h"
#include "support/mhd_run_process.h"
#include "support/scratch_dir.h"
#include "../sim_backends/plugin_file.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;
namespace ros2 = mhd::dds::ros2;
using mhd::test::MhdRunProcess;

/// The base driver: publishes odometry at 50 Hz (a base at x 0.25 m, y 0.1 m in odom, yaw
/// 0.3 rad, driving 0.2 m/s forward) in `odom_frame`, and keeps every twist it receives.
class FakeBaseDriver {
 public:
  FakeBaseDriver(std::uint32_t domain, std::string odom_frame)
      : participant_(domain),
        cmd_vel_topic_(participant_, geometry_msgs_msg_dds__Twist__desc, "rt/cmd_vel", ros2::default_qos()),
        cmd_vel_(participant_.handle(), cmd_vel_topic_, ros2::default_qos()),
        odom_topic_(participant_, nav_msgs_msg_dds__Odometry__desc, "rt/odom", ros2::default_qos()),
        odom_(participant_.handle(), odom_topic_, ros2::default_qos()),
        odom_frame_(std::move(odom_frame)),
        odometry_(standing_odometry()) {}
  FakeBaseDriver(const FakeBaseDriver&) = delete;
  FakeBaseDriver& operator=(const FakeBaseDriver&) = delete;

  /// Takes what arrived since the last call into twists().
  void receive() {
    for (const ros2::Twist& t : cmd_vel_.take()) twists_.push_back(t);
  }
  [[nodiscard]] const std::vector<ros2::Twist>& twists() const { return twists_; }

 private:
  ros2::Odometry standing_odometry() {
    ros2::Odometry odometry{};
    odometry.header.frame_id = odom_frame_.data();
    odometry.child_frame_id = child_frame_.data();
    odometry.pose.pose.position.x = 0.25;
    odometry.pose.pose.position.y = 0.1;
    odometry.pose.pose.orientation.z = std::sin(0.15);
    odometry.pose.pose.orientation.w = std::cos(0.15);
    odometry.twist.twist.linear.x = 0.2;
    return odometry;
  }

  mhd::dds::Participant participant_;
  mhd::dds::Topic cmd_vel_topic_;
  mhd::dds::Reader<ros2::Twist> cmd_vel_;
  mhd::dds::Topic odom_topic_;
  mhd::dds::Writer<ros2::Odometry> odom_;
  std::string odom_frame_;
  std::string child_frame_ = "base_link";
  ros2::Odometry odometry_;
  std::vector<ros2::Twist> twists_;
  mhd::dds::test::Repeating publisher_{std::chrono::milliseconds(20), [this] {
                                         odometry_.header.stamp = ros2::ros_time(mhd::dds::realtime_ns());
                                         odom_.write(odometry_);
                                       }};
};

bool is_zero(const ros2::Twist& t) {
  return t.linear.x == 0.0 && t.linear.y == 0.0 && t.linear.z == 0.0 && t.angular.x == 0.0 && t.angular.y == 0.0 &&
         t.angular.z == 0.0;
}

struct Ran {
  int status = -1;
  std::string output;
  std::vector<ros2::Twist> twists;
};

/// How a run of the ROS 2 base ends: by a signal after 3 s, or by what the scene makes
/// happen (a crashing display, a hanging tracker).
struct EndCase {
  const char* name;
  int signal;  ///< 0: none
  int status;  ///< the exit status
  const char* from;  ///< put `to` there in the scene (nullptr: nothing)
  const char* to;
  const char* says;
};

/// `mhd run` with the driver publishing odometry in "odom", ended as `c` says; the
/// twists the driver received.
Ran run_with_driver(const EndCase& c) {
  const std::uint32_t domain = mhd::dds::test::use_loopback_and_unique_domain(7);
  const fs::path dir = mhd::test::scratch_dir("ros2_base", c.name);
  std::vector<std::pair<std::string, std::string>> fills{
      {"value=\"DOMAIN\"", "value=\"" + std::to_string(domain) + "\""}};
  if (c.from != nullptr) fills.emplace_back(c.from, c.to);
  std::ofstream(dir / "scene.xml") << mhd::test::fill_scene_template(
      fs::path(MHD_SOURCE_DIR) / "tests/data/hardware/ros2_base.xml", fills);
  FakeBaseDriver driver(domain, "odom");
  MhdRunProcess mhd({.argv = {MHD_CLI, "run", (dir / "scene.xml").string(), "--duration", "30", "-q",
                              "--plugin-path", MHD_FAULT_INJECTION_PLUGIN_DIR, "--plugin-path", MHD_SIM_PLUGIN_DIR},
                     .dir = dir});
  Ran ran;
  const auto start = std::chrono::steady_clock::now();
  bool signalled = c.signal == 0;
  for (;;) {
    driver.receive();
    if (mhd.wait_for(std::chrono::milliseconds(10))) break;
    if (!signalled && std::chrono::steady_clock::now() - start > std::chrono::seconds(3)) {
      mhd.signal(c.signal);
      signalled = true;
    }
    if (std::chrono::steady_clock::now() - start > std::chrono::seconds(30)) break;
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the last twists in flight
  driver.receive();
  const auto status = mhd.wait_for(std::chrono::seconds(5));
  ran.status = status && WIFEXITED(*status) ? WEXITSTATUS(*status) : -1;
  ran.output = mhd.output();
  ran.twists = driver.twists();
  return ran;
}

class Ros2BaseEnd : public ::testing::TestWithParam<EndCase> {};

TEST_P(Ros2BaseEnd, TheDriverSeesThePlannersTwistsThenAZeroLast) {
  const EndCase c = GetParam();
  const Ran ran = run_with_driver(c);
  EXPECT_EQ(ran.status, c.status) << ran.output;
  EXPECT_NE(ran.output.find(c.says), std::string::npos) << ran.output;
  ASSERT_FALSE(ran.twists.empty()) << "no twist reached the driver: " << ran.output;
  EXPECT_TRUE(std::any_of(ran.twists.begin(), ran.twists.end(), [](const ros2::Twist& t) { return !is_zero(t); }))
      << "the planner never moved the base: " << ran.output;
  EXPECT_TRUE(is_zero(ran.twists.back())) << "last twist " << ran.twists.back().linear.x << " "
                                          << ran.twists.back().linear.y << " " << ran.twists.back().angular.z;
}

INSTANTIATE_TEST_SUITE_P(
    Ros2Base, Ros2BaseEnd,
    ::testing::Values(
        EndCase{"SIGINT", SIGINT, 0, nullptr, nullptr, "stopped by SIGINT"},
        EndCase{"SIGTERM", SIGTERM, 0, nullptr, nullptr, "stopped by SIGTERM"},
        EndCase{"SIGHUP", SIGHUP, 128 + SIGHUP, nullptr, nullptr, "stopped by SIGHUP"},
        // fi_crash's 150th frame: 2.5 s in, at 60 Hz.
        EndCase{"crashed_plugin", 0, 4, "<!--EXTRA-->",
                "<plugin kind=\"display\" name=\"fi_crash\"><param name=\"crash\" value=\"abort\"/>"
                "<param name=\"crash_on_call\" value=\"150\"/></plugin>",
                "last gasp: zero torque sent, base stop sent"},
        EndCase{"watchdog", 0, 3, "<plugin kind=\"tracker\" name=\"sim_is900\">",
                "<plugin kind=\"tracker\" name=\"fi_is900\"><param name=\"fault\" value=\"hang\"/>"
                "<param name=\"fault_call\" value=\"tracker_read\"/><param name=\"fault_after_s\" value=\"2\"/>",
                "tracker_read has not returned"}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(Ros2Base, WithBasePoseSourceOdometryTheDriversOdometryIsMhdsBaseEstimate) {
  // <server> base_pose_source odometry: the tracker's base sensor is not used; the driver's
  // odometry (x 0.25 m, y 0.1 m, yaw 0.3 rad in odom = the world) is the base pose.
  const Ran ran = run_with_driver(EndCase{"odometry", SIGINT, 0, "<!--SERVER-->",
                                          "<server><param name=\"base_pose_source\" value=\"odometry\"/>"
                                          "<param name=\"predict_base_pose\" value=\"false\"/></server>",
                                          "stopped by SIGINT"});
  EXPECT_EQ(ran.status, 0) << ran.output;
  EXPECT_NE(ran.output.find("ends at (0.250, -0.100) m"), std::string::npos) << ran.output;
  ASSERT_FALSE(ran.twists.empty()) << ran.output;
  EXPECT_TRUE(is_zero(ran.twists.back()));
}

TEST(Ros2Base, ByDefaultTheTrackerNotTheOdometryIsTheBaseEstimate) {
  const Ran ran = run_with_driver(EndCase{"tracker", SIGINT, 0, "<!--SERVER-->",
                                          "<server><param name=\"predict_base_pose\" value=\"false\"/></server>",
                                          "stopped by SIGINT"});
  EXPECT_EQ(ran.status, 0) << ran.output;
  EXPECT_NE(ran.output.find("ends at ("), std::string::npos) << ran.output;
  EXPECT_EQ(ran.output.find("ends at (0.250, -0.100) m"), std::string::npos) << ran.output;
}

// ---- the plugin alone, through dlopen --------------------------------------------------

struct OpenedBase {
  mhd::test::PluginFile file{MHD_ROS2_BASE_PLUGIN};
  mhd::test::FakeHost host;
  mhd::test::StartedPlugin plugin;
  explicit OpenedBase(std::uint32_t domain)
      : plugin(file.api(), host.host, {{"domain_id", std::to_string(domain).c_str()}}) {}
  /// base_read until it gives a state or 5 s pass.
  std::optional<mhd_base_state> read() {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (std::chrono::steady_clock::now() < give_up) {
      mhd_base_state state{};
      mhd_error err{};
      const mhd_status status = file.api().base_read(plugin.get(), &state, &err);
      if (status == MHD_OK) return state;
      if (status != MHD_NO_DATA) throw std::runtime_error(err.message);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return std::nullopt;
  }
  std::uint64_t counter(const std::string& name) {
    std::array<mhd_counter, 8> out{};
    std::size_t n = 0;
    mhd_error err{};
    if (file.api().counters(plugin.get(), out.data(), out.size(), &n, &err) != MHD_OK) throw std::runtime_error(err.message);
    for (std::size_t i = 0; i < n && i < out.size(); ++i) {
      if (name == out[i].name) return out[i].value;
    }
    throw std::runtime_error("no counter " + name);
  }
};

TEST(Ros2Base, ADriversOdometryBecomesTheBaseStateInMhdsWorld) {
  const std::uint32_t domain = mhd::dds::test::use_loopback_and_unique_domain(8);
  OpenedBase base(domain);
  FakeBaseDriver driver(domain, "odom");
  const auto state = base.read();
  ASSERT_TRUE(state) << "no odometry reached base_read";
  // ROS's z-up odom (x forward, y left) in MHD's y-up world: x stays, z = -y, heading = yaw.
  EXPECT_NEAR(state->x_m, 0.25, 1e-12);
  EXPECT_NEAR(state->z_m, -0.1, 1e-12);
  EXPECT_NEAR(state->heading_rad, 0.3, 1e-12);
  // 0.2 m/s forward at heading 0.3 rad, in the world frame.
  EXPECT_NEAR(state->vx_mps, 0.2 * std::cos(0.3), 1e-12);
  EXPECT_NEAR(state->vz_mps, -0.2 * std::sin(0.3), 1e-12);
  // Stamped now: the host time it carries is within a second of the fake host's clock.
  EXPECT_NEAR(state->timestamp_s, base.host.now_s, 1.0);
  EXPECT_GT(base.counter("accepted"), 0u);
  EXPECT_EQ(base.counter("dropped_wrong_frame"), 0u);
}

TEST(Ros2Base, OdometryInAnotherFrameIsDroppedAndCounted) {
  const std::uint32_t domain = mhd::dds::test::use_loopback_and_unique_domain(9);
  OpenedBase base(domain);
  FakeBaseDriver driver(domain, "map");
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  mhd_base_state state{};
  mhd_error err{};
  for (int i = 0; i < 50; ++i) {
    EXPECT_EQ(base.file.api().base_read(base.plugin.get(), &state, &err), MHD_NO_DATA);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_GT(base.counter("dropped_wrong_frame"), 0u);
  EXPECT_EQ(base.counter("accepted"), 0u);
}

// ---- the conversions -------------------------------------------------------------------

ros2::Odometry good_odometry(std::string& odom, std::string& child) {
  ros2::Odometry o{};
  o.header.frame_id = odom.data();
  o.child_frame_id = child.data();
  o.header.stamp = ros2::ros_time(mhd::dds::realtime_ns());
  o.pose.pose.orientation.w = 1.0;
  return o;
}

TEST(Ros2MobileBase, ACommandBecomesATwistInBaseLink) {
  mhd_base_command c{};
  c.vx_mps = 0.3;
  c.vz_mps = 0.1;  // to the right
  c.omega_radps = 0.5;
  const ros2::Twist t = ros2::twist_of(c);
  EXPECT_EQ(t.linear.x, 0.3);
  EXPECT_EQ(t.linear.y, -0.1);  // ROS's y is to the left
  EXPECT_EQ(t.angular.z, 0.5);
  EXPECT_EQ(t.linear.z, 0.0);
  EXPECT_EQ(t.angular.x, 0.0);
  EXPECT_EQ(t.angular.y, 0.0);
}

TEST(Ros2MobileBase, EachCheckRefusesItsBadOdometryAndPassesTheGoodOne) {
  std::string odom = "odom";
  std::string child = "base_link";
  const ros2::OdometryCheck check{"odom", "base_link", mhd::dds::realtime_ns()};
  mhd_base_state out{};
  ros2::Odometry o = good_odometry(odom, child);
  EXPECT_EQ(ros2::base_state_of(o, check, out), ros2::OdometryVerdict::Accepted);
  for (const double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
    o = good_odometry(odom, child);
    o.pose.pose.position.x = bad;
    EXPECT_EQ(ros2::base_state_of(o, check, out), ros2::OdometryVerdict::NotFinite);
    o = good_odometry(odom, child);
    o.twist.twist.angular.z = bad;
    EXPECT_EQ(ros2::base_state_of(o, check, out), ros2::OdometryVerdict::NotFinite);
  }
  o = good_odometry(odom, child);
  o.pose.pose.orientation.w = 0.5;
  EXPECT_EQ(ros2::base_state_of(o, check, out), ros2::OdometryVerdict::NotUnitQuaternion);
  o.pose.pose.orientation.w = 1.005;  // within 1 %: normalised
  EXPECT_EQ(ros2::base_state_of(o, check, out), ros2::OdometryVerdict::Accepted);
  o = good_odometry(odom, child);
  o.header.stamp = ros2::ros_time(check.now_ns + 1'000'000'000);  // a second ahead
  EXPECT_EQ(ros2::base_state_of(o, check, out), ros2::OdometryVerdict::BadStamp);
  o.header.stamp = ros2::Time{};  // never stamped
  EXPECT_EQ(ros2::base_state_of(o, check, out), ros2::OdometryVerdict::BadStamp);
  std::string other = "base_footprint";
  o = good_odometry(odom, other);
  EXPECT_EQ(ros2::base_state_of(o, check, out), ros2::OdometryVerdict::WrongFrame);
  o.child_frame_id = nullptr;
  EXPECT_EQ(ros2::base_state_of(o, check, out), ros2::OdometryVerdict::WrongFrame);
}

}  // namespace
