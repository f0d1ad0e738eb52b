#pragma once
// The planner simulator of thesis ch. 3.6 (Fig. 3.8-3.10), faster than real time.
//
// Scene: the user stands at the origin facing +x (heading 0) with the hand arm's length
// (settings.arm_length_m) in front; the base waits at its target, facing the user, planner
// idle. At t = 0 the user is at a new position of a grid (and turned by a facing change),
// hand again arm's length in front, and stands there. The planner runs at its command period
// (10 Hz) on a velocity-controlled base (the twist held over each period, exact arcs, no
// acceleration limit, as in the thesis's simulator). The position is "followed" when the
// HIP (the hand) is inside the planar usable workspace at some check time t <= 1 s (checks
// every period / substeps). The followed area is the number of followed cells times the
// cell area. Deterministic; nothing here touches files.
//
// In 3-D (simulate_volume) the hand is also at one of a list of heights, and a position
// is followed only when the hand is inside the usable workspace's vertical extent too, at
// the same check time: the arm at its fixed height, or on a lift that LiftPlanner drives
// from height 0 (where the rig file puts the arm) at t = 0. The followed volume is the sum
// over heights of the followed area times the height step.

#include "kinematics/rig.h"
#include "planner/planner.h"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mhd::plan_sim {

/// The arm's usable reach in height: the usable workspace's vertical extent in the world
/// with the lift at 0 (the defaults: scenes/rigs/pomhi.xml's PHANToM, its frame 0.87 m up,
/// the usable box 30 mm inside the workspace), and the lift that carries it, if any.
struct VerticalReach {
  double low_m = 0.8965;
  double high_m = 1.1035;
  std::optional<Lift> lift;
};

struct MapSpec {
  double half_size_m = 1.5;         ///< the grid covers [-half, half]^2 around the start
  double cell_m = 0.025;
  double facing_change_rad = 0.0;   ///< the user's new facing minus the old one
  double horizon_s = 1.0;
  int substeps = 10;                ///< success checks per command period
  double hand_height_m = 1.1;       ///< the hand's height at the new position
  /// Set: the hand must be within the arm's vertical reach too (3-D); unset: planar only.
  std::optional<VerticalReach> vertical;
};

struct CaseFigures {
  bool followed = false;
  double time_s = 0.0;        ///< when the HIP was first back inside (if followed)
  bool base_entered = false;  ///< the base moved into (or deeper into) the user's cylinder
};

/// One next user position (world x, z) with the spec's facing change.
[[nodiscard]] CaseFigures simulate_case(PlannerKind kind, const PlannerSettings& settings, const MapSpec& spec,
                                       const Eigen::Vector2d& next_user_W);

struct FollowMap {
  int cells_per_side = 0;
  double half_size_m = 0.0;
  double cell_m = 0.0;
  std::vector<std::uint8_t> followed;  ///< row-major: row = z index (z ascending), column = x index
  std::vector<double> follow_time_s;   ///< same layout: when the HIP was first inside (followed cells)
  int followed_cells = 0;
  int base_entries = 0;

  [[nodiscard]] double followed_area_m2() const noexcept { return followed_cells * cell_m * cell_m; }
  [[nodiscard]] Eigen::Vector2d cell_center(int ix, int iz) const noexcept;
};

[[nodiscard]] FollowMap simulate_map(PlannerKind kind, const PlannerSettings& settings, const MapSpec& spec);

/// The followed volume: simulate_map at each of `hand_heights_m` (evenly spaced, at least
/// two), with spec.vertical set (the spec's own, or the default reach without a lift).
struct FollowVolume {
  std::vector<double> hand_heights_m;
  std::vector<int> followed_cells;  ///< per height
  double cell_m = 0.0;
  double height_step_m = 0.0;
  int base_entries = 0;

  [[nodiscard]] double followed_volume_m3() const noexcept;
};

[[nodiscard]] FollowVolume simulate_volume(PlannerKind kind, const PlannerSettings& settings, MapSpec spec,
                                           const std::vector<double>& hand_heights_m);

struct TableRow {
  PlannerKind kind = PlannerKind::Seed;
  double facing_change_rad = 0.0;
  double max_linear_speed_mps = 0.0;
  double max_angular_speed_radps = 0.0;
  double followed_area_m2 = 0.0;
  int followed_cells = 0;
  int base_entries = 0;
};

/// "planner,facing_change_deg,max_linear_speed_mps,max_angular_speed_degps,followed_cells,followed_area_m2,base_entries"
/// and one line per row.
[[nodiscard]] std::string table_csv(const std::vector<TableRow>& rows);
/// The table as printed by `mhd plan-sim`: per facing change, areas in m^2 by linear speed
/// (rows) and angular speed (columns) for each planner, and predictive / seed.
[[nodiscard]] std::string table_text(const std::vector<TableRow>& rows);

/// One follow map as CSV, for tools/plots/plan_sim_maps.py to draw (titles, axes, legend and
/// scale need a plotting library, so the pictures are drawn there from these numbers):
/// "# name=value" lines describe the scene (planner, limits, facing change, grid, the user's
/// and the base's start, the user's cylinder), then "x_m,z_m,follow_time_s" for each
/// followed cell (world x, z of its centre; when the HIP was first back inside).
[[nodiscard]] std::string map_csv(const FollowMap& map, PlannerKind kind, const PlannerSettings& settings,
                                  const MapSpec& spec);

}  // namespace mhd::plan_sim
