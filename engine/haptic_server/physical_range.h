#pragma once
// Readings no hardware can give: joint angles past the device's joint limits by more than
// a margin, a tracked sensor farther from the tracker than its tracking range. The server
// treats them as faults (zero torque, base stop, the plugin named). Allocation-free checks;
// the messages are built only once a reading has failed them.

#include "kinematics/phantom_kinematics.h"

#include <Eigen/Core>

#include <string>

namespace mhd {

/// How far past MHD's modelled joint limits a real arm may be pushed (end stops, cable
/// stretch, the modelled limits being MHD's and not SensAble's) before a reading is absurd.
inline constexpr double kJointLimitMargin_rad = 0.35;  // 20 degrees

/// False when any angle (or theta3 - theta2) lies outside `limits` widened by the margin.
[[nodiscard]] bool joint_angles_plausible(const PhantomJointLimits& limits, const Eigen::Vector3d& q_rad) noexcept;

/// "device_read returned joint angles (a, b, c) rad, outside the joint limits by more than 0.35 rad"
[[nodiscard]] std::string joint_angles_fault(const Eigen::Vector3d& q_rad);

/// False when the sensor position p_T_m (in the tracker frame T) lies farther from T's
/// origin than `tracking_range_m`.
[[nodiscard]] bool tracked_position_plausible(const Eigen::Vector3d& p_T_m, double tracking_range_m) noexcept;

/// "tracker_read returned sensor 0 at 1e+09 m from the tracker, beyond its tracking range of 50 m"
[[nodiscard]] std::string tracked_position_fault(unsigned sensor_id, const Eigen::Vector3d& p_T_m,
                                                 double tracking_range_m);

}  // namespace mhd
