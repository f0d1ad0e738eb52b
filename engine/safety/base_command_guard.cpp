#include "safety/base_command_guard.h"

#include <algorithm>
#include <cmath>

namespace mhd {

BaseCommandGuard::BaseCommandGuard(const BaseCommandGuardSettings& settings) noexcept : settings_(settings) {}

BaseStopCause BaseCommandGuard::stop_cause(const BaseTwist& c, const BaseGuardInput& in) const noexcept {
  const bool finite = std::isfinite(c.vx_mps) && std::isfinite(c.vz_mps) && std::isfinite(c.omega_radps) &&
                      std::isfinite(in.X_WB.x_m) && std::isfinite(in.X_WB.z_m) && std::isfinite(in.X_WB.heading_rad) &&
                      std::isfinite(in.t_s);
  if (!finite) return BaseStopCause::NotFinite;
  if (!(in.base_age_s < settings_.tracker_timeout_s)) return BaseStopCause::BaseStale;
  if (!(in.head_age_s < settings_.tracker_timeout_s) || !in.p_W_head_xz_m.allFinite()) return BaseStopCause::HeadStale;
  return BaseStopCause::None;
}

bool BaseCommandGuard::keep_out(BaseTwist& t, const BaseGuardInput& in) const noexcept {
  const double hold_s = settings_.command_hold_s;
  const double margin_m = settings_.user_max_speed_mps * (std::max(in.head_age_s, 0.0) + hold_s) +
                          settings_.max_speed_mps * (std::max(in.base_age_s, 0.0) + hold_s);
  const Eigen::Vector2d to_user(in.p_W_head_xz_m.x() - in.X_WB.x_m, in.p_W_head_xz_m.y() - in.X_WB.z_m);
  const double distance_m = to_user.norm();
  if (distance_m >= settings_.keep_out_m + margin_m) return false;
  // Ry(h) maps (vx, vz) to world (x, z) = (c vx + s vz, -s vx + c vz).
  const double c = std::cos(in.X_WB.heading_rad), s = std::sin(in.X_WB.heading_rad);
  const Eigen::Vector2d v_W(c * t.vx_mps + s * t.vz_mps, -s * t.vx_mps + c * t.vz_mps);
  Eigen::Vector2d kept_W = Eigen::Vector2d::Zero();
  if (distance_m > margin_m) {
    // The user is somewhere in the disk of radius margin around the tracked head: allowed
    // velocities point away from every place in it, a cone of half-angle pi/2 - theta about
    // -u. Outside the cone, v goes to its projection on the nearer edge (or zero).
    const Eigen::Vector2d u = to_user / distance_m;
    const Eigen::Vector2d w(-u.y(), u.x());
    const double sin_theta = margin_m / distance_m, cos_theta = std::sqrt(1.0 - sin_theta * sin_theta);
    const double a = v_W.dot(u), b = v_W.dot(w);
    if (a * cos_theta + std::abs(b) * sin_theta <= 0.0) return false;  // inside the cone
    const Eigen::Vector2d edge = -sin_theta * u + std::copysign(cos_theta, b) * w;
    kept_W = std::max(0.0, v_W.dot(edge)) * edge;
  }  // else the user may be anywhere around the base: no linear motion at all
  t.vx_mps = c * kept_W.x() - s * kept_W.y();
  t.vz_mps = s * kept_W.x() + c * kept_W.y();
  return true;
}

BaseGuardDecision BaseCommandGuard::apply(const BaseTwist& command_B, const BaseGuardInput& in) noexcept {
  BaseGuardDecision out;
  const BaseStopCause cause = stop_cause(command_B, in);
  if (cause != BaseStopCause::None) {
    if (cause != previous_cause_) {
      if (cause == BaseStopCause::NotFinite) ++counts_.not_finite;
      if (cause == BaseStopCause::BaseStale) ++counts_.base_stale;
      if (cause == BaseStopCause::HeadStale) ++counts_.head_stale;
    }
    previous_cause_ = cause;
    out.action = BaseGuardAction::Stopped;
    out.stop_cause = cause;
    return out;  // zero twist
  }
  if (previous_cause_ != BaseStopCause::None) {
    resume_start_s_ = in.t_s;
    previous_cause_ = BaseStopCause::None;
  }
  BaseTwist t = command_B;
  if (keep_out(t, in)) {
    ++counts_.keep_out_deflections;
    out.action = BaseGuardAction::Deflected;
  }

  // Limits, ramping back in after a stop so the base resumes smoothly.
  const double since_resume_s = std::max(0.0, in.t_s - resume_start_s_);
  const double max_speed_mps = std::min(settings_.max_speed_mps, settings_.resume_accel_mps2 * since_resume_s);
  const double max_omega_radps = std::min(settings_.max_omega_radps, settings_.resume_angular_accel_radps2 * since_resume_s);
  const double speed = std::hypot(t.vx_mps, t.vz_mps);
  double scale = 1.0;
  if (speed > max_speed_mps) scale = max_speed_mps / speed;
  if (std::abs(t.omega_radps) * scale > max_omega_radps) scale = max_omega_radps / std::abs(t.omega_radps);
  if (scale < 1.0) {
    t.vx_mps *= scale;
    t.vz_mps *= scale;
    t.omega_radps *= scale;
    if (out.action == BaseGuardAction::Passed) out.action = BaseGuardAction::Scaled;
  }
  out.twist_B = t;
  return out;
}

}  // namespace mhd
