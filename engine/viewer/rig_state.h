#pragma once
// What the viewer draws of the rig: one snapshot in the world frame W (y up, floor
// y = 0), as a display frame (plugin_host/hardware_io.h) describes it.
//
// The head frame H follows the simulated user's: x forward (the gaze), y up, z to the
// right (right-handed), so a head with heading h about +y looks along (cos h, 0, -sin h).

#include "diagnostics/result.h"
#include "geometry/pose.h"
#include "kinematics/base_pose.h"
#include "plugin_host/hardware_io.h"

#include <Eigen/Core>

#include <optional>
#include <string>

namespace mhd::viewer {

struct RigState {
  double timestamp_s = 0.0;
  Eigen::Vector3d p_W_hip_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_W_proxy_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_W_N = Eigen::Vector3d::Zero();
  bool in_contact = false;
  BasePose base;
  Pose X_W_head = Pose::Identity();
};

/// The state a display frame describes, or an error ("display frame: p_W_hip_m[1] is not
/// finite", "display frame: q_W_head_wxyz has zero norm") for a frame that cannot be drawn.
[[nodiscard]] Result<RigState, std::string> rig_state_from_frame(const DisplayFrame& frame);

/// The inverse, for tests and for publishing a state over a frame-based channel.
[[nodiscard]] DisplayFrame display_frame_from_rig_state(const RigState& state);

/// A head at p_W_head_m looking at p_W_target_m with world +y as up (x forward, y up,
/// z right). A target straight above or below falls back to looking along -z.
[[nodiscard]] Pose head_looking_at(const Eigen::Vector3d& p_W_head_m, const Eigen::Vector3d& p_W_target_m);

}  // namespace mhd::viewer
