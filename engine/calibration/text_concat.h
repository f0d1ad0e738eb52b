#pragma once
// Message building shared by the calibration files (one definition, since a target's
// files are compiled together in batches).

#include <numbers>
#include <string>
#include <string_view>

namespace mhd::calibration_detail {

inline constexpr double kDegPerRad = 180.0 / std::numbers::pi;

/// The parts (anything a string_view is made from) joined.
template <typename... Parts>
std::string concat(const Parts&... parts) {
  std::string out;
  (out.append(std::string_view(parts)), ...);
  return out;
}

}  // namespace mhd::calibration_detail
