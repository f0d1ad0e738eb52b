#include "haptic_server/physical_range.h"

#include <fmt/core.h>

namespace mhd {

bool tool_position_plausible(const DeviceInfo& info, const Eigen::Vector3d& p_D_tool_m) noexcept {
  return p_D_tool_m.allFinite() && distance_outside_workspace_m(info, p_D_tool_m.data()) <= kWorkspaceMargin_m;
}

std::string tool_position_fault(const Eigen::Vector3d& p_D_tool_m) {
  return fmt::format("device_read returned the tool at ({:g}, {:g}, {:g}) m, outside the device's workspace by more "
                     "than {:g} m",
                     p_D_tool_m.x(), p_D_tool_m.y(), p_D_tool_m.z(), kWorkspaceMargin_m);
}

bool tracked_position_plausible(const Eigen::Vector3d& p_T_m, double tracking_range_m) noexcept {
  return p_T_m.allFinite() && p_T_m.norm() <= tracking_range_m;
}

std::string tracked_position_fault(unsigned sensor_id, const Eigen::Vector3d& p_T_m, double tracking_range_m) {
  return fmt::format("tracker_read returned sensor {} at {:g} m from the tracker, beyond its tracking range of {:g} m",
                     sensor_id, p_T_m.norm(), tracking_range_m);
}

bool base_position_plausible(const BaseState& state, double tracking_range_m) noexcept {
  const Eigen::Vector2d p_m(state.x_m, state.z_m);
  return p_m.allFinite() && p_m.norm() <= tracking_range_m;
}

std::string base_position_fault(const BaseState& state, double tracking_range_m) {
  return fmt::format("base_read returned the base at ({:g}, {:g}) m, farther than the tracking range of {:g} m",
                     state.x_m, state.z_m, tracking_range_m);
}

std::string lift_position_fault(double lift_m, double min_m, double max_m) {
  return fmt::format("base_read returned the lift at {:g} m, outside the rig's lift range [{:g}, {:g}] m", lift_m, min_m,
                     max_m);
}

}  // namespace mhd
