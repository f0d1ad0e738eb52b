#pragma once
// The rig's state as ROS 2 messages (ros2_msgs.idl): what the `ros2_state` display
// publishes for `ros2 topic echo` and rviz2 (docs/networking.md, "ROS 2"). Poses are of
// MHD's world frame W (y up, the floor y = 0), named by the header's frame_id; ROS's
// convention is z up, so rviz2 needs a static transform from its fixed frame to it.

#include "ros2_msgs.h"

#include <mhd/plugin_abi.h>

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace mhd::dds::ros2 {

using Time = builtin_interfaces_msg_dds__Time_;
using Quaternion = geometry_msgs_msg_dds__Quaternion_;
using PoseStamped = geometry_msgs_msg_dds__PoseStamped_;
using WrenchStamped = geometry_msgs_msg_dds__WrenchStamped_;
using JointState = sensor_msgs_msg_dds__JointState_;

/// The frame_id of the poses unless the scene names another: MHD's world, not ROS's
/// z-up "world".
inline constexpr const char* kDefaultFrameId = "mhd_world";

/// The base's planar pose as three joints of JointState, in this order: x and z on the
/// floor (m) and the heading about +y (rad), each in W.
inline constexpr std::array<const char*, 3> kBaseJointNames = {"base_x", "base_z", "base_heading"};

/// "mhd/rig<N>": the ROS namespace of rig N's topics.
[[nodiscard]] std::string default_namespace(std::uint32_t rig_id);
/// ROS 2's DDS name of the ROS topic "/<ros_namespace>/<name>": "rt/<ros_namespace>/<name>"
/// (rmw_cyclonedds's "rt" prefix for topics; leading and trailing slashes of the namespace
/// are ignored).
[[nodiscard]] std::string dds_topic_name(std::string_view ros_namespace, std::string_view name);

/// CLOCK_REALTIME nanoseconds as builtin_interfaces/Time (nanosec in [0, 1e9)).
[[nodiscard]] Time ros_time(std::int64_t realtime_ns);
/// A PoseStamped's stamp as CLOCK_REALTIME nanoseconds.
[[nodiscard]] std::int64_t stamp_ns(const Time& stamp);

/// MHD's (w, x, y, z) as ROS's Quaternion (x, y, z, w).
[[nodiscard]] Quaternion ros_quaternion(const double (&q_wxyz)[4]);
/// The base's orientation: heading h about +y (R_y(h), docs/simulation.md, "Conventions").
[[nodiscard]] Quaternion heading_quaternion(double heading_rad);

/// One frame's messages. The headers' frame_id and the joint names point into this
/// object, so it is neither copied nor moved; set() allocates nothing.
class RigMessages {
 public:
  explicit RigMessages(std::string frame_id);
  RigMessages(const RigMessages&) = delete;
  RigMessages& operator=(const RigMessages&) = delete;

  /// Fills every message from `frame`, stamped `stamp_ns` (CLOCK_REALTIME).
  void set(const mhd_display_frame& frame, std::int64_t stamp_ns);

  PoseStamped hip{};    ///< the HIP, orientation identity (a point: the device is 3-DoF)
  PoseStamped proxy{};  ///< the proxy on the surface, orientation identity
  PoseStamped base{};   ///< the base's origin on the floor, heading about +y
  PoseStamped head{};   ///< the user's head
  WrenchStamped force{};  ///< the force on the hand in W; torque zero (3-DoF device)
  JointState joints{};    ///< kBaseJointNames; no velocity or effort

 private:
  std::string frame_id_;
  std::array<char*, 3> joint_names_{};
  std::array<double, 3> joint_positions_{};
};

}  // namespace mhd::dds::ros2
