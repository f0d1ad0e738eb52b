#include "haptic_server/server_settings.h"

#include "scene/param_block_reader.h"

#include <fmt/core.h>

#include <cstdint>
#include <numbers>
#include <string_view>

namespace mhd {

Result<ServerSettings> server_settings_from(const SceneDescription& scene) {
  constexpr double kDegToRad = std::numbers::pi / 180.0;
  ServerSettings s;
  s.base_guard.keep_out_m = 0.475;  // robot radius 0.225 + human radius 0.25 (docs/planner.md)
  s.haptic_rate_hz = scene.haptics.update_rate_Hz;
  // Until open() asks the device: then the device's limit, lowered by the scene's.
  s.tick.safety.max_force_N = scene.haptics.max_force_N.value_or(kNoDeviceMaxForce_N);

  ParamBlockReader r(scene.server ? &*scene.server : nullptr, "<server>");
  s.tick.safety.tracker_timeout_s = r.positive("tracker_timeout_s", s.tick.safety.tracker_timeout_s);
  s.tick.safety.tracker_fade_s = r.non_negative("tracker_fade_s", s.tick.safety.tracker_fade_s);
  s.tick.safety.hip_jump_m = r.positive("hip_jump_m", s.tick.safety.hip_jump_m);
  s.tick.safety.fade_in_s = r.non_negative("fade_in_s", s.tick.safety.fade_in_s);
  s.tick.predict_base_pose = r.boolean("predict_base_pose", s.tick.predict_base_pose);
  s.base_sensor_id = static_cast<std::uint32_t>(r.unsigned_integer("base_sensor_id", s.base_sensor_id));
  s.head_sensor_id = static_cast<std::uint32_t>(r.unsigned_integer("head_sensor_id", s.head_sensor_id));
  s.io_rate_hz = r.positive("io_rate_hz", s.io_rate_hz);
  s.base_rate_hz = r.positive("base_rate_hz", s.base_rate_hz);
  s.display_rate_hz = r.positive("display_rate_hz", s.display_rate_hz);
  s.base_guard.max_speed_mps = r.positive("base_max_speed_mps", s.base_guard.max_speed_mps);
  s.base_guard.max_omega_radps =
      r.positive("base_max_omega_degps", s.base_guard.max_omega_radps / kDegToRad) * kDegToRad;
  s.base_guard.keep_out_m = r.non_negative("keep_out_m", s.base_guard.keep_out_m);
  s.record_flush_s = r.positive("record_flush_s", s.record_flush_s);
  s.tick_on_tracker_sample = r.boolean("tick_on_tracker_sample", s.tick_on_tracker_sample);
  s.min_tick_interval_s = r.non_negative("min_tick_interval_s", s.min_tick_interval_s);
  s.plugin_call_timeout_s = r.positive("plugin_call_timeout_s", s.plugin_call_timeout_s);
  s.tracking_range_m = r.positive("tracking_range_m", s.tracking_range_m);
  // Rates a host loop can keep (a tiny rate is a near-infinite period, a huge one a busy spin).
  const auto within = [&r](std::string_view name, double value, double low, double high) {
    if (value >= low && value <= high) return;
    r.error(name, fmt::format("param '{}' in <server> must be within [{:g}, {:g}], got {:g}", name, low, high, value));
  };
  within("io_rate_hz", s.io_rate_hz, 10.0, 20'000.0);
  within("base_rate_hz", s.base_rate_hz, 1.0, 1000.0);
  within("display_rate_hz", s.display_rate_hz, 1.0, 1000.0);
  within("tracking_range_m", s.tracking_range_m, 1.0, 1000.0);
  if (s.min_tick_interval_s > 1.0 / s.haptic_rate_hz) {
    r.error("min_tick_interval_s", "param 'min_tick_interval_s' in <server> must not exceed the haptic period (1 / rate)");
  }
  if (s.tick.safety.tracker_fade_s > s.tick.safety.tracker_timeout_s) {
    r.error("tracker_fade_s", "param 'tracker_fade_s' in <server> must not exceed tracker_timeout_s");
  }
  if (s.base_sensor_id == s.head_sensor_id) {
    r.error("head_sensor_id", "params 'base_sensor_id' and 'head_sensor_id' in <server> must differ");
  }
  s.base_guard.tracker_timeout_s = s.tick.safety.tracker_timeout_s;

  Diagnostics errors = r.finish();
  if (!errors.empty()) return errors;
  return s;
}

}  // namespace mhd
