#include "simulation_config/simulated_user_config.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace mhd::simulation {

namespace {

std::string_view trim(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

std::optional<double> parse_number(std::string_view s) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc{} || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

/// Shortest round-trip form: "1.5", not "1.500000".
std::string format(double v) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), v);
  return std::string(buffer.data(), result.ptr);
}

bool positive(double v) { return v > 0.0 && std::isfinite(v); }
bool non_negative(double v) { return v >= 0.0 && std::isfinite(v); }

}  // namespace

double hand_height_at(const std::optional<HandHeightSweep>& sweep, double fixed_m, double time_s) noexcept {
  if (!sweep) return fixed_m;
  const HandHeightSweep& w = *sweep;
  const double leg_s = (w.high_m - w.low_m) / w.speed_mps;
  const double period_s = 2.0 * (leg_s + w.hold_s);
  const double phase_s = std::fmod(std::max(0.0, time_s), period_s);
  if (phase_s < w.hold_s) return w.low_m;
  if (phase_s < w.hold_s + leg_s) return w.low_m + w.speed_mps * (phase_s - w.hold_s);
  if (phase_s < 2.0 * w.hold_s + leg_s) return w.high_m;
  return w.high_m - w.speed_mps * (phase_s - 2.0 * w.hold_s - leg_s);
}

double eye_height_at(double standing_m, double hand_height_m) noexcept {
  constexpr double kEyesAboveLowHand_m = 0.7;
  constexpr double kCrouchedEyes_m = 1.0;
  return std::clamp(hand_height_m + kEyesAboveLowHand_m, std::min(kCrouchedEyes_m, standing_m), standing_m);
}

void validate(const SimulatedUserConfig& c) {
  require(positive(c.max_speed_mps), "max_speed_mps must be positive");
  require(positive(c.max_turn_rate_radps), "max_turn_rate_radps must be positive");
  require(positive(c.step_s), "step_s must be positive");
  require(std::isfinite(c.start_time_s), "start_time_s must be finite");
  require(non_negative(c.walk_speed_min_mps) && c.walk_speed_min_mps <= c.walk_speed_max_mps &&
              c.walk_speed_max_mps <= c.max_speed_mps,
          "walking speeds must satisfy 0 <= walk_speed_min_mps <= walk_speed_max_mps <= max_speed_mps");
  require(non_negative(c.walk_turn_rate_max_radps) && c.walk_turn_rate_max_radps <= c.max_turn_rate_radps,
          "walk_turn_rate_max_radps must be in [0, max_turn_rate_radps]");
  require(positive(c.side_step_speed_max_mps) && c.side_step_speed_max_mps <= c.max_speed_mps,
          "side_step_speed_max_mps must be in (0, max_speed_mps]");
  require(non_negative(c.side_step_probability) && non_negative(c.stand_probability) &&
              c.side_step_probability + c.stand_probability <= 1.0,
          "side_step_probability and stand_probability must be >= 0 with a sum <= 1");
  require(positive(c.area_half_size_m), "area_half_size_m must be positive");
  require(std::isfinite(c.start.x_m) && std::isfinite(c.start.z_m) && std::isfinite(c.start.heading_rad),
          "start must be finite");
  require(positive(c.eye_height_m), "eye_height_m must be positive");
  require(non_negative(c.hand_reach_m) && positive(c.hand_height_m) && non_negative(c.hand_motion_amplitude_m),
          "hand_reach_m, hand_height_m and hand_motion_amplitude_m must be >= 0 (height > 0)");
  require(!c.gaze_target_W || c.gaze_target_W->allFinite(), "gaze_target_W must be finite");
  if (const auto& sweep = c.hand_height_sweep) {
    require(positive(sweep->low_m) && positive(sweep->high_m) && sweep->low_m < sweep->high_m,
            "hand_height_sweep_m must be two heights 0 < low < high");
    require(positive(sweep->speed_mps), "hand_height_sweep_speed_mps must be positive");
    require(non_negative(sweep->hold_s), "hand_height_sweep_hold_s must be >= 0");
  }
  if (c.loop_path) {
    const bool moves = std::any_of(c.path.begin(), c.path.end(), [&](const Waypoint& w) {
      return w.x_m != c.path.front().x_m || w.z_m != c.path.front().z_m;
    });
    require(moves, "a looping path needs two different waypoints");
  }
  for (std::size_t i = 0; i < c.path.size(); ++i) {
    const Waypoint& w = c.path[i];
    const std::string name = "waypoint " + std::to_string(i + 1);
    require(std::isfinite(w.x_m) && std::isfinite(w.z_m) && std::isfinite(w.speed_mps), name + ": not finite");
    const bool walked_to = i > 0 || (c.loop_path && c.path.size() > 1);
    if (!walked_to) continue;
    require(w.speed_mps > 0.0, name + ": speed must be positive, got " + format(w.speed_mps));
    require(w.speed_mps <= c.max_speed_mps,
            name + ": speed " + format(w.speed_mps) + " m/s is above max_speed_mps " + format(c.max_speed_mps));
  }
}

std::vector<Waypoint> parse_waypoints(std::string_view text) {
  std::vector<Waypoint> path;
  int index = 0;
  for (;;) {
    const std::size_t semicolon = text.find(';');
    const std::string_view item = trim(text.substr(0, semicolon));
    ++index;
    if (!item.empty() || semicolon != std::string_view::npos) {
      // Three numbers separated by blanks.
      std::array<double, 3> v{};
      std::string_view rest = item;
      bool ok = true;
      for (double& x : v) {
        rest = trim(rest);
        const std::size_t end = std::min(rest.find_first_of(" \t"), rest.size());
        const auto number = parse_number(rest.substr(0, end));
        ok = ok && number.has_value();
        x = number.value_or(0.0);
        rest = rest.substr(end);
      }
      if (!ok || !trim(rest).empty()) {
        throw std::invalid_argument("waypoint " + std::to_string(index) + ": expected 'x z speed_mps', got '" +
                                    std::string(item) + "'");
      }
      path.push_back({v[0], v[1], v[2]});
    }
    if (semicolon == std::string_view::npos) break;
    text.remove_prefix(semicolon + 1);
    if (trim(text).empty()) break;  // a trailing ';'
  }
  if (path.empty()) throw std::invalid_argument("no waypoints");
  return path;
}

}  // namespace mhd::simulation
