#pragma once
// A three-omni-wheel mobile base (POSTECH MHD robot: three omni wheels 120 deg apart,
// 80 mm wheels, 0.5 m/s, 40 deg/s, 50 Hz motor controller).
//
// Frames: world W is y-up; the base frame B has its origin on the floor at the base's
// centre, x_B forward, y_B up, z_B = x_B x y_B. heading is the rotation of B about +y_W,
// so x_B = (cos h, 0, -sin h) in W. A body twist is (vx, vz, omega) in B; its world
// velocity is R_y(h) (vx, 0, vz).
//
// Wheel i (0, 1, 2) sits at angle a_i = i * 120 deg about +y_B from x_B (wheel 0 in
// front), at distance base_radius_m, and drives along t_i = y_B x r_i / |r_i| =
// (-sin a_i, -cos a_i) in (x_B, z_B): a positive wheel speed turns the base about +y.

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <random>

namespace mhd::sim_omni3 {

/// Planar pose of the base on the floor (see the frames above); heading in [-pi, pi].
struct PlanarPose {
  double x_m = 0.0;
  double z_m = 0.0;
  double heading_rad = 0.0;
};

/// (vx_mps, vz_mps, omega_radps): a body twist in B, or a velocity in W.
using Twist = Eigen::Vector3d;
/// Angular speeds of wheels 0, 1, 2 in rad/s.
using WheelSpeeds = Eigen::Vector3d;

/// Inverse and forward kinematics of the wheel layout.
class Omni3Kinematics {
 public:
  /// Precondition: both radii > 0.
  Omni3Kinematics(double base_radius_m, double wheel_radius_m);

  /// Wheel speeds that realise the body twist (no slip).
  [[nodiscard]] WheelSpeeds wheel_speeds(const Twist& twist_B) const { return ik_ * twist_B; }
  /// The body twist that wheel speeds produce (no slip).
  [[nodiscard]] Twist body_twist(const WheelSpeeds& wheels_radps) const { return fk_ * wheels_radps; }

 private:
  Eigen::Matrix3d ik_;
  Eigen::Matrix3d fk_;
};

/// Scales the whole twist by one factor so that |(vx, vz)| <= max_speed_mps and
/// |omega| <= max_omega_radps: the direction of travel and the turn-to-travel ratio stay.
[[nodiscard]] Twist limit_twist(const Twist& twist_B, double max_speed_mps, double max_omega_radps);

struct Omni3Config {
  double base_radius_m = 0.2;
  double wheel_radius_m = 0.04;
  double max_speed_mps = 0.5;
  double max_omega_radps = 0.6981317007977318;  ///< 40 deg/s
  double control_rate_hz = 50.0;
  /// First-order time constant of each wheel's speed loop; 0: the setpoint is reached
  /// within the acceleration limit only.
  double motor_time_constant_s = 0.05;
  /// Largest wheel rim acceleration; all wheels are scaled together so the base keeps
  /// its direction while accelerating.
  double max_wheel_accel_mps2 = 1.0;
  /// Each wheel loses a fraction of its rim speed to slip, drawn uniformly from
  /// [0, slip_fraction] per wheel and controller period. 0: no slip.
  double slip_fraction = 0.0;
  /// The base's own command watchdog: a command older than this stops the base (two
  /// missed 10 Hz commands).
  double command_timeout_s = 0.2;
  /// Integration step of the pose and wheel dynamics.
  double physics_step_s = 0.001;
  std::uint64_t seed = 0;
  PlanarPose initial_pose;
};

/// The base's true motion. Time runs on a fixed grid of physics steps from start():
/// simulate_until(t) advances to the last grid point at or before t, so results do not
/// depend on how often it is called. Not thread-safe.
class Omni3Model {
 public:
  /// Throws std::invalid_argument for a non-positive or non-finite setting.
  explicit Omni3Model(const Omni3Config& config);

  /// Puts the time origin at t_s; keeps the pose, stops the wheels, forgets commands.
  void start(double t_s);

  /// The latest body twist command, received at host time t_received_s. Each 50 Hz
  /// controller tick uses the latest command received at or before it, limited; with no
  /// command, or one older than command_timeout_s, the setpoint is zero.
  void command(const Twist& twist_B, double t_received_s);

  /// Advances to host time t_s (no-op if t_s is not ahead). Precondition: started.
  void simulate_until(double t_s);

  [[nodiscard]] const Omni3Config& config() const { return config_; }
  [[nodiscard]] const Omni3Kinematics& kinematics() const { return kinematics_; }
  /// Host time of the current state (a grid point).
  [[nodiscard]] double time_s() const;
  [[nodiscard]] const PlanarPose& pose() const { return pose_; }
  /// Dead reckoning from the wheel speeds (what encoders would give): drifts with slip.
  [[nodiscard]] const PlanarPose& odometry() const { return odometry_; }
  /// True velocity (slip included) of the base origin in W: (vx, vz, omega).
  [[nodiscard]] Twist velocity_W() const;
  [[nodiscard]] const WheelSpeeds& wheel_speeds() const { return wheels_radps_; }
  /// True when the last controller tick found no fresh command (none, or a stale one).
  [[nodiscard]] bool watchdog_stopped() const { return watchdog_stopped_; }
  /// Host time of the latest command (0 before the first).
  [[nodiscard]] double command_time_s() const { return command_time_s_; }

 private:
  void control_tick(double t_s);
  void physics_step();

  Omni3Config config_;
  Omni3Kinematics kinematics_;
  int steps_per_tick_ = 20;
  std::mt19937_64 rng_;

  double t0_s_ = 0.0;
  std::int64_t step_ = 0;
  bool started_ = false;

  std::optional<Twist> command_B_;
  double command_time_s_ = 0.0;
  bool watchdog_stopped_ = true;

  WheelSpeeds setpoint_radps_ = WheelSpeeds::Zero();
  WheelSpeeds wheels_radps_ = WheelSpeeds::Zero();
  Eigen::Vector3d slip_ = Eigen::Vector3d::Zero();
  Twist twist_B_ = Twist::Zero();  ///< true body twist of the last step
  PlanarPose pose_;
  PlanarPose odometry_;
};

}  // namespace mhd::sim_omni3
