#include "prediction/base_pose_predictor.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mhd {

namespace {

bool finite(const BasePose& p) noexcept {
  return std::isfinite(p.x_m) && std::isfinite(p.z_m) && std::isfinite(p.heading_rad);
}

bool finite(const BaseTwist& v) noexcept {
  return std::isfinite(v.vx_mps) && std::isfinite(v.vz_mps) && std::isfinite(v.omega_radps);
}

// Moves `value` towards 0 by the exponential decay over dt, by at most max_step.
double decay_scalar(double value, double factor, double max_step) noexcept {
  const double step = std::clamp(value * (1.0 - factor), -max_step, max_step);
  return value - step;
}

}  // namespace

std::string_view to_string(BaseSampleStatus status) noexcept {
  switch (status) {
    case BaseSampleStatus::Accepted: return "accepted";
    case BaseSampleStatus::Reset: return "reset";
    case BaseSampleStatus::OutOfOrder: return "out of order";
    case BaseSampleStatus::Invalid: return "invalid";
  }
  return "unknown";
}

BasePosePredictor::BasePosePredictor(const BasePosePredictorSettings& settings) noexcept : settings_(settings) {}

void BasePosePredictor::reset() noexcept { *this = BasePosePredictor(settings_); }

bool BasePosePredictor::command_fresh(double t_s) const noexcept {
  return has_command_ && std::abs(t_s - t_command_s_) <= settings_.command_timeout_s;
}

void BasePosePredictor::restart(double t_s, const BasePose& pose) noexcept {
  has_estimate_ = true;
  t_estimate_s_ = t_s;
  pose_ = pose;
  expanding_ = !command_fresh(t_s);
  twist_B_ = expanding_ ? BaseTwist{} : command_B_;
  samples_since_restart_ = 1;
  ++generation_;
  rebase_output_ = true;
  ++resets_;
  ++accepted_;
}

BaseSampleStatus BasePosePredictor::add_measurement(double t_s, const BasePose& pose) noexcept {
  if (!std::isfinite(t_s) || !finite(pose)) {
    ++ignored_;
    return BaseSampleStatus::Invalid;
  }
  const double t_measured_s = t_s - settings_.latency_s;
  if (!has_estimate_) {
    restart(t_measured_s, pose);
    return BaseSampleStatus::Reset;
  }
  if (t_measured_s <= t_estimate_s_) {
    ++ignored_;
    return BaseSampleStatus::OutOfOrder;
  }
  const double dt_s = t_measured_s - t_estimate_s_;
  if (dt_s > settings_.reset_gap_s) {
    restart(t_measured_s, pose);
    return BaseSampleStatus::Reset;
  }

  const BasePose predicted = integrate_twist(pose_, twist_B_, dt_s);
  const double error_x_m = pose.x_m - predicted.x_m;
  const double error_z_m = pose.z_m - predicted.z_m;
  const double error_heading_rad = wrap_angle(pose.heading_rad - predicted.heading_rad);
  if (std::hypot(error_x_m, error_z_m) > settings_.reset_distance_m ||
      std::abs(error_heading_rad) > settings_.reset_heading_rad) {
    restart(t_measured_s, pose);
    return BaseSampleStatus::Reset;
  }

  ++samples_since_restart_;
  double position_gain = settings_.position_gain;
  double velocity_gain = settings_.velocity_gain;
  double heading_gain = settings_.heading_gain;
  double yaw_rate_gain = settings_.yaw_rate_gain;
  if (expanding_) {
    // Least-squares line through the n samples since the restart, in alpha-beta form.
    const auto n = static_cast<double>(samples_since_restart_);
    const double alpha_n = 2.0 * (2.0 * n - 1.0) / (n * (n + 1.0));
    const double beta_n = 6.0 / (n * (n + 1.0));
    position_gain = std::max(position_gain, alpha_n);
    velocity_gain = std::max(velocity_gain, beta_n);
    heading_gain = std::max(heading_gain, alpha_n);
    yaw_rate_gain = std::max(yaw_rate_gain, beta_n);
    expanding_ = alpha_n > settings_.position_gain || beta_n > settings_.velocity_gain ||
                 alpha_n > settings_.heading_gain || beta_n > settings_.yaw_rate_gain;
  }
  pose_.x_m = predicted.x_m + position_gain * error_x_m;
  pose_.z_m = predicted.z_m + position_gain * error_z_m;
  pose_.heading_rad = predicted.heading_rad + heading_gain * error_heading_rad;

  // A sample that comes very soon after the last one must not blow up beta / dt.
  const double dt_gain_s = std::max(dt_s, 0.5 * settings_.nominal_period_s);
  const Eigen::Vector2d error_B = world_to_base_xz(predicted.heading_rad, error_x_m, error_z_m);
  twist_B_.vx_mps += velocity_gain * error_B.x() / dt_gain_s;
  twist_B_.vz_mps += velocity_gain * error_B.y() / dt_gain_s;
  twist_B_.omega_radps += yaw_rate_gain * error_heading_rad / dt_gain_s;
  if (command_fresh(t_measured_s)) {
    const double w = settings_.command_weight;
    twist_B_.vx_mps += w * (command_B_.vx_mps - twist_B_.vx_mps);
    twist_B_.vz_mps += w * (command_B_.vz_mps - twist_B_.vz_mps);
    twist_B_.omega_radps += w * (command_B_.omega_radps - twist_B_.omega_radps);
  }

  t_estimate_s_ = t_measured_s;
  ++generation_;
  ++accepted_;
  if (samples_since_restart_ <= static_cast<std::uint64_t>(std::max(settings_.startup_samples, 0))) {
    rebase_output_ = true;
  }
  return BaseSampleStatus::Accepted;
}

bool BasePosePredictor::add_command(double t_s, const BaseTwist& twist_B) noexcept {
  if (!std::isfinite(t_s) || !finite(twist_B) || (has_command_ && t_s < t_command_s_)) return false;
  has_command_ = true;
  t_command_s_ = t_s;
  command_B_ = twist_B;
  return true;
}

BasePose BasePosePredictor::model_at(double t_s) const noexcept {
  const double horizon = settings_.max_extrapolation_s;
  // While the start-up fit still rests on a few noisy samples and no command says how
  // the base moves, its twist is mostly noise (a heading rate from two samples 5 ms
  // apart): projected a metre out to the HIP it made 2-3 cm leaps. Hold the pose then,
  // and never extrapolate faster than a base can move.
  const bool guessing = expanding_ && !command_fresh(t_s) &&
                        samples_since_restart_ <= static_cast<std::uint64_t>(std::max(settings_.startup_samples, 0));
  BaseTwist twist = guessing ? BaseTwist{} : twist_B_;
  const double speed_mps = std::hypot(twist.vx_mps, twist.vz_mps);
  if (speed_mps > settings_.max_speed_mps) {
    twist.vx_mps *= settings_.max_speed_mps / speed_mps;
    twist.vz_mps *= settings_.max_speed_mps / speed_mps;
  }
  twist.omega_radps = std::clamp(twist.omega_radps, -settings_.max_yaw_rate_radps, settings_.max_yaw_rate_radps);
  return integrate_twist(pose_, twist, std::clamp(t_s - t_estimate_s_, -horizon, horizon));
}

BasePose BasePosePredictor::predict(double t_s) noexcept {
  if (!has_estimate_) return BasePose{};
  if (!has_output_ || rebase_output_) {
    output_ = model_at(t_s);
    offset_x_m_ = offset_z_m_ = offset_heading_rad_ = 0.0;
    has_output_ = true;
    rebase_output_ = false;
  } else {
    if (output_generation_ != generation_) {
      // Re-anchor: the new estimate plus the offset reproduces the last output exactly.
      const BasePose model_then = model_at(t_output_s_);
      offset_x_m_ = output_.x_m - model_then.x_m;
      offset_z_m_ = output_.z_m - model_then.z_m;
      offset_heading_rad_ = wrap_angle(output_.heading_rad - model_then.heading_rad);
    }
    const double dt_s = std::max(0.0, t_s - t_output_s_);
    const double factor = std::exp(-dt_s / settings_.smoothing_time_constant_s);
    // The linear offset shrinks along its own direction, by at most speed * dt.
    const double offset_m = std::hypot(offset_x_m_, offset_z_m_);
    if (offset_m > 0.0) {
      const double shrunk_m = decay_scalar(offset_m, factor, settings_.max_correction_speed_mps * dt_s);
      offset_x_m_ *= shrunk_m / offset_m;
      offset_z_m_ *= shrunk_m / offset_m;
    }
    offset_heading_rad_ = decay_scalar(offset_heading_rad_, factor, settings_.max_correction_rate_radps * dt_s);
    const BasePose model_now = model_at(t_s);
    output_ = BasePose{model_now.x_m + offset_x_m_, model_now.z_m + offset_z_m_,
                       model_now.heading_rad + offset_heading_rad_};
  }
  output_generation_ = generation_;
  t_output_s_ = t_s;
  return BasePose{output_.x_m, output_.z_m, wrap_angle(output_.heading_rad)};
}

double BasePosePredictor::age_s(double t_s) const noexcept {
  return has_estimate_ ? t_s - t_estimate_s_ : std::numeric_limits<double>::infinity();
}

bool BasePosePredictor::is_stale(double t_s, double max_age_s) const noexcept { return !(age_s(t_s) <= max_age_s); }

}  // namespace mhd
