#include "planner/planner_geometry.h"

#include <algorithm>
#include <cmath>

namespace mhd::planner_geometry {

Eigen::Vector2d direction(double heading_rad) noexcept {
  return Eigen::Vector2d(std::cos(heading_rad), -std::sin(heading_rad));
}

double heading_of(const Eigen::Vector2d& d) noexcept { return std::atan2(-d.y(), d.x()); }

Eigen::Vector2d follow_target(const Eigen::Vector2d& user, const Eigen::Vector2d& hand, double user_heading_rad,
                              double distance_m) noexcept {
  const Eigen::Vector2d to_hand = hand - user;
  const double n = to_hand.norm();
  const Eigen::Vector2d dir = n > 1e-3 ? Eigen::Vector2d(to_hand / n) : direction(user_heading_rad);
  return user + distance_m * dir;
}

double facing_heading(const Eigen::Vector2d& base, const Eigen::Vector2d& user, double facing_angle_rad) noexcept {
  // The device's direction in W is heading + facing angle; it must be heading_of(user - base).
  return wrap_angle(heading_of(user - base) - facing_angle_rad);
}

double signed_angle(const Eigen::Vector2d& a, const Eigen::Vector2d& b) noexcept {
  return wrap_angle(heading_of(b) - heading_of(a));
}

Eigen::Vector2d point_on_circle(const Eigen::Vector2d& center, const Eigen::Vector2d& from, double angle_rad,
                                double radius_m) noexcept {
  return center + radius_m * direction(heading_of(from - center) + angle_rad);
}

double segment_distance(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) noexcept {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((c - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - c).norm();
}

Eigen::Vector2d hip_in_base(const BasePose& base, const Eigen::Vector3d& p_W_hip) noexcept {
  return world_to_base_xz(base.heading_rad, p_W_hip.x() - base.x_m, p_W_hip.z() - base.z_m);
}

bool guard_velocity(const Eigen::Vector2d& base, const Eigen::Vector2d& user, double band_m, double period_s,
                    double omega_radps, Eigen::Vector2d& v_W) noexcept {
  const Eigen::Vector2d rel = base - user;
  const double d = rel.norm();
  if (d < 1e-9) return false;  // no direction to guard; the escape case handles it
  const Eigen::Vector2d out = rel / d;
  const double radial = v_W.dot(out);
  const Eigen::Vector2d tangential = v_W - radial * out;
  const double needed = tangential.norm() * std::tan(std::min(0.5 * std::abs(omega_radps) * period_s, 0.7));
  if (radial >= needed) return false;
  const double d_next = (rel + period_s * v_W).norm();
  if (d >= band_m && d_next >= band_m) return false;
  // Keep the tangential part, set the radial one to the least safe value; never faster.
  const double speed = v_W.norm();
  v_W = tangential + needed * out;
  const double n = v_W.norm();
  if (n > speed && n > 0.0) v_W *= speed / n;
  return true;
}

BaseTwist body_twist(double heading_rad, const Eigen::Vector2d& v_W, double omega_radps,
                     const PlannerSettings& settings) noexcept {
  Eigen::Vector2d v = v_W;
  const double speed = v.norm();
  if (speed > settings.max_linear_speed_mps) v *= settings.max_linear_speed_mps / speed;
  const double omega = std::clamp(omega_radps, -settings.max_angular_speed_radps, settings.max_angular_speed_radps);
  const double mid_heading = heading_rad + 0.5 * omega * settings.command_period_s;
  const Eigen::Vector2d v_B = world_to_base_xz(mid_heading, v.x(), v.y());
  return BaseTwist{v_B.x(), v_B.y(), omega};
}

}  // namespace mhd::planner_geometry
