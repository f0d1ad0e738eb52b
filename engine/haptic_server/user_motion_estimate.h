#pragma once
// The user's walking motion from the head track, for the base planner: the head's floor
// velocity low-passed (head bobbing and tracker noise are not walking) and its heading.

#include "haptic_server/head_state.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace mhd {

/// The head's line of sight (its +x) projected on the floor, as a heading about world +y
/// (0 along world +x, positive turning from +x towards -z).
[[nodiscard]] double planar_heading_rad(const Eigen::Quaterniond& q_W) noexcept;

class UserMotionEstimate {
 public:
  /// The low-pass filter's time constant.
  static constexpr double kTimeConstant_s = 0.2;

  /// Takes the newest head state (the same one again is fine): a head measured later than
  /// the previous known one moves the velocity towards their finite difference in x-z by
  /// dt / (kTimeConstant_s + dt). An unknown head leaves the velocity as it was.
  void update(const HeadState& head) noexcept;

  /// The smoothed floor velocity (world x, z); zero until two heads have been measured.
  [[nodiscard]] Eigen::Vector2d velocity_W_mps() const noexcept { return velocity_W_mps_; }
  /// planar_heading_rad of the head last given to update (0 before any).
  [[nodiscard]] double heading_rad() const noexcept { return heading_rad_; }

 private:
  HeadState previous_;
  Eigen::Vector2d velocity_W_mps_ = Eigen::Vector2d::Zero();
  double heading_rad_ = 0.0;
};

}  // namespace mhd
