#include "haptic_server/force_limit.h"

#include <fmt/core.h>

namespace mhd {

ForceLimit force_limit_for(const std::optional<double>& scene_max_force_N, double device_max_force_N,
                           std::string_view device_name) {
  if (!scene_max_force_N) return {device_max_force_N, std::nullopt};
  if (*scene_max_force_N <= device_max_force_N) return {*scene_max_force_N, std::nullopt};
  return {device_max_force_N,
          fmt::format("<haptics max_force_N> is {:g} N, more than device '{}' allows ({:g} N, its device_info): "
                      "forces are limited to {:g} N",
                      *scene_max_force_N, device_name, device_max_force_N, device_max_force_N)};
}

}  // namespace mhd
