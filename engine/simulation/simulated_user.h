#pragma once
// The scripted user of a simulated session: walks a path of waypoints, or a seeded
// random walk with turns, pauses and sudden side-steps; keeps the head at eye height
// facing the walking direction (or a fixed target) and holds the hand at arm's reach
// in front of the chest with small motions. update() writes head and hand to the
// SimulatedWorld.
//
// The body moves on a fixed grid of steps (step_s) from start_time_s; between grid
// points it is interpolated linearly, so the state at a time does not depend on how
// often the user was advanced, and no speed ever exceeds max_speed_mps.
// Frames as in simulated_world.h: heading h about +y, forward (cos h, 0, -sin h),
// right-hand side (sin h, 0, cos h) (the +z axis of the body frame).

#include "simulation/simulated_world.h"
#include "simulation_config/simulated_user_config.h"

#include <Eigen/Geometry>

#include <cstdint>
#include <optional>
#include <random>
#include <string_view>
#include <vector>

namespace mhd::simulation {

class SimulatedUser {
 public:
  /// Throws std::invalid_argument for an invalid configuration (a path speed above the
  /// maximum, a probability outside [0, 1], ...).
  explicit SimulatedUser(SimulatedUserConfig config);

  /// Moves to time t_s; a time before the current one is ignored.
  void advance_to(double t_s);
  /// advance_to(t_s), then writes head and hand into the world.
  void update(double t_s, SimulatedWorld& world);

  [[nodiscard]] double time_s() const { return time_s_; }
  /// Position on the floor and heading (the body's facing).
  [[nodiscard]] PlanarPose body() const;
  /// Walking velocity (vx, vz) in the world.
  [[nodiscard]] Eigen::Vector2d velocity_W() const;
  [[nodiscard]] bool side_stepping() const { return next_.side_stepping; }
  /// Side-steps begun so far (random walk).
  [[nodiscard]] int side_steps_started() const { return side_steps_started_; }
  /// True once a non-looping path has reached its last waypoint.
  [[nodiscard]] bool path_finished() const { return path_finished_; }

  [[nodiscard]] HeadPose head() const;
  [[nodiscard]] Eigen::Vector3d hand_W() const;

  [[nodiscard]] const SimulatedUserConfig& config() const { return config_; }

 private:
  struct GridState {
    double x_m = 0.0;
    double z_m = 0.0;
    double heading_rad = 0.0;
    bool side_stepping = false;  ///< the step that ends here was a side-step
  };
  enum class Manoeuvre { Walk, SideStep, Stand };

  [[nodiscard]] GridState step(const GridState& s, double t_s);
  [[nodiscard]] GridState step_path(const GridState& s);
  [[nodiscard]] GridState step_random(const GridState& s, double t_s);
  void choose_manoeuvre(const GridState& s, double t_s);
  [[nodiscard]] double uniform(double lo, double hi);

  SimulatedUserConfig config_;
  std::mt19937_64 rng_;

  std::int64_t step_index_ = 0;  ///< previous_ is at start + index * step, next_ one step later
  GridState previous_;
  GridState next_;
  double time_s_ = 0.0;

  // Scripted path.
  std::size_t target_ = 1;
  bool path_finished_ = false;

  // Random walk.
  Manoeuvre manoeuvre_ = Manoeuvre::Stand;
  double manoeuvre_end_s_ = 0.0;
  double speed_mps_ = 0.0;      ///< walk: forward speed; side-step: signed speed to the right
  double turn_rate_radps_ = 0.0;
  int side_steps_started_ = 0;

  // Hand motion: per axis, frequency and phase.
  Eigen::Vector3d hand_frequency_hz_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d hand_phase_rad_ = Eigen::Vector3d::Zero();
};

}  // namespace mhd::simulation
