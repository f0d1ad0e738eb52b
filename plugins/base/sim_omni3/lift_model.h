#pragma once
// A vertical lift carried by the base (the rig's <lift>, kinematics/rig.h): a
// motor that follows a commanded vertical speed within its own speed and
// acceleration limits, between end stops. Its controller brakes ahead of each
// stop, so the lift reaches it at rest and never passes it; without a fresh
// command (its own watchdog) it brakes to a stop.
//
// Time runs on a fixed grid of physics steps from start(): simulate_until(t)
// advances to the last grid point at or before t, so results do not depend on
// how often it is called. Not thread-safe.

namespace mhd::sim_omni3 {

struct LiftConfig {
  double min_m = 0.0;  ///< lower end stop, at or below 0 (the rig file's arm height)
  double max_m = 0.0;  ///< upper end stop, at or above 0; above min_m
  double max_speed_mps = 0.2;
  double max_acceleration_mps2 = 1.0;
  double command_timeout_s = 0.2;
  double physics_step_s = 0.001;
  double initial_m = 0.0;  ///< where the lift stands at start (within the stops)
};

class LiftModel {
 public:
  /// Throws std::invalid_argument naming the first bad setting.
  explicit LiftModel(const LiftConfig &config);

  /// Puts the time origin at t_s; keeps the height, stops, forgets commands.
  void start(double t_s);
  /// The commanded vertical speed (up positive), received at host time
  /// t_received_s. Throws std::invalid_argument when it is not finite.
  void command(double v_mps, double t_received_s);
  /// Advances to host time t_s (no-op if t_s is not ahead).
  void simulate_until(double t_s);

  [[nodiscard]] const LiftConfig &config() const noexcept { return config_; }
  [[nodiscard]] double height_m() const noexcept { return height_m_; }
  [[nodiscard]] double velocity_mps() const noexcept { return velocity_mps_; }
  /// True when the last step found no fresh command (none, or one older than
  /// the timeout).
  [[nodiscard]] bool watchdog_stopped() const noexcept { return watchdog_stopped_; }

 private:
  void step(double t_s);

  LiftConfig config_;
  double height_m_ = 0.0;
  double velocity_mps_ = 0.0;
  double command_mps_ = 0.0;
  double command_time_s_ = 0.0;
  bool commanded_ = false;
  bool watchdog_stopped_ = true;
  double t0_s_ = 0.0;
  long long steps_ = 0;
};

}  // namespace mhd::sim_omni3
