// The `ros2_state` display plugin: every mhd_display_frame it gets becomes the rig's ROS 2
// messages (ros2_messages.h) on ROS 2's DDS topics, stamped on CLOCK_REALTIME:
// PoseStamped on <ns>/hip_pose, proxy_pose, base_pose and head_pose, WrenchStamped on
// <ns>/force, JointState on <ns>/joint_states, with <ns> "mhd/rig<rig_id>" unless the
// scene names another. Called on the server's 60 Hz display thread, never the haptic one.

#include "dds_common/dds_convert.h"
#include "dds_common/dds_plugin_params.h"
#include "dds_common/ros2_messages.h"
#include "dds_common/ros2_topics.h"

#include <mhd/plugin_sdk.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>

namespace mhd::ros2_state {
namespace ros2 = dds::ros2;

struct Config {
  dds::DdsEndpoint endpoint;
  std::string ros_namespace;
  std::string frame_id;
};

class Ros2StatePlugin {
 public:
  static constexpr std::array kParams =
      sdk::join(dds::kEndpointParams,
                std::array{sdk::text("namespace", nullptr, "the ROS namespace of the topics (default /mhd/rig<rig_id>)"),
                           sdk::text("frame_id", "mhd_world", "the frame_id of the poses and wrenches")});

  Ros2StatePlugin(const mhd_host& host, const sdk::Params& params)
      : Ros2StatePlugin(host, read_config(params, host.scene_file)) {}

  void display_write(const mhd_display_frame& frame) {
    // A frame of no newer snapshot is no news. A topic's stamps only go forward, whatever
    // the jitter between the two clocks read for the conversion (a preemption between them).
    if (frame.timestamp_s <= last_timestamp_s_) return;
    last_timestamp_s_ = frame.timestamp_s;
    const std::int64_t stamp_ns = std::max(
        dds::realtime_from_host(frame.timestamp_s, sdk::host_now(host_), dds::realtime_ns()), last_stamp_ns_ + 1);
    last_stamp_ns_ = stamp_ns;
    messages_.set(frame, stamp_ns);
    hip_.write(messages_.hip);
    proxy_.write(messages_.proxy);
    base_.write(messages_.base);
    head_.write(messages_.head);
    force_.write(messages_.force);
    joints_.write(messages_.joints);
  }

 private:
  Ros2StatePlugin(const mhd_host& host, const Config& c)
      : host_(host),
        participant_(c.endpoint.domain_id, c.endpoint.config, c.endpoint.identity_dir),
        hip_(participant_, geometry_msgs_msg_dds__PoseStamped__desc, topic(c, ros2::TopicNames::hip)),
        proxy_(participant_, geometry_msgs_msg_dds__PoseStamped__desc, topic(c, ros2::TopicNames::proxy)),
        base_(participant_, geometry_msgs_msg_dds__PoseStamped__desc, topic(c, ros2::TopicNames::base)),
        head_(participant_, geometry_msgs_msg_dds__PoseStamped__desc, topic(c, ros2::TopicNames::head)),
        force_(participant_, geometry_msgs_msg_dds__WrenchStamped__desc, topic(c, ros2::TopicNames::force)),
        joints_(participant_, sensor_msgs_msg_dds__JointState__desc, topic(c, ros2::TopicNames::joints)),
        messages_(c.frame_id) {}

  static std::string topic(const Config& c, const char* name) { return ros2::dds_topic_name(c.ros_namespace, name); }

  static Config read_config(const sdk::Params& params, const char* scene_file) {
    Config c;
    c.endpoint = dds::read_endpoint(params, scene_file);
    c.ros_namespace = dds::checked_ros_name(
        "namespace", params.optional_text("namespace").value_or(ros2::default_namespace(c.endpoint.rig_id)));
    c.frame_id = dds::checked_ros_name("frame_id", params.optional_text("frame_id").value_or(ros2::kDefaultFrameId));
    return c;
  }

  mhd_host host_;
  dds::Participant participant_;
  ros2::RosPublisher<ros2::PoseStamped> hip_, proxy_, base_, head_;
  ros2::RosPublisher<ros2::WrenchStamped> force_;
  ros2::RosPublisher<ros2::JointState> joints_;
  ros2::RigMessages messages_;
  double last_timestamp_s_ = -std::numeric_limits<double>::infinity();
  std::int64_t last_stamp_ns_ = std::numeric_limits<std::int64_t>::min() + 1;
};

}  // namespace mhd::ros2_state

MHD_PLUGIN_ENTRY(mhd::ros2_state::Ros2StatePlugin,
                 {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                  .description = "Publishes the rig's state as ROS 2 messages (PoseStamped, WrenchStamped, "
                                 "JointState) over Cyclone DDS"})
