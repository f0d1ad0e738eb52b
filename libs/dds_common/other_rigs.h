#pragma once
// The other rigs whose tracker samples a rig's `dds` tracker also reads (param
// `other_rigs`): the shared tracking sees every user and base, so each rig's planner can
// keep its base out of the others' way (docs/planner.md, "Several rigs on one floor").
// Sensor S of rig R reaches the haptic server as sensor other_rig_sensor_id(R, S), which
// `<server other_rig_sensors>` names. Header-only.

#include <mhd/plugin_sdk_params.hpp>

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace mhd::dds {

/// Most other rigs one tracker reads (the server's kMaxOtherRigs).
inline constexpr std::size_t kMaxOtherRigs = 8;
/// Highest rig id `other_rigs` takes: 1000 R + S stays a 32-bit sensor id.
inline constexpr std::uint32_t kMaxOtherRigId = 999999;

[[nodiscard]] constexpr std::uint32_t other_rig_sensor_id(std::uint32_t rig_id, std::uint32_t sensor_id) noexcept {
  return 1000u * rig_id + sensor_id;
}

/// "2 3": rig ids, each in [0, kMaxOtherRigId], none the rig's own or repeated, at most
/// kMaxOtherRigs. Throws sdk::ParamError naming the parameter.
inline std::vector<std::uint32_t> parse_other_rigs(const std::string& text, std::uint32_t own_rig) {
  std::vector<std::uint32_t> rigs;
  std::istringstream words(text);
  const auto refuse = [&](const std::string& why) {
    return sdk::ParamError("parameter 'other_rigs' " + why + ", got '" + text + "'");
  };
  for (std::string word; words >> word;) {
    if (word.size() > 6 || word.find_first_not_of("0123456789") != std::string::npos) {
      throw refuse("must be rig ids in [0, " + std::to_string(kMaxOtherRigId) + "]");
    }
    const auto rig = static_cast<std::uint32_t>(std::stoul(word));
    if (rig == own_rig) throw refuse("names the rig's own id " + std::to_string(own_rig));
    if (std::find(rigs.begin(), rigs.end(), rig) != rigs.end()) throw refuse("names rig " + word + " twice");
    if (rigs.size() == kMaxOtherRigs) throw refuse("names more than " + std::to_string(kMaxOtherRigs) + " rigs");
    rigs.push_back(rig);
  }
  return rigs;
}

}  // namespace mhd::dds
