#include "lift_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace mhd::sim_omni3 {
namespace {

void require(bool ok, const std::string &what) {
  if (!ok) throw std::invalid_argument("lift: " + what);
}

}  // namespace

LiftModel::LiftModel(const LiftConfig &config) : config_(config), height_m_(config.initial_m) {
  const LiftConfig &c = config;
  require(std::isfinite(c.min_m) && std::isfinite(c.max_m) && c.min_m <= 0.0 && c.max_m >= 0.0 && c.min_m < c.max_m,
          "the range must hold 0 and have min < max");
  require(std::isfinite(c.max_speed_mps) && c.max_speed_mps > 0.0, "max speed must be > 0");
  require(std::isfinite(c.max_acceleration_mps2) && c.max_acceleration_mps2 > 0.0, "max acceleration must be > 0");
  require(std::isfinite(c.command_timeout_s) && c.command_timeout_s > 0.0, "command timeout must be > 0");
  require(std::isfinite(c.physics_step_s) && c.physics_step_s > 0.0, "physics step must be > 0");
  require(std::isfinite(c.initial_m) && c.initial_m >= c.min_m && c.initial_m <= c.max_m,
          "the start height must be within the range");
}

void LiftModel::start(double t_s) {
  if (!std::isfinite(t_s)) throw std::invalid_argument("lift: start time must be finite");
  t0_s_ = t_s;
  steps_ = 0;
  velocity_mps_ = 0.0;
  commanded_ = false;
  watchdog_stopped_ = true;
}

void LiftModel::command(double v_mps, double t_received_s) {
  if (!std::isfinite(v_mps) || !std::isfinite(t_received_s)) {
    throw std::invalid_argument("lift: the command is not finite");
  }
  command_mps_ = v_mps;
  command_time_s_ = t_received_s;
  commanded_ = true;
}

void LiftModel::simulate_until(double t_s) {
  if (!std::isfinite(t_s)) return;
  for (;;) {
    const double next_t_s = t0_s_ + static_cast<double>(steps_ + 1) * config_.physics_step_s;
    if (next_t_s > t_s) return;
    step(next_t_s);
    ++steps_;
  }
}

void LiftModel::step(double t_s) {
  const double dt = config_.physics_step_s;
  const double a_max = config_.max_acceleration_mps2;
  const bool fresh = commanded_ && command_time_s_ <= t_s && t_s - command_time_s_ <= config_.command_timeout_s;
  watchdog_stopped_ = !fresh;
  double setpoint = fresh ? std::clamp(command_mps_, -config_.max_speed_mps, config_.max_speed_mps) : 0.0;
  // Brake ahead of the end stops: never faster than what stops within the room
  // left.
  const double room_up = std::max(0.0, config_.max_m - height_m_);
  const double room_down = std::max(0.0, height_m_ - config_.min_m);
  setpoint = std::min(setpoint, std::sqrt(2.0 * a_max * room_up));
  setpoint = std::max(setpoint, -std::sqrt(2.0 * a_max * room_down));
  velocity_mps_ += std::clamp(setpoint - velocity_mps_, -a_max * dt, a_max * dt);
  height_m_ += velocity_mps_ * dt;
  // The end stops themselves: the lift halts on them.
  if (height_m_ >= config_.max_m || height_m_ <= config_.min_m) {
    height_m_ = std::clamp(height_m_, config_.min_m, config_.max_m);
    velocity_mps_ = 0.0;
  }
}

}  // namespace mhd::sim_omni3
