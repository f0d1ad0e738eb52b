#pragma once
// What the host checks of a Cartesian device: the DeviceInfo it reports at open, the
// states it reads, and the clamp of every command it sends. Allocation-free on success; a
// message is built only once a check has failed.

#include "plugin_host/hardware_io.h"

#include <optional>
#include <string>

namespace mhd {

/// Why `info` is unusable ("max_force_N = 0, which must be > 0"), or nothing when it is
/// usable: finite, positive force and stiffness limits, DOF 3 or 6, a torque limit > 0
/// exactly when dof_out is 6, 1..kMaxWorkspaceBoxes boxes each with min < max.
[[nodiscard]] std::optional<std::string> device_info_problem(const DeviceInfo& info);

/// Why `state` is not a reading (a non-finite field named "p_D_tool_m[1]", an orientation
/// that is not a unit quaternion), or nothing.
[[nodiscard]] std::optional<std::string> device_state_problem(const DeviceState& state);

/// `command` with its force scaled down to max_force_N and its torque to max_torque_Nm
/// (directions kept), and the torque zeroed for a device with 3 output DOF.
[[nodiscard]] DeviceCommand clamp_to_device(const DeviceInfo& info, const DeviceCommand& command) noexcept;

/// The distance from p_D_m (3 values) to the union of the device's workspace boxes (0 inside).
[[nodiscard]] double distance_outside_workspace_m(const DeviceInfo& info, const double* p_D_m) noexcept;

}  // namespace mhd
