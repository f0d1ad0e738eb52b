// The `ros2_base` plugin: a mobile base driven through ROS 2 over Cyclone DDS, with ROS 2's
// type names and no ROS dependency (as `ros2_state` publishes). Each base command becomes
// a geometry_msgs/Twist on cmd_vel; nav_msgs/Odometry from the base's driver becomes MHD's
// base state (ros2_mobile_base.h: frames and checks). Stale odometry is the host's to
// judge (its base timeout stops the base); a base driver must stop by itself when
// cmd_vel falls silent, as ROS 2 base drivers do.

#include "dds_common/dds_convert.h"
#include "dds_common/dds_plugin_params.h"
#include "dds_common/ros2_mobile_base.h"
#include "dds_common/ros2_topics.h"

#include <mhd/plugin_sdk.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <string>

namespace mhd::ros2_base {
namespace ros2 = dds::ros2;

struct Config {
  dds::DdsEndpoint endpoint;
  std::string cmd_vel_topic;
  std::string odom_topic;
  ros2::OdometryCheck check;
};

class Ros2BasePlugin {
 public:
  static constexpr std::array kParams = sdk::join(
      dds::kEndpointParams,
      std::array{sdk::text("cmd_vel_topic", "/cmd_vel", "the ROS topic the base driver takes Twist commands on"),
                 sdk::text("odom_topic", "/odom", "the ROS topic the base driver publishes Odometry on"),
                 sdk::text("odom_frame", "odom", "the frame_id odometry must carry"),
                 sdk::text("base_frame", "base_link", "the child_frame_id odometry must carry")});

  Ros2BasePlugin(const mhd_host& host, const sdk::Params& params) : Ros2BasePlugin(host, read_config(params)) {}

  /// A zero twist before and after: the driver's first and last commands are stops.
  void start() { cmd_vel_.write(ros2::Twist{}); }
  void stop() { cmd_vel_.write(ros2::Twist{}); }

  void base_write(const mhd_base_command& command) { cmd_vel_.write(ros2::twist_of(command)); }

  /// The newest odometry that passes the checks since the last read.
  mhd_status base_read(mhd_base_state& out) {
    check_.now_ns = dds::realtime_ns();
    bool fresh = false;
    std::array<void*, 16> samples{};
    std::array<dds_sample_info_t, 16> infos{};
    for (;;) {
      samples.fill(nullptr);  // null: Cyclone lends the samples
      const dds_return_t n = dds::check(dds_take(odom_reader_.handle(), samples.data(), infos.data(), samples.size(),
                                                 static_cast<std::uint32_t>(samples.size())),
                                        "dds_take");
      for (dds_return_t i = 0; i < n; ++i) {
        const auto k = static_cast<std::size_t>(i);
        if (infos[k].valid_data) fresh = take(*static_cast<const ros2::Odometry*>(samples[k]), out) || fresh;
      }
      if (n > 0) dds_return_loan(odom_reader_.handle(), samples.data(), n);
      if (n < static_cast<dds_return_t>(samples.size())) break;
    }
    return fresh ? MHD_OK : MHD_NO_DATA;
  }

  std::size_t counters(std::span<mhd_counter> out) const {
    const std::array<mhd_counter, 5> all{
        mhd_counter{"accepted", accepted_},
        mhd_counter{"dropped_wrong_frame", dropped_[1]},
        mhd_counter{"dropped_not_finite", dropped_[2]},
        mhd_counter{"dropped_not_unit_quaternion", dropped_[3]},
        mhd_counter{"dropped_bad_stamp", dropped_[4]},
    };
    for (std::size_t i = 0; i < out.size() && i < all.size(); ++i) out[i] = all[i];
    return all.size();
  }

 private:
  Ros2BasePlugin(const mhd_host& host, const Config& c)
      : host_(host),
        participant_(c.endpoint.domain_id, c.endpoint.config, c.endpoint.identity_dir),
        cmd_vel_(participant_, geometry_msgs_msg_dds__Twist__desc, ros2::dds_topic_name("", c.cmd_vel_topic)),
        odom_topic_(participant_, nav_msgs_msg_dds__Odometry__desc, ros2::dds_topic_name("", c.odom_topic).c_str(),
                    ros2::default_qos()),
        // Best effort matches a driver's reliable and its best-effort ("sensor data") writers.
        odom_reader_(dds::check(dds_create_reader(participant_.handle(), odom_topic_.handle(),
                                                  dds::Qos::best_effort(10).get(), nullptr),
                                "dds_create_reader")),
        check_(c.check) {}

  static Config read_config(const sdk::Params& params) {
    Config c;
    c.endpoint = dds::read_endpoint(params, nullptr);
    c.cmd_vel_topic = dds::checked_ros_name("cmd_vel_topic", params.text("cmd_vel_topic"));
    c.odom_topic = dds::checked_ros_name("odom_topic", params.text("odom_topic"));
    c.check.odom_frame = dds::checked_ros_name("odom_frame", params.text("odom_frame"));
    c.check.base_frame = dds::checked_ros_name("base_frame", params.text("base_frame"));
    return c;
  }

  /// Takes one message into `out` when it passes; counts it either way.
  bool take(const ros2::Odometry& odometry, mhd_base_state& out) {
    mhd_base_state state{};
    const ros2::OdometryVerdict verdict = ros2::base_state_of(odometry, check_, state);
    if (verdict != ros2::OdometryVerdict::Accepted) {
      ++dropped_[static_cast<std::size_t>(verdict)];
      return false;
    }
    ++accepted_;
    state.timestamp_s = dds::host_from_realtime(ros2::stamp_ns(odometry), sdk::host_now(host_), check_.now_ns);
    out = state;
    return true;
  }

  mhd_host host_;
  dds::Participant participant_;
  ros2::RosPublisher<ros2::Twist> cmd_vel_;
  dds::Topic odom_topic_;
  dds::Entity odom_reader_;
  ros2::OdometryCheck check_;
  std::uint64_t accepted_ = 0;
  std::array<std::uint64_t, 5> dropped_{};
};

}  // namespace mhd::ros2_base

MHD_PLUGIN_ENTRY(mhd::ros2_base::Ros2BasePlugin,
                 {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                  .description = "A ROS 2 mobile base over Cyclone DDS: Twist on cmd_vel, Odometry in"})
