#include "planner/planner_settings.h"

#include "kinematics/rig.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <system_error>

namespace mhd {

namespace {

enum class Unit { Length, Angle, AngularSpeed, Speed, Time };

struct Field {
  std::string_view name;  ///< without unit suffix
  Unit unit;
  double& (*ref)(PlannerSettings&);
};

constexpr double kDeg = std::numbers::pi / 180.0;

// The accepted suffixes of a unit and their scale to SI.
struct Suffix {
  std::string_view text;
  double scale;
};

std::array<Suffix, 2> suffixes(Unit unit) noexcept {
  switch (unit) {
    case Unit::Length: return {Suffix{"_m", 1.0}, Suffix{"_mm", 1e-3}};
    case Unit::Angle: return {Suffix{"_rad", 1.0}, Suffix{"_deg", kDeg}};
    case Unit::AngularSpeed: return {Suffix{"_radps", 1.0}, Suffix{"_degps", kDeg}};
    case Unit::Speed: return {Suffix{"_mps", 1.0}, Suffix{"_mmps", 1e-3}};
    case Unit::Time: return {Suffix{"_s", 1.0}, Suffix{"_ms", 1e-3}};
  }
  return {Suffix{"", 1.0}, Suffix{"", 1.0}};
}

#define MHD_FIELD(name, unit, member) \
  Field { name, unit, [](PlannerSettings& s) -> double& { return s.member; } }

const std::array<Field, 19>& fields() {
  static const std::array<Field, 19> kFields{
      MHD_FIELD("arm_length", Unit::Length, arm_length_m),
      MHD_FIELD("robot_radius", Unit::Length, robot_radius_m),
      MHD_FIELD("human_radius", Unit::Length, human_radius_m),
      MHD_FIELD("step_angle", Unit::Angle, step_angle_rad),
      MHD_FIELD("max_linear_speed", Unit::Speed, max_linear_speed_mps),
      MHD_FIELD("max_angular_speed", Unit::AngularSpeed, max_angular_speed_radps),
      MHD_FIELD("deceleration_interval", Unit::Length, deceleration_interval_m),
      MHD_FIELD("angular_deceleration_interval", Unit::Angle, angular_deceleration_interval_rad),
      MHD_FIELD("stop_interval", Unit::Length, stop_interval_m),
      MHD_FIELD("stop_angle", Unit::Angle, stop_angle_rad),
      MHD_FIELD("facing_angle", Unit::Angle, facing_angle_rad),
      MHD_FIELD("usable_x_min", Unit::Length, usable_B.x_min_m),
      MHD_FIELD("usable_x_max", Unit::Length, usable_B.x_max_m),
      MHD_FIELD("usable_z_min", Unit::Length, usable_B.z_min_m),
      MHD_FIELD("usable_z_max", Unit::Length, usable_B.z_max_m),
      MHD_FIELD("safety_margin", Unit::Length, safety_margin_m),
      MHD_FIELD("prediction_horizon", Unit::Time, prediction_horizon_s),
      MHD_FIELD("catch_margin", Unit::Length, catch_margin_m),
      MHD_FIELD("command_period", Unit::Time, command_period_s),
  };
  return kFields;
}

#undef MHD_FIELD

std::string known_names() {
  std::string out;
  for (const Field& f : fields()) {
    const auto s = suffixes(f.unit);
    if (!out.empty()) out += ", ";
    out += std::string(f.name) + std::string(s[0].text) + "|" + std::string(s[1].text.substr(1));
  }
  return out;
}

bool parse_double(std::string_view text, double& value) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  if (text.empty()) return false;
  if (text.front() == '+') text.remove_prefix(1);
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end && std::isfinite(value);
}

std::string fmt_deg(double rad) { return std::to_string(rad / kDeg); }

}  // namespace

std::string_view to_string(PlannerKind kind) noexcept {
  switch (kind) {
    case PlannerKind::Seed: return "seed";
    case PlannerKind::Predictive: return "predictive";
  }
  return "?";
}

bool parse_planner_kind(std::string_view text, PlannerKind& kind) noexcept {
  if (text == "seed") {
    kind = PlannerKind::Seed;
    return true;
  }
  if (text == "predictive") {
    kind = PlannerKind::Predictive;
    return true;
  }
  return false;
}

std::vector<std::string> validate(const PlannerSettings& s) {
  std::vector<std::string> errors;
  const auto positive = [&](std::string_view name, double v) {
    if (!(v > 0.0)) errors.push_back(std::string(name) + " must be > 0, got " + std::to_string(v));
  };
  const auto non_negative = [&](std::string_view name, double v) {
    if (!(v >= 0.0)) errors.push_back(std::string(name) + " must be >= 0, got " + std::to_string(v));
  };
  positive("arm_length_m", s.arm_length_m);
  positive("robot_radius_m", s.robot_radius_m);
  non_negative("human_radius_m", s.human_radius_m);
  if (!(s.step_angle_rad > 0.0 && s.step_angle_rad <= 0.5 * std::numbers::pi))
    errors.push_back("step_angle_deg must be in (0, 90], got " + fmt_deg(s.step_angle_rad));
  positive("max_linear_speed_mps", s.max_linear_speed_mps);
  positive("max_angular_speed_radps", s.max_angular_speed_radps);
  positive("deceleration_interval_m", s.deceleration_interval_m);
  positive("angular_deceleration_interval_rad", s.angular_deceleration_interval_rad);
  non_negative("stop_interval_m", s.stop_interval_m);
  non_negative("stop_angle_rad", s.stop_angle_rad);
  if (!(std::abs(s.facing_angle_rad) <= 2.0 * std::numbers::pi))
    errors.push_back("facing_angle_deg must be within [-360, 360], got " + fmt_deg(s.facing_angle_rad));
  if (!(s.usable_B.x_min_m < s.usable_B.x_max_m))
    errors.push_back("usable_x_min_m must be below usable_x_max_m");
  if (!(s.usable_B.z_min_m < s.usable_B.z_max_m))
    errors.push_back("usable_z_min_m must be below usable_z_max_m");
  non_negative("safety_margin_m", s.safety_margin_m);
  non_negative("prediction_horizon_s", s.prediction_horizon_s);
  if (!(s.catch_margin_m >= 0.0 && 2.0 * s.catch_margin_m < s.usable_B.x_max_m - s.usable_B.x_min_m &&
        2.0 * s.catch_margin_m < s.usable_B.z_max_m - s.usable_B.z_min_m))
    errors.push_back("catch_margin_m must be >= 0 and leave some of the usable workspace, got " +
                     std::to_string(s.catch_margin_m));
  positive("command_period_s", s.command_period_s);
  if (!(s.collision_radius_m() + s.safety_margin_m < s.target_distance_m()))
    errors.push_back("robot_radius_m + human_radius_m + safety_margin_m (" +
                     std::to_string(s.collision_radius_m() + s.safety_margin_m) +
                     ") must be below arm_length_m + robot_radius_m (" + std::to_string(s.target_distance_m()) +
                     "): the target would be inside the user's cylinder");
  return errors;
}

Result<PlannerSettings, std::vector<std::string>> planner_settings_from_map(
    const std::map<std::string, std::string>& values, const PlannerSettings& defaults) {
  PlannerSettings settings = defaults;
  std::vector<std::string> errors;
  for (const auto& [name, text] : values) {
    const Field* field = nullptr;
    double scale = 1.0;
    for (const Field& f : fields()) {
      for (const Suffix& suffix : suffixes(f.unit)) {
        if (name.size() == f.name.size() + suffix.text.size() && name.starts_with(f.name) &&
            name.ends_with(suffix.text)) {
          field = &f;
          scale = suffix.scale;
        }
      }
    }
    if (field == nullptr) {
      errors.push_back("unknown planner setting '" + name + "' (known: " + known_names() + ")");
      continue;
    }
    double value = 0.0;
    if (!parse_double(text, value)) {
      errors.push_back("planner setting '" + name + "': '" + text + "' is not a number");
      continue;
    }
    field->ref(settings) = value * scale;
  }
  if (errors.empty()) errors = validate(settings);
  if (!errors.empty()) return errors;
  return settings;
}

PlanarBox usable_box_in_base(const Rig& rig) noexcept { return usable_box_in_base(rig, rig.device().usable_workspace()); }

PlanarBox usable_box_in_base(const Rig& rig, const WorkspaceBox& box) noexcept {
  const Pose X_B_P = rig.X_robot_base().inverse(Eigen::Isometry) * rig.X_robot_phantom();
  PlanarBox out{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p_P((corner & 1) ? box.max_P_m.x() : box.min_P_m.x(),
                              (corner & 2) ? box.max_P_m.y() : box.min_P_m.y(),
                              (corner & 4) ? box.max_P_m.z() : box.min_P_m.z());
    const Eigen::Vector3d p_B = X_B_P * p_P;
    out.x_min_m = std::min(out.x_min_m, p_B.x());
    out.x_max_m = std::max(out.x_max_m, p_B.x());
    out.z_min_m = std::min(out.z_min_m, p_B.z());
    out.z_max_m = std::max(out.z_max_m, p_B.z());
  }
  return out;
}

}  // namespace mhd
