#include "safety/base_command_guard.h"

#include <algorithm>
#include <cmath>

namespace mhd {

BaseCommandGuard::BaseCommandGuard(const BaseCommandGuardSettings& settings) noexcept : settings_(settings) {}

BaseGuardResult BaseCommandGuard::apply(const BaseTwist& command_B, const BasePose& base,
                                        const Eigen::Vector2d& user_xz_W, double tracker_age_s) noexcept {
  BaseGuardResult out;
  const bool finite = std::isfinite(command_B.vx_mps) && std::isfinite(command_B.vz_mps) &&
                      std::isfinite(command_B.omega_radps) && std::isfinite(base.x_m) && std::isfinite(base.z_m) &&
                      std::isfinite(base.heading_rad);
  if (!finite || !(tracker_age_s < settings_.tracker_timeout_s)) {
    ++stops_;
    out.action = BaseGuardAction::Stopped;
    return out;  // zero twist
  }
  BaseTwist t = command_B;

  // Keep-out: in the world, v_W = Ry(h) (vx, 0, vz); the component towards the user is cut.
  if (user_xz_W.allFinite()) {
    const Eigen::Vector2d to_user(user_xz_W.x() - base.x_m, user_xz_W.y() - base.z_m);
    const double distance = to_user.norm();
    if (distance < settings_.keep_out_m && distance > 1e-9) {
      const Eigen::Vector2d dir_W = to_user / distance;  // (x, z)
      const double c = std::cos(base.heading_rad), s = std::sin(base.heading_rad);
      // Ry(h) maps (vx, vz) to world (x, z) = (c vx + s vz, -s vx + c vz).
      Eigen::Vector2d v_W(c * t.vx_mps + s * t.vz_mps, -s * t.vx_mps + c * t.vz_mps);
      const double towards = v_W.dot(dir_W);
      if (towards > 0.0) {
        v_W -= towards * dir_W;
        t.vx_mps = c * v_W.x() - s * v_W.y();
        t.vz_mps = s * v_W.x() + c * v_W.y();
        ++deflections_;
        out.action = BaseGuardAction::Deflected;
      }
    }
  }

  const double speed = std::hypot(t.vx_mps, t.vz_mps);
  double scale = 1.0;
  if (speed > settings_.max_speed_mps) scale = settings_.max_speed_mps / speed;
  if (std::abs(t.omega_radps) * scale > settings_.max_omega_radps) scale = settings_.max_omega_radps / std::abs(t.omega_radps);
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
