#include "dds_common/ros2_messages.h"

#include <cmath>

namespace mhd::dds::ros2 {
namespace {

std::string_view trim_slashes(std::string_view s) {
  while (!s.empty() && s.front() == '/') s.remove_prefix(1);
  while (!s.empty() && s.back() == '/') s.remove_suffix(1);
  return s;
}

geometry_msgs_msg_dds__Point_ point(const double (&p)[3]) { return {p[0], p[1], p[2]}; }

constexpr Quaternion kIdentity{0.0, 0.0, 0.0, 1.0};

}  // namespace

std::string default_namespace(std::uint32_t rig_id) { return "mhd/rig" + std::to_string(rig_id); }

std::string dds_topic_name(std::string_view ros_namespace, std::string_view name) {
  const std::string_view ns = trim_slashes(ros_namespace);
  std::string out = "rt/";
  if (!ns.empty()) {
    out += ns;
    out += '/';
  }
  out += trim_slashes(name);
  return out;
}

std::int64_t stamp_ns(const Time& stamp) { return std::int64_t{stamp.sec} * 1'000'000'000 + stamp.nanosec; }

Time ros_time(std::int64_t realtime_ns) {
  constexpr std::int64_t kNsPerS = 1'000'000'000;
  // Floor division: a time before 1970 still has nanosec in [0, 1e9).
  std::int64_t sec = realtime_ns / kNsPerS;
  std::int64_t nanosec = realtime_ns % kNsPerS;
  if (nanosec < 0) {
    nanosec += kNsPerS;
    --sec;
  }
  return {static_cast<std::int32_t>(sec), static_cast<std::uint32_t>(nanosec)};
}

Quaternion ros_quaternion(const double (&q_wxyz)[4]) { return {q_wxyz[1], q_wxyz[2], q_wxyz[3], q_wxyz[0]}; }

Quaternion heading_quaternion(double heading_rad) {
  return {0.0, std::sin(heading_rad / 2.0), 0.0, std::cos(heading_rad / 2.0)};
}

RigMessages::RigMessages(std::string frame_id) : frame_id_(std::move(frame_id)) {
  for (std::size_t i = 0; i < kBaseJointNames.size(); ++i) {
    // The C types hold char*; DDS only reads them when writing.
    joint_names_[i] = const_cast<char*>(kBaseJointNames[i]);
  }
  for (PoseStamped* p : {&hip, &proxy, &base, &head}) p->header.frame_id = frame_id_.data();
  force.header.frame_id = frame_id_.data();
  // JointState names joints, not a frame (ROS leaves its frame_id empty).
  joints.header.frame_id = const_cast<char*>("");
  constexpr auto kJoints = static_cast<std::uint32_t>(kBaseJointNames.size());
  // _release false: DDS never frees what these point to.
  joints.name = {._maximum = kJoints, ._length = kJoints, ._buffer = joint_names_.data(), ._release = false};
  joints.position = {._maximum = kJoints, ._length = kJoints, ._buffer = joint_positions_.data(), ._release = false};
  joints.velocity = {._maximum = 0, ._length = 0, ._buffer = nullptr, ._release = false};
  joints.effort = {._maximum = 0, ._length = 0, ._buffer = nullptr, ._release = false};
}

void RigMessages::set(const mhd_display_frame& f, std::int64_t stamp_ns) {
  const Time stamp = ros_time(stamp_ns);
  for (PoseStamped* p : {&hip, &proxy, &base, &head}) p->header.stamp = stamp;
  force.header.stamp = stamp;
  joints.header.stamp = stamp;

  hip.pose = {point(f.p_W_hip_m), kIdentity};
  proxy.pose = {point(f.p_W_proxy_m), kIdentity};
  base.pose = {{f.base_x_m, 0.0, f.base_z_m}, heading_quaternion(f.base_heading_rad)};
  head.pose = {point(f.p_W_head_m), ros_quaternion(f.q_W_head_wxyz)};
  force.wrench.force = {f.force_W_N[0], f.force_W_N[1], f.force_W_N[2]};
  force.wrench.torque = {0.0, 0.0, 0.0};
  joint_positions_ = {f.base_x_m, f.base_z_m, f.base_heading_rad};
}

}  // namespace mhd::dds::ros2
