#pragma once
// One row of a haptic server recording: what one haptic tick saw and did, plus the user's
// pose as the tracker last reported it. SI units, world frame.

#include <array>
#include <cstdint>
#include <limits>

namespace mhd {

struct RecordingRow {
  double t_s = 0.0;   ///< host clock
  double dt_s = 0.0;  ///< time since the previous tick, as the tick used it
  std::array<double, 3> p_D_tool_m{};  ///< the tool as the device reported it, device frame
  std::array<double, 3> p_W_hip{};
  std::array<double, 3> proxy_W_m{};
  std::array<double, 3> force_W_N{};      ///< rendered: what the device was told
  std::array<double, 3> cmd_force_W_N{};  ///< the proxy's force before the safety stage
  std::array<double, 3> force_D_N{};  ///< force_W_N in the device frame: what was sent
  double base_x_m = 0.0, base_z_m = 0.0, base_heading_rad = 0.0;
  double lift_m = 0.0;  ///< the arm's lift height the tick used (0 without a lift)
  double user_x_m = 0.0, user_z_m = 0.0, user_heading_rad = 0.0;
  double tracker_age_s = 0.0;
  double safety_gain = 0.0;
  std::int32_t contact_object = -1;
  std::uint8_t contact = 0;
  /// The scene's first shared object's origin as this rig renders it (docs/shared-objects.md);
  /// NaN when the scene shares none.
  std::array<double, 3> p_W_shared_m{kNoShared, kNoShared, kNoShared};

  static constexpr double kNoShared = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace mhd
