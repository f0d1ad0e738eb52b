#include "haptic_server/physical_range.h"

#include <fmt/core.h>

namespace mhd {

bool joint_angles_plausible(const PhantomJointLimits& limits, const Eigen::Vector3d& q_rad) noexcept {
  if (!q_rad.allFinite()) return false;
  const double m = kJointLimitMargin_rad;
  const double difference = q_rad.z() - q_rad.y();
  return (q_rad.array() >= limits.lower_rad.array() - m).all() &&
         (q_rad.array() <= limits.upper_rad.array() + m).all() &&
         difference >= limits.min_link_difference_rad - m && difference <= limits.max_link_difference_rad + m;
}

std::string joint_angles_fault(const Eigen::Vector3d& q_rad) {
  return fmt::format("device_read returned joint angles ({:g}, {:g}, {:g}) rad, outside the joint limits by more "
                     "than {:g} rad",
                     q_rad.x(), q_rad.y(), q_rad.z(), kJointLimitMargin_rad);
}

bool tracked_position_plausible(const Eigen::Vector3d& p_T_m, double tracking_range_m) noexcept {
  return p_T_m.allFinite() && p_T_m.norm() <= tracking_range_m;
}

std::string tracked_position_fault(unsigned sensor_id, const Eigen::Vector3d& p_T_m, double tracking_range_m) {
  return fmt::format("tracker_read returned sensor {} at {:g} m from the tracker, beyond its tracking range of {:g} m",
                     sensor_id, p_T_m.norm(), tracking_range_m);
}

}  // namespace mhd
