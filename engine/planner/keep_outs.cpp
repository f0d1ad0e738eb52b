#include "planner/keep_outs.h"

#include "planner/planner_geometry.h"

#include <algorithm>
#include <cmath>

namespace mhd {

namespace g = planner_geometry;

/// A base inside a keep-out's band backs out at (band - distance) / (this many periods).
constexpr double kPushOutPeriods = 4.0;

double contact_distance_m(const KeepOut& keep_out, const PlannerSettings& settings) noexcept {
  return settings.robot_radius_m + keep_out.radius_m;
}

bool outside_bands(const KeepOuts& keep_outs, const Eigen::Vector2d& p, double extra_m,
                   const PlannerSettings& settings) noexcept {
  for (const KeepOut& k : keep_outs)
    if ((p - k.centre_W).norm() < contact_distance_m(k, settings) + settings.safety_margin_m + extra_m) return false;
  return true;
}

bool chord_clears(const KeepOuts& keep_outs, const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                  const PlannerSettings& settings) noexcept {
  for (const KeepOut& k : keep_outs) {
    const double band = contact_distance_m(k, settings) + settings.safety_margin_m;
    const double clear_m = std::min(band, (from - k.centre_W).norm()) - 1e-9;
    if (g::segment_distance(from, to, k.centre_W) < clear_m) return false;
  }
  return true;
}

namespace {

/// The least distance from `q` to the path a constant body twist drives over `period_s`:
/// a circular arc (a segment when it does not turn), found exactly. The arc's circle is
/// the one through its start, middle and end; q's nearest point on that circle is on the
/// arc when q's direction from the centre lies within the arc's sweep, otherwise the
/// nearer end is.
double arc_distance(const BasePose& base, const BaseTwist& twist_B, double period_s, const Eigen::Vector2d& q) noexcept {
  const Eigen::Vector2d a(base.x_m, base.z_m);
  const BasePose mid = integrate_twist(base, twist_B, 0.5 * period_s);
  const BasePose end = integrate_twist(base, twist_B, period_s);
  const Eigen::Vector2d m(mid.x_m, mid.z_m);
  const Eigen::Vector2d b(end.x_m, end.z_m);
  const double ends = std::min((q - a).norm(), (q - b).norm());
  // Circumcentre of a, m, b; nearly straight arcs (and standing still) are segments.
  const Eigen::Vector2d ab = m - a;
  const Eigen::Vector2d ac = b - a;
  const double det = 2.0 * (ab.x() * ac.y() - ab.y() * ac.x());
  if (std::abs(twist_B.omega_radps * period_s) < 1e-9 || std::abs(det) < 1e-18)
    return g::segment_distance(a, b, q);
  const Eigen::Vector2d c_rel(
      (ac.y() * ab.squaredNorm() - ab.y() * ac.squaredNorm()) / det,
      (ab.x() * ac.squaredNorm() - ac.x() * ab.squaredNorm()) / det);
  const Eigen::Vector2d centre = a + c_rel;
  const double radius = c_rel.norm();
  const auto angle = [&](const Eigen::Vector2d& p) { return std::atan2(p.y() - centre.y(), p.x() - centre.x()); };
  const double a0 = angle(a);
  const double sweep_mid = wrap_angle(angle(m) - a0);
  const double sign = sweep_mid < 0.0 ? -1.0 : 1.0;
  const double sweep = sign * wrap_angle(angle(b) - a0);
  const double at_q = sign * wrap_angle(angle(q) - a0);
  if (at_q >= 0.0 && at_q <= sweep) return std::min(ends, std::abs((q - centre).norm() - radius));
  return ends;
}

/// Whether that arc comes nearer `centre` than `contact_m` (or, starting nearer, nearer
/// than it starts).
bool arc_enters(const BasePose& base, const BaseTwist& twist_B, double period_s, const Eigen::Vector2d& centre,
                double contact_m) noexcept {
  const double d_start = (Eigen::Vector2d(base.x_m, base.z_m) - centre).norm();
  return arc_distance(base, twist_B, period_s, centre) < std::min(contact_m, d_start - 1e-12);
}

}  // namespace

bool guard_keep_outs(const BasePose& base, const Eigen::Vector2d& user, double own_band_m, const KeepOuts& keep_outs,
                     const PlannerSettings& settings, double omega_radps, Eigen::Vector2d& v_W) noexcept {
  const Eigen::Vector2d p(base.x_m, base.z_m);
  const double period = settings.command_period_s;
  bool changed = g::guard_velocity(p, user, own_band_m, period, omega_radps, v_W);
  if (keep_outs.empty()) return changed;
  for (const KeepOut& k : keep_outs) {
    const double band = contact_distance_m(k, settings) + settings.safety_margin_m;
    changed = g::guard_velocity(p, k.centre_W, band, period, omega_radps, v_W) || changed;
  }
  // Inside a keep-out's band the base also backs out, faster the deeper it is: a keep-out
  // is seen late and moves, and without this two bases that met at the band would stay
  // there, where any error in what each sees of the other is a contact.
  for (const KeepOut& k : keep_outs) {
    const Eigen::Vector2d rel = p - k.centre_W;
    const double d = rel.norm();
    const double band = contact_distance_m(k, settings) + settings.safety_margin_m;
    if (d >= band || d < 1e-9) continue;
    const Eigen::Vector2d out = rel / d;
    const double push = std::min(settings.max_linear_speed_mps, (band - d) / (kPushOutPeriods * period));
    const double radial = v_W.dot(out);
    if (radial < push) {
      v_W += (push - radial) * out;
      changed = true;
    }
  }
  if (v_W.norm() > settings.max_linear_speed_mps) v_W *= settings.max_linear_speed_mps / v_W.norm();
  const BaseTwist twist = g::body_twist(base.heading_rad, v_W, omega_radps, settings);
  bool enters = arc_enters(base, twist, period, user, settings.collision_radius_m());
  for (const KeepOut& k : keep_outs)
    enters = enters || arc_enters(base, twist, period, k.centre_W, contact_distance_m(k, settings));
  if (enters && !v_W.isZero()) {
    v_W.setZero();
    changed = true;
  }
  return changed;
}

}  // namespace mhd
