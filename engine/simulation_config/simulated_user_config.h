#pragma once
// What the scripted user of a simulated session does (simulation/simulated_user.h), as a
// scene's <simulated_user> block declares it: the path or random walk, and the body. Kept
// apart from the user itself so that a scene can be judged (haptic_server/run_check.h)
// without linking the simulation.

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <optional>
#include <string_view>
#include <vector>

namespace mhd::simulation {

/// A pose on the floor: position (x, z) and heading about +y.
struct PlanarPose {
  double x_m = 0.0, z_m = 0.0;
  double heading_rad = 0.0;
};

struct Waypoint {
  double x_m = 0.0;
  double z_m = 0.0;
  double speed_mps = 0.0;  ///< walking speed on the way to this waypoint
};

/// Parses "x z speed; x z speed; ..." (metres, m/s; numbers separated by blanks,
/// waypoints by ';'). Throws std::invalid_argument, e.g. "waypoint 2: expected 'x z
/// speed_mps', got '1 2'".
[[nodiscard]] std::vector<Waypoint> parse_waypoints(std::string_view text);

/// A user who crouches and reaches: the hand's height goes from `low_m` up to `high_m` and
/// back at `speed_mps`, holding `hold_s` at each end, starting crouched at `low_m`. The eyes
/// come down with a low hand (a crouch): eye_height_at() below.
struct HandHeightSweep {
  double low_m = 0.3;
  double high_m = 1.9;
  double speed_mps = 0.3;
  double hold_s = 1.0;
};

/// The hand's height at `time_s` since the user started (the sweep's, or `fixed_m`).
[[nodiscard]] double hand_height_at(const std::optional<HandHeightSweep>& sweep, double fixed_m, double time_s) noexcept;
/// The eye height of a user whose hand is at `hand_height_m`: standing (`standing_m`)
/// until the hand comes within 0.7 m of the eyes' height, then crouching with it, down to
/// 1 m.
[[nodiscard]] double eye_height_at(double standing_m, double hand_height_m) noexcept;

struct SimulatedUserConfig {
  /// Scripted path: the user starts on the first waypoint (its speed is used only when
  /// looping back to it) and walks to each next one at that one's speed. Empty: random walk.
  std::vector<Waypoint> path;
  /// After the last waypoint, walk back to the first and go round again; else stand.
  bool loop_path = false;
  /// No part of the walk is faster; path speeds above it are an error.
  double max_speed_mps = 1.5;
  /// The heading turns towards the walking direction at most this fast.
  double max_turn_rate_radps = 3.0;

  // Random walk (used when path is empty): a sequence of manoeuvres.
  std::uint64_t seed = 0;
  PlanarPose start;                       ///< where the random walk begins
  double walk_speed_min_mps = 0.3;        ///< walking: speed drawn from [min, max]
  double walk_speed_max_mps = 1.0;
  double walk_turn_rate_max_radps = 0.6;  ///< walking: constant turn rate from [-max, max]
  double side_step_probability = 0.25;    ///< chance that a manoeuvre is a side-step
  double stand_probability = 0.15;        ///< chance that a manoeuvre is a pause
  double side_step_speed_max_mps = 1.5;   ///< side-step speed drawn from [0.5, 1] x this
  /// Soft bound: beyond |x| or |z| = this the walk steers back towards the origin.
  double area_half_size_m = 3.0;

  // Body.
  double eye_height_m = 1.65;
  std::optional<Eigen::Vector3d> gaze_target_W;  ///< the head faces this point when set
  double hand_reach_m = 0.45;                    ///< in front of the chest, horizontally
  double hand_height_m = 1.1;
  std::optional<HandHeightSweep> hand_height_sweep;  ///< set: crouches and reaches (hand_height_m unused)
  double hand_motion_amplitude_m = 0.02;  ///< per axis, slow sinusoids with seeded phases

  double start_time_s = 0.0;
  double step_s = 0.005;
};

/// Throws std::invalid_argument naming the first problem (a path speed above the maximum,
/// a probability outside [0, 1], ...).
void validate(const SimulatedUserConfig& config);

}  // namespace mhd::simulation
