#pragma once
// Readings no hardware can give: a tool position outside the device's reported workspace
// by more than a margin, a tracked sensor farther from the tracker than its tracking range. The server
// treats them as faults (zero torque, base stop, the plugin named). Allocation-free checks;
// the messages are built only once a reading has failed them.

#include "plugin_host/device_info_check.h"

#include "plugin_host/hardware_io.h"

#include <Eigen/Core>

#include <string>

namespace mhd {

/// How far outside the workspace a device reports (DeviceInfo) a real tool may be
/// (end stops, cable stretch, a conservative box) before a reading is absurd.
inline constexpr double kWorkspaceMargin_m = 0.1;

/// False when p_D_tool_m is not finite or lies farther than the margin outside the union
/// of the device's workspace boxes.
[[nodiscard]] bool tool_position_plausible(const DeviceInfo& info, const Eigen::Vector3d& p_D_tool_m) noexcept;

/// "device_read returned the tool at (a, b, c) m, outside the device's workspace by more than 0.1 m"
[[nodiscard]] std::string tool_position_fault(const Eigen::Vector3d& p_D_tool_m);

/// False when the sensor position p_T_m (in the tracker frame T) lies farther from T's
/// origin than `tracking_range_m`.
[[nodiscard]] bool tracked_position_plausible(const Eigen::Vector3d& p_T_m, double tracking_range_m) noexcept;

/// "tracker_read returned sensor 0 at 1e+09 m from the tracker, beyond its tracking range of 50 m"
[[nodiscard]] std::string tracked_position_fault(unsigned sensor_id, const Eigen::Vector3d& p_T_m,
                                                 double tracking_range_m);

/// False when the base's odometry puts it farther from the world origin than
/// `tracking_range_m`: the base moves where it is tracked, so farther is no real reading.
[[nodiscard]] bool base_position_plausible(const BaseState& state, double tracking_range_m) noexcept;

/// "base_read returned the base at (1e+308, 0) m, farther than the tracking range of 50 m"
[[nodiscard]] std::string base_position_fault(const BaseState& state, double tracking_range_m);

/// "base_read returned the lift at 2.5 m, outside the rig's lift range [-0.5, 0.7] m"
[[nodiscard]] std::string lift_position_fault(double lift_m, double min_m, double max_m);

}  // namespace mhd
