#pragma once
// Parameters of the base motion planner (thesis ch. 3.3-3.8) and how to read them from
// name -> value text (the scene XML's <planner ...> attributes). SI units inside; every
// name carries its unit, and lengths, angles and angular speeds may be given in either
// of two units: "<name>_m" or "<name>_mm", "<name>_rad" or "<name>_deg",
// "<name>_radps" or "<name>_degps". docs/planner.md explains each parameter.

#include "diagnostics/result.h"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace mhd {

class Rig;
struct WorkspaceBox;

/// Axis-aligned rectangle on the floor plane, in the base frame B (x forward, z right).
struct PlanarBox {
  double x_min_m = 0.0;
  double x_max_m = 0.0;
  double z_min_m = 0.0;
  double z_max_m = 0.0;

  [[nodiscard]] bool contains(double x_m, double z_m) const noexcept {
    return x_m >= x_min_m && x_m <= x_max_m && z_m >= z_min_m && z_m <= z_max_m;
  }
};

/// Which planner: the thesis's (ch. 3.4, Table 3.1) or MHD's predictive one.
enum class PlannerKind { Seed, Predictive };

[[nodiscard]] std::string_view to_string(PlannerKind kind) noexcept;
/// "seed" or "predictive"; false for anything else.
[[nodiscard]] bool parse_planner_kind(std::string_view text, PlannerKind& kind) noexcept;

struct PlannerSettings {
  /// The user's hand reach (body centre to hand), the thesis's "human arm length".
  double arm_length_m = 0.45;
  /// The thesis's robot radius: base centre to the HIP's resting place. 0.225 m puts the hand
  /// at the centre of the usable workspace's depth with scenes/rigs/pomhi.xml.
  double robot_radius_m = 0.225;
  double human_radius_m = 0.25;
  /// pi': the largest angle (seen from the user) between base and target for a straight move,
  /// and the advance of each temporary sub-target.
  double step_angle_rad = 0.5235987755982988;  // 30 deg
  double max_linear_speed_mps = 0.5;
  double max_angular_speed_radps = 0.6981317007977318;  // 40 deg/s
  /// Within this distance of its goal the speed falls in proportion to the distance (seed).
  double deceleration_interval_m = 0.2;
  /// Within this heading error the turn rate falls in proportion to it (seed).
  double angular_deceleration_interval_rad = 0.3490658503988659;  // 20 deg
  /// Closer than this to the target the base has arrived: linear velocity 0.
  double stop_interval_m = 0.05;
  /// Heading errors below this count as facing the user.
  double stop_angle_rad = 0.03490658503988659;  // 2 deg
  /// Direction the device faces in B, as an angle about +y from B's x axis: the base turns so
  /// that this direction points at the user. -90 deg is B's +z (scenes/rigs/pomhi.xml).
  double facing_angle_rad = -1.5707963267948966;
  /// The arm's usable workspace projected on the floor, in B (the base cannot move the HIP
  /// vertically, so height is not checked). Default: pomhi.xml with the PHANToM 1.5.
  PlanarBox usable_B{-0.1621, 0.1589, 0.1603, 0.2913};
  /// The planner also acts when the base is nearer the user than collision radius + this,
  /// and the guard removes any velocity towards the user inside that band.
  double safety_margin_m = 0.05;
  /// How far ahead the predictive planner extrapolates the user's tracked velocity.
  double prediction_horizon_s = 0.3;
  /// Predictive planner: drives the HIP at least this far inside the usable workspace's
  /// edges before it stops (the catch goal's box).
  double catch_margin_m = 0.025;
  /// The period at which update() is called (the haptic server's planner loop: 10 Hz).
  double command_period_s = 0.1;

  /// d' = arm length + robot radius: the base's distance from the user at its target.
  [[nodiscard]] double target_distance_m() const noexcept { return arm_length_m + robot_radius_m; }
  /// Radius of the user's cylinder in configuration space: robot radius + human radius.
  [[nodiscard]] double collision_radius_m() const noexcept { return robot_radius_m + human_radius_m; }
};

/// Every problem with a settings value, e.g. "step_angle_deg must be in (0, 90], got 120".
[[nodiscard]] std::vector<std::string> validate(const PlannerSettings& settings);

/// Starts from `defaults`, applies each name -> value (names as in PlannerSettings with a
/// unit suffix: "max_linear_speed_mps", "step_angle_deg", "usable_x_min_mm", ...), then
/// validates. The error is one message per bad entry. Unknown names, unparsable numbers and invalid results are all reported, e.g.
/// "unknown planner setting 'max_speed' (known: arm_length_m|mm, ...)" or
/// "planner setting 'stop_interval_m': 'abc' is not a number".
[[nodiscard]] Result<PlannerSettings, std::vector<std::string>> planner_settings_from_map(
    const std::map<std::string, std::string>& values, const PlannerSettings& defaults = {});

/// The device's usable workspace projected on the floor in B, from a rig: the bounding
/// rectangle of the usable box's corners (exact when P's axes are B's, as in pomhi.xml).
[[nodiscard]] PlanarBox usable_box_in_base(const Rig& rig) noexcept;
/// The same for a usable box `usable_P` in the device frame P (a device's own report).
[[nodiscard]] PlanarBox usable_box_in_base(const Rig& rig, const WorkspaceBox& usable_P) noexcept;

}  // namespace mhd
