#include "haptic_server/user_motion_estimate.h"

#include <cmath>

namespace mhd {

double planar_heading_rad(const Eigen::Quaterniond& q_W) noexcept {
  const Eigen::Vector3d forward = q_W * Eigen::Vector3d::UnitX();  // line of sight
  return std::atan2(-forward.z(), forward.x());
}

void UserMotionEstimate::update(const HeadState& head) noexcept {
  heading_rad_ = planar_heading_rad(head.q_W);
  if (head.known && previous_.known && head.t_s > previous_.t_s) {
    const double dt_s = head.t_s - previous_.t_s;
    const Eigen::Vector2d v_W_mps((head.p_W_m.x() - previous_.p_W_m.x()) / dt_s,
                                  (head.p_W_m.z() - previous_.p_W_m.z()) / dt_s);
    const double alpha = dt_s / (kTimeConstant_s + dt_s);
    velocity_W_mps_ += alpha * (v_W_mps - velocity_W_mps_);
  }
  if (head.known) previous_ = head;
}

}  // namespace mhd
