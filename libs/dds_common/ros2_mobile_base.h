#pragma once
// A ROS 2 mobile base as MHD sees it (the `ros2_base` plugin): MHD's base command as the
// geometry_msgs/Twist a base driver takes on cmd_vel, and the nav_msgs/Odometry it
// publishes as MHD's base state. ROS's frames (REP 103) are z up, x forward, y left; MHD's
// world is y up with the floor y = 0 (docs/simulation.md, "Conventions"), so
//   x_W = x_odom, z_W = -y_odom, heading (about +y_W) = yaw (about +z_odom),
// and in the base's own frame ROS's y (left) is MHD's -z (right). Both turn the same way.

#include "ros2_msgs.h"

#include <mhd/plugin_abi.h>

#include <cstdint>
#include <string>

namespace mhd::dds::ros2 {

using Twist = geometry_msgs_msg_dds__Twist_;
using Odometry = nav_msgs_msg_dds__Odometry_;

/// MHD's base command (x forward, y up, z right; omega about +y) as a Twist in base_link.
[[nodiscard]] Twist twist_of(const mhd_base_command& command);

/// Why an odometry message was not taken.
enum class OdometryVerdict { Accepted, WrongFrame, NotFinite, NotUnitQuaternion, BadStamp };

struct OdometryCheck {
  std::string odom_frame;  ///< header.frame_id it must carry
  std::string base_frame;  ///< child_frame_id it must carry
  std::int64_t now_ns = 0; ///< CLOCK_REALTIME now: a stamp more than 0.1 s ahead is refused
};

/// The odometry as MHD's base state (its timestamp_s left for the caller, which knows the
/// host clock), or why not. The pose is in the odom frame, the twist in base_link (ROS's
/// convention); MHD's velocities are in the world frame. A quaternion within 1 % of unit
/// length is normalised.
[[nodiscard]] OdometryVerdict base_state_of(const Odometry& odometry, const OdometryCheck& check,
                                            mhd_base_state& out);

/// The stamp as CLOCK_REALTIME nanoseconds.
[[nodiscard]] std::int64_t stamp_ns(const Odometry& odometry);

}  // namespace mhd::dds::ros2
