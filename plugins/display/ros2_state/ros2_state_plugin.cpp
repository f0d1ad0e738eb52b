// The `ros2_state` display plugin: every mhd_display_frame it gets becomes the rig's ROS 2
// messages (ros2_messages.h) on ROS 2's DDS topics, stamped on CLOCK_REALTIME:
// PoseStamped on <ns>/hip_pose, proxy_pose, base_pose and head_pose, WrenchStamped on
// <ns>/force, JointState on <ns>/joint_states, with <ns> "mhd/rig<rig_id>" unless the
// scene names another. Called on the server's 60 Hz display thread, never the haptic one.

#include "dds_common/dds_convert.h"
#include "dds_common/dds_plugin_params.h"
#include "dds_common/ros2_messages.h"
#include "dds_common/ros2_topics.h"
#include "sim_common/plugin_params.h"
#include "sim_common/plugin_shell.h"

#include <mhd/plugin_abi.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

namespace mhd::ros2_state {
namespace {

using plugin_support::guarded_open;
namespace ros2 = dds::ros2;

struct Config {
  dds::DdsEndpoint endpoint;
  std::string ros_namespace;
  std::string frame_id;
};

struct Instance {
  Instance(const mhd_host& h, const Config& c)
      : host(h),
        participant(c.endpoint.domain_id, c.endpoint.config, c.endpoint.identity_dir),
        hip(participant, geometry_msgs_msg_dds__PoseStamped__desc, topic(c, ros2::TopicNames::hip)),
        proxy(participant, geometry_msgs_msg_dds__PoseStamped__desc, topic(c, ros2::TopicNames::proxy)),
        base(participant, geometry_msgs_msg_dds__PoseStamped__desc, topic(c, ros2::TopicNames::base)),
        head(participant, geometry_msgs_msg_dds__PoseStamped__desc, topic(c, ros2::TopicNames::head)),
        force(participant, geometry_msgs_msg_dds__WrenchStamped__desc, topic(c, ros2::TopicNames::force)),
        joints(participant, sensor_msgs_msg_dds__JointState__desc, topic(c, ros2::TopicNames::joints)),
        messages(c.frame_id) {}

  static std::string topic(const Config& c, const char* name) { return ros2::dds_topic_name(c.ros_namespace, name); }

  std::atomic<bool> in_call{false};  ///< plugin_support::with_instance's
  mhd_host host;
  dds::Participant participant;
  ros2::RosPublisher<ros2::PoseStamped> hip, proxy, base, head;
  ros2::RosPublisher<ros2::WrenchStamped> force;
  ros2::RosPublisher<ros2::JointState> joints;
  ros2::RigMessages messages;
  bool started = false;
};

/// A ROS name: letters, digits, '_' and '/' (ROS 2's rules, which DDS topic names take too).
std::string checked_ros_name(const char* parameter, std::string value) {
  for (const char c : value) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '/';
    if (!ok) {
      throw plugin_support::ParamError("parameter '" + std::string(parameter) + "' = '" + value +
                                       "': a ROS name has letters, digits, '_' and '/' only");
    }
  }
  return value;
}

constexpr std::array kParams =
    sdk::join(dds::kEndpointParams,
              std::array{sdk::text("namespace", nullptr, "the ROS namespace of the topics (default /mhd/rig<rig_id>)"),
                         sdk::text("frame_id", "mhd_world", "the frame_id of the poses and wrenches")});

Config read_config(const mhd_param* params, std::size_t count, const char* scene_file) {
  plugin_support::ParamReader reader(kParams, params, count);
  Config c;
  c.endpoint = dds::read_endpoint(reader, params, count, scene_file);
  c.ros_namespace = checked_ros_name(
      "namespace", reader.optional_text("namespace").value_or(ros2::default_namespace(c.endpoint.rig_id)));
  c.frame_id = checked_ros_name("frame_id", reader.optional_text("frame_id").value_or(ros2::kDefaultFrameId));
  reader.reject_unknown();
  return c;
}

mhd_plugin_instance* open_instance(const mhd_host* host, const mhd_param* params, size_t param_count, mhd_error* err) {
  return guarded_open(err, [&] {
    plugin_support::check_host(host);
    const Config config = read_config(params, param_count, host->scene_file);
    return reinterpret_cast<mhd_plugin_instance*>(new Instance(*host, config));
  });
}

template <class F>
mhd_status call(mhd_plugin_instance* self, plugin_support::Need need, mhd_error* err, F&& f) {
  return plugin_support::with_instance<Instance>(MHD_PLUGIN_NAME, self, need, err, std::forward<F>(f));
}

mhd_status start_instance(mhd_plugin_instance* self, mhd_error* err) {
  return call(self, plugin_support::Need::Open, err, [&](Instance& s) {
    s.started = true;
    return MHD_OK;
  });
}

mhd_status stop_instance(mhd_plugin_instance* self, mhd_error* err) {
  return call(self, plugin_support::Need::Open, err, [&](Instance& s) {
    s.started = false;
    return MHD_OK;
  });
}

void close_instance(mhd_plugin_instance* self) { delete reinterpret_cast<Instance*>(self); }

mhd_status display_write(mhd_plugin_instance* self, const mhd_display_frame* frame, mhd_error* err) {
  return call(self, plugin_support::Need::Running, err, [&](Instance& s) {
    if (frame == nullptr) throw std::invalid_argument("display_write: NULL frame");
    const std::int64_t stamp_ns =
        dds::realtime_from_host(frame->timestamp_s, plugin_support::host_now(s.host), dds::realtime_ns());
    s.messages.set(*frame, stamp_ns);
    s.hip.write(s.messages.hip);
    s.proxy.write(s.messages.proxy);
    s.base.write(s.messages.base);
    s.head.write(s.messages.head);
    s.force.write(s.messages.force);
    s.joints.write(s.messages.joints);
    return MHD_OK;
  });
}

constexpr mhd_plugin_api kApi = {
    .abi_version = MHD_PLUGIN_ABI_VERSION,
    .struct_size = sizeof(mhd_plugin_api),
    .kind = MHD_PLUGIN_KIND,
    .name = MHD_PLUGIN_NAME,
    .version = "1.0.0",
    .description = "Publishes the rig's state as ROS 2 messages (PoseStamped, WrenchStamped, JointState) over Cyclone DDS",
    .open = open_instance,
    .start = start_instance,
    .stop = stop_instance,
    .close = close_instance,
    .params = kParams.data(),
    .param_count = kParams.size(),
    .device_info = nullptr,
    .device_read = nullptr,
    .device_write = nullptr,
    .tracker_read = nullptr,
    .base_read = nullptr,
    .base_write = nullptr,
    .display_write = display_write,
    .simulate_until = nullptr,
    .tracker_wait = nullptr,
    .counters = nullptr,
};

}  // namespace
}  // namespace mhd::ros2_state

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  return host_abi_version == MHD_PLUGIN_ABI_VERSION ? &mhd::ros2_state::kApi : nullptr;
}
