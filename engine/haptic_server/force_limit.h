#pragma once
// The force limit of a run, from one source: the device. Its ABI-3 device_info reports
// max_force_N; the scene's <haptics max_force_N> may only lower it (docs/haptic_server.md,
// "Force limit"). The safety stage clamps every force to the result, and the plugin host
// scales a command down to the device's limit once more before device_write.

#include <optional>
#include <string>
#include <string_view>

namespace mhd {

struct ForceLimit {
  double max_force_N = 0.0;            ///< what every force sent to the device keeps to
  std::optional<std::string> warning;  ///< set when the scene asked for more than the device allows
};

/// device_max_force_N (the device's reported limit, > 0), lowered to scene_max_force_N
/// when the scene gives a smaller one; a scene that gives none gets the device's. A scene
/// asking for more than the device allows gets the device's limit and a warning naming
/// both values and `device_name`; a run is not refused for it, since the device's limit
/// holds either way.
[[nodiscard]] ForceLimit force_limit_for(const std::optional<double>& scene_max_force_N, double device_max_force_N,
                                         std::string_view device_name);

}  // namespace mhd
