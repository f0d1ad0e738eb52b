#include "sim_omni3_model.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace mhd::sim_omni3 {
namespace {

void require_positive(double value, const char* name) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(std::string(name) + " must be a positive number");
  }
}

/// World velocity of a body twist at heading h: R_y(h) (vx, 0, vz).
Twist to_world(const Twist& twist_B, double heading_rad) {
  const double c = std::cos(heading_rad);
  const double s = std::sin(heading_rad);
  return {c * twist_B[0] + s * twist_B[1], -s * twist_B[0] + c * twist_B[1], twist_B[2]};
}

/// One step with the twist held constant, world velocity taken at mid-step heading.
void integrate(PlanarPose& pose, const Twist& twist_B, double dt_s) {
  const Twist v_W = to_world(twist_B, pose.heading_rad + 0.5 * twist_B[2] * dt_s);
  pose.x_m += v_W[0] * dt_s;
  pose.z_m += v_W[1] * dt_s;
  pose.heading_rad = std::remainder(pose.heading_rad + v_W[2] * dt_s, 2.0 * std::numbers::pi);
}

}  // namespace

Omni3Kinematics::Omni3Kinematics(double base_radius_m, double wheel_radius_m) {
  require_positive(base_radius_m, "base_radius_m");
  require_positive(wheel_radius_m, "wheel_radius_m");
  // Rim speed u_i = t_i . v + omega * R with t_i = (-sin a_i, -cos a_i).
  for (int i = 0; i < 3; ++i) {
    const double a = 2.0 * std::numbers::pi * i / 3.0;
    ik_.row(i) << -std::sin(a), -std::cos(a), base_radius_m;
  }
  ik_ /= wheel_radius_m;
  fk_ = ik_.inverse();
}

Twist limit_twist(const Twist& twist_B, double max_speed_mps, double max_omega_radps) {
  const double speed = std::hypot(twist_B[0], twist_B[1]);
  const double omega = std::abs(twist_B[2]);
  double scale = 1.0;
  if (speed > max_speed_mps) scale = std::min(scale, max_speed_mps / speed);
  if (omega > max_omega_radps) scale = std::min(scale, max_omega_radps / omega);
  return twist_B * scale;
}

Omni3Model::Omni3Model(const Omni3Config& config)
    : config_(config), kinematics_(config.base_radius_m, config.wheel_radius_m), rng_(config.seed) {
  require_positive(config.max_speed_mps, "max_speed_mps");
  require_positive(config.max_omega_radps, "max_omega_radps");
  require_positive(config.control_rate_hz, "control_rate_hz");
  require_positive(config.max_wheel_accel_mps2, "max_wheel_accel_mps2");
  require_positive(config.command_timeout_s, "command_timeout_s");
  require_positive(config.physics_step_s, "physics_step_s");
  if (!(config.motor_time_constant_s >= 0.0) || !std::isfinite(config.motor_time_constant_s)) {
    throw std::invalid_argument("motor_time_constant_s must be a non-negative number");
  }
  if (!(config.slip_fraction >= 0.0 && config.slip_fraction < 1.0)) {
    throw std::invalid_argument("slip_fraction must be in [0, 1)");
  }
  const PlanarPose& p = config.initial_pose;
  if (!std::isfinite(p.x_m) || !std::isfinite(p.z_m) || !std::isfinite(p.heading_rad)) {
    throw std::invalid_argument("initial_pose must be finite");
  }
  // The controller period, in whole physics steps.
  steps_per_tick_ = std::max(1, static_cast<int>(std::lround(1.0 / (config.control_rate_hz * config.physics_step_s))));
  pose_ = p;
  odometry_ = p;
}

void Omni3Model::start(double t_s) {
  if (!std::isfinite(t_s)) throw std::invalid_argument("start time must be finite");
  t0_s_ = t_s;
  step_ = 0;
  started_ = true;
  command_B_.reset();
  watchdog_stopped_ = true;
  setpoint_radps_.setZero();
  wheels_radps_.setZero();
  slip_.setZero();
  twist_B_.setZero();
}

void Omni3Model::command(const Twist& twist_B, double t_received_s) {
  if (!twist_B.allFinite() || !std::isfinite(t_received_s)) {
    throw std::invalid_argument("base command has a non-finite value");
  }
  command_B_ = twist_B;
  command_time_s_ = t_received_s;
}

double Omni3Model::time_s() const { return t0_s_ + static_cast<double>(step_) * config_.physics_step_s; }

Twist Omni3Model::velocity_W() const { return to_world(twist_B_, pose_.heading_rad); }

void Omni3Model::simulate_until(double t_s) {
  if (!started_) throw std::logic_error("simulate_until before start");
  if (!std::isfinite(t_s)) throw std::invalid_argument("simulation time must be finite");
  // The tolerance keeps a t_s that lands on a grid point from losing that step to rounding.
  const double steps = std::floor((t_s - t0_s_) / config_.physics_step_s + 1e-9);
  while (static_cast<double>(step_) < steps) {
    if (step_ % steps_per_tick_ == 0) control_tick(time_s());
    physics_step();
    ++step_;
  }
}

void Omni3Model::control_tick(double t_s) {
  constexpr double kTimeTolerance_s = 1e-9;
  const bool fresh = command_B_ && command_time_s_ <= t_s + kTimeTolerance_s &&
                     t_s - command_time_s_ <= config_.command_timeout_s + kTimeTolerance_s;
  watchdog_stopped_ = !fresh;
  setpoint_radps_ = fresh ? kinematics_.wheel_speeds(
                                limit_twist(*command_B_, config_.max_speed_mps, config_.max_omega_radps))
                          : WheelSpeeds::Zero();
  // Slip is drawn only while the wheels turn, so a resting base consumes no random numbers.
  const bool moving = !setpoint_radps_.isZero(0.0) || !wheels_radps_.isZero(0.0);
  if (config_.slip_fraction > 0.0 && moving) {
    std::uniform_real_distribution<double> loss(0.0, config_.slip_fraction);
    for (int i = 0; i < 3; ++i) slip_[i] = loss(rng_);
  }
}

void Omni3Model::physics_step() {
  const double dt = config_.physics_step_s;
  const double tau = config_.motor_time_constant_s;
  const double gain = tau > 0.0 ? -std::expm1(-dt / tau) : 1.0;
  WheelSpeeds change = (setpoint_radps_ - wheels_radps_) * gain;
  const double max_change = config_.max_wheel_accel_mps2 / config_.wheel_radius_m * dt;
  const double largest = change.cwiseAbs().maxCoeff();
  if (largest > max_change) change *= max_change / largest;
  wheels_radps_ += change;

  const WheelSpeeds ground_radps = wheels_radps_.cwiseProduct((Eigen::Vector3d::Ones() - slip_));
  twist_B_ = kinematics_.body_twist(ground_radps);
  integrate(pose_, twist_B_, dt);
  integrate(odometry_, kinematics_.body_twist(wheels_radps_), dt);
}

}  // namespace mhd::sim_omni3
