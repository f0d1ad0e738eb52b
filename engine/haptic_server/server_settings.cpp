#include "haptic_server/server_settings.h"

#include "scene/param_block_reader.h"

#include <fmt/core.h>

#include <algorithm>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>
#include <sstream>
#include <string_view>
#include <vector>

namespace mhd {
namespace {

BasePoseSource base_pose_source_from(ParamBlockReader& r) {
  const std::string source = r.text("base_pose_source", "tracker");
  if (source == "odometry") return BasePoseSource::Odometry;
  if (source != "tracker") {
    r.error("base_pose_source",
            fmt::format("param 'base_pose_source' in <server> must be tracker or odometry, got '{}'", source));
  }
  return BasePoseSource::Tracker;
}

/// <server> other_rig_sensors: "HEAD:BASE ..." pairs of sensor ids, none of them the
/// rig's own nor repeated, at most kMaxOtherRigs.
OtherRigSensorList other_rigs_from(ParamBlockReader& r, std::uint32_t own_base, std::uint32_t own_head) {
  constexpr std::string_view kName = "other_rig_sensors";
  OtherRigSensorList list;
  const std::string text = r.text(std::string(kName), "");
  const auto refuse = [&](const std::string& why) {
    r.error(kName, fmt::format("param 'other_rig_sensors' in <server> {}, got '{}'", why, text));
    return OtherRigSensorList{};
  };
  std::istringstream words(text);
  std::vector<std::uint32_t> seen{own_base, own_head};
  for (std::string pair; words >> pair;) {
    const auto colon = pair.find(':');
    std::uint64_t ids[2] = {0, 0};
    bool ok = colon != std::string::npos && colon > 0 && colon + 1 < pair.size();
    for (int i = 0; ok && i < 2; ++i) {
      const std::string part = i == 0 ? pair.substr(0, colon) : pair.substr(colon + 1);
      ok = part.size() <= 10 && part.find_first_not_of("0123456789") == std::string::npos;
      if (ok) ids[i] = std::stoull(part);
      ok = ok && ids[i] <= kMaxSensorId;
    }
    if (!ok) return refuse(fmt::format("must be HEAD:BASE pairs of sensor ids in [0, {}]", kMaxSensorId));
    if (list.count == kMaxOtherRigs) return refuse(fmt::format("names more than {} rigs", kMaxOtherRigs));
    for (const std::uint64_t id : ids) {
      if (std::find(seen.begin(), seen.end(), id) != seen.end())
        return refuse(fmt::format("names sensor {} twice, or one of the rig's own (base_sensor_id, head_sensor_id)", id));
      seen.push_back(static_cast<std::uint32_t>(id));
    }
    list.rigs[list.count++] = OtherRigSensors{static_cast<std::uint32_t>(ids[0]), static_cast<std::uint32_t>(ids[1])};
  }
  return list;
}

/// The rules between settings, each reported at the setting that breaks it.
void check_together(const ServerSettings& s, ParamBlockReader& r) {
  if (s.min_tick_interval_s > 1.0 / s.haptic_rate_hz) {
    r.error("min_tick_interval_s", "param 'min_tick_interval_s' in <server> must not exceed the haptic period (1 / rate)");
  }
  if (s.tick.safety.tracker_fade_s > s.tick.safety.tracker_timeout_s) {
    r.error("tracker_fade_s", "param 'tracker_fade_s' in <server> must not exceed tracker_timeout_s");
  }
  if (s.base_sensor_id == s.head_sensor_id) {
    r.error("head_sensor_id", "params 'base_sensor_id' and 'head_sensor_id' in <server> must differ");
  }
}

}  // namespace

Result<ServerSettings> server_settings_from(const SceneDescription& scene) {
  constexpr double kDegToRad = std::numbers::pi / 180.0;
  ServerSettings s;
  s.base_guard.keep_out_m = 0.475;  // robot radius 0.225 + human radius 0.25 (docs/planner.md)
  s.haptic_rate_hz = scene.haptics.update_rate_Hz;
  // Until open() asks the device: then the device's limit, lowered by the scene's.
  s.tick.safety.max_force_N = scene.haptics.max_force_N.value_or(kNoDeviceMaxForce_N);

  ParamBlockReader r(scene.server ? &*scene.server : nullptr, "<server>");
  // Each number within its declared range (kServerNumbers).
  const auto number = [&r](std::string_view name, double fallback) {
    for (const ServerNumber& n : kServerNumbers) {
      if (n.name == name) return r.within(name, fallback, n.low, n.high, n.unit);
    }
    throw std::logic_error("server setting '" + std::string(name) + "' is read but not declared");
  };
  const auto sensor_id = [&r](std::string_view name, std::uint32_t fallback) {
    const std::uint64_t id = r.unsigned_integer(name, fallback);
    if (id <= kMaxSensorId) return static_cast<std::uint32_t>(id);
    r.error(name, fmt::format("param '{}' in <server> must be an integer in [0, {}], got {}", name, kMaxSensorId, id));
    return fallback;
  };
  s.tick.safety.tracker_timeout_s = number("tracker_timeout_s", s.tick.safety.tracker_timeout_s);
  s.tick.safety.tracker_fade_s = number("tracker_fade_s", s.tick.safety.tracker_fade_s);
  s.tick.safety.hip_jump_m = number("hip_jump_m", s.tick.safety.hip_jump_m);
  s.tick.safety.fade_in_s = number("fade_in_s", s.tick.safety.fade_in_s);
  s.tick.predict_base_pose = r.boolean("predict_base_pose", s.tick.predict_base_pose);
  s.base_sensor_id = sensor_id("base_sensor_id", s.base_sensor_id);
  s.head_sensor_id = sensor_id("head_sensor_id", s.head_sensor_id);
  s.base_pose_source = base_pose_source_from(r);
  s.io_rate_hz = number("io_rate_hz", s.io_rate_hz);
  s.base_rate_hz = number("base_rate_hz", s.base_rate_hz);
  s.display_rate_hz = number("display_rate_hz", s.display_rate_hz);
  s.base_guard.max_speed_mps = number("base_max_speed_mps", s.base_guard.max_speed_mps);
  s.base_guard.max_omega_radps = number("base_max_omega_degps", s.base_guard.max_omega_radps / kDegToRad) * kDegToRad;
  s.base_guard.keep_out_m = number("keep_out_m", s.base_guard.keep_out_m);
  s.record_flush_s = number("record_flush_s", s.record_flush_s);
  s.tick_on_tracker_sample = r.boolean("tick_on_tracker_sample", s.tick_on_tracker_sample);
  s.min_tick_interval_s = number("min_tick_interval_s", s.min_tick_interval_s);
  s.plugin_call_timeout_s = number("plugin_call_timeout_s", s.plugin_call_timeout_s);
  s.tracking_range_m = number("tracking_range_m", s.tracking_range_m);
  s.other_rigs_timeout_s = number("other_rigs_timeout_s", s.other_rigs_timeout_s);
  s.other_rigs = other_rigs_from(r, s.base_sensor_id, s.head_sensor_id);
  check_together(s, r);
  s.base_guard.tracker_timeout_s = s.tick.safety.tracker_timeout_s;

  Diagnostics errors = r.finish();
  if (!errors.empty()) return errors;
  return s;
}

}  // namespace mhd
