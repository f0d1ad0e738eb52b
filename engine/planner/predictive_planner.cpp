#include "planner/predictive_planner.h"

#include "planner/keep_outs.h"
#include "planner/planner_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace mhd {

namespace g = planner_geometry;

namespace {

// B (x, z) -> world (x, z) rotation at a heading (the inverse of world_to_base_xz).
Eigen::Vector2d base_to_world_xz(double heading_rad, const Eigen::Vector2d& v_B) noexcept {
  const double c = std::cos(heading_rad);
  const double s = std::sin(heading_rad);
  return Eigen::Vector2d(c * v_B.x() + s * v_B.y(), -s * v_B.x() + c * v_B.y());
}

}  // namespace

PlannerOutput PredictivePlanner::plan(const PlannerInput& in) noexcept {
  const PlannerSettings& s = settings_;
  auto [out, base, hand] = planar_start(in, s);

  const double d_target = s.target_distance_m();
  const double r_collision = s.collision_radius_m();
  const double band = r_collision + s.safety_margin_m;

  // Extrapolated user; the shift is capped so the thesis target stays outside the band.
  Eigen::Vector2d shift = s.prediction_horizon_s * in.user_velocity_W;
  const double max_shift = d_target - band;
  if (shift.norm() > max_shift) shift *= max_shift / shift.norm();
  const Eigen::Vector2d user_p = in.user_W + shift;
  const Eigen::Vector2d hand_p = hand + shift;
  const Eigen::Vector2d hip_p_B = world_to_base_xz(in.base.heading_rad, hand_p.x() - base.x(), hand_p.y() - base.y());

  const Eigen::Vector2d rel = base - in.user_W;
  const double d = rel.norm();
  out.target_W = g::follow_target(user_p, hand_p, in.user_heading_rad, d_target);
  out.goal_heading_rad = in.base.heading_rad;
  out.goal_W = base;

  if (!active_ && (!out.hip_in_usable || !s.usable_B.contains(hip_p_B.x(), hip_p_B.y()) || d < band ||
                   (base - user_p).norm() < band))
    active_ = true;
  if (!active_) return out;

  PlanarBox box = s.usable_B;
  box.x_min_m += s.catch_margin_m;
  box.x_max_m -= s.catch_margin_m;
  box.z_min_m += s.catch_margin_m;
  box.z_max_m -= s.catch_margin_m;

  bool deadbeat = false;
  if (d < r_collision) {
    out.status = PlannerCase::Escape;
    const Eigen::Vector2d away =
        d > 1e-9 ? Eigen::Vector2d(rel / d) : -g::direction(in.base.heading_rad + s.facing_angle_rad);
    out.goal_W = in.user_W + d_target * away;
    out.goal_heading_rad = g::facing_heading(out.goal_W, user_p, s.facing_angle_rad);
  } else if (box.contains(hip_p_B.x(), hip_p_B.y()) && d >= band) {
    out.status = PlannerCase::Stopping;  // caught: the HIP is well inside
  } else {
    // A chord is clear when it keeps the band from the user (or, inside the band, does not
    // come closer than the base already is).
    const double clear_m = std::min(band, d) - 1e-9;
    const auto clear = [&](const Eigen::Vector2d& p) {
      return g::segment_distance(base, p, in.user_W) >= clear_m && chord_clears(in.keep_outs, base, p, s);
    };

    // Catch goal: the soonest pose with the HIP in the box. A goal whose chord is not clear
    // is timed along the way round the band (tangent, arc, tangent).
    const double facing = g::facing_heading(out.target_W, user_p, s.facing_angle_rad);
    const double span = std::min(0.5 * std::numbers::pi, s.max_angular_speed_radps * 1.0);
    const double r_way = band + 0.02;
    const auto path_length = [&](const Eigen::Vector2d& goal) {
      const double dg = (goal - in.user_W).norm();
      const double db = std::max(d, r_way);
      const double theta = std::abs(g::signed_angle(rel, goal - in.user_W));
      const double arc = theta - std::acos(std::min(1.0, r_way / db)) - std::acos(std::min(1.0, r_way / dg));
      return std::sqrt(db * db - r_way * r_way) + std::sqrt(std::max(0.0, dg * dg - r_way * r_way)) +
             r_way * std::max(0.0, arc);
    };
    constexpr int kHalf = 12;
    double best_cost = std::numeric_limits<double>::infinity();
    Eigen::Vector2d best_goal = base;
    double best_heading = in.base.heading_rad;
    bool best_clear = false;
    for (int k = -kHalf; k <= kHalf + 1; ++k) {
      const double h = k <= kHalf ? in.base.heading_rad + span * k / kHalf : facing;
      const Eigen::Vector2d q = world_to_base_xz(h, hand_p.x() - base.x(), hand_p.y() - base.y());
      const Eigen::Vector2d p(std::clamp(q.x(), box.x_min_m, box.x_max_m), std::clamp(q.y(), box.z_min_m, box.z_max_m));
      const Eigen::Vector2d goal = hand_p - base_to_world_xz(h, p);
      if ((goal - in.user_W).norm() < band + 0.01 || (goal - user_p).norm() < band + 0.01 ||
          !outside_bands(in.keep_outs, goal, 0.01, s))
        continue;
      const bool is_clear = clear(goal);
      const double length = is_clear ? (goal - base).norm() : path_length(goal);
      const double turn = std::abs(wrap_angle(h - in.base.heading_rad));
      const double cost = std::max(length / s.max_linear_speed_mps, turn / s.max_angular_speed_radps) +
                          0.02 * std::abs(wrap_angle(h - facing)) / std::numbers::pi;
      if (cost < best_cost) {
        best_cost = cost;
        best_goal = goal;
        best_heading = h;
        best_clear = is_clear;
      }
    }
    if (std::isfinite(best_cost) && best_clear) {
      out.status = PlannerCase::Straight;
      out.goal_W = best_goal;
      out.goal_heading_rad = wrap_angle(best_heading);
      deadbeat = true;
    } else {
      // Round the user towards the best goal (or the thesis target): the largest clear step
      // on a circle between the band and d', at least pi' when that is clear.
      const Eigen::Vector2d toward = std::isfinite(best_cost) ? best_goal : out.target_W;
      out.status = PlannerCase::SubTarget;
      const double radius = std::clamp(d, r_way, d_target);
      const double angle = g::signed_angle(rel, toward - in.user_W);
      const double sign = angle < 0.0 ? -1.0 : 1.0;
      const double total = std::abs(angle);
      double lo = 0.0;
      double hi = total;
      if (clear(g::point_on_circle(in.user_W, base, sign * std::min(s.step_angle_rad, total), radius))) {
        lo = std::min(s.step_angle_rad, total);
      }
      for (int i = 0; i < 16; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (clear(g::point_on_circle(in.user_W, base, sign * mid, radius)))
          lo = mid;
        else
          hi = mid;
      }
      out.goal_W = g::point_on_circle(in.user_W, base, sign * lo, radius);
      out.goal_heading_rad = std::isfinite(best_cost) ? wrap_angle(best_heading)
                                                      : g::facing_heading(out.goal_W, user_p, s.facing_angle_rad);
    }
  }

  Eigen::Vector2d v_W = Eigen::Vector2d::Zero();
  double omega = 0.0;
  if (out.status == PlannerCase::Stopping) {
    active_ = false;
  } else {
    const Eigen::Vector2d to_goal = out.goal_W - base;
    const double dist = to_goal.norm();
    if (dist > 1e-12) {
      const double speed =
          deadbeat ? std::min(s.max_linear_speed_mps, dist / s.command_period_s) : s.max_linear_speed_mps;
      v_W = speed / dist * to_goal;
    }
    const double heading_error = wrap_angle(out.goal_heading_rad - in.base.heading_rad);
    omega = std::clamp(heading_error / s.command_period_s, -s.max_angular_speed_radps, s.max_angular_speed_radps);
  }

  out.guard_active = guard_keep_outs(in.base, in.user_W, band, in.keep_outs, s, omega, v_W);
  out.twist_B = g::body_twist(in.base.heading_rad, v_W, omega, s);
  return out;
}

}  // namespace mhd
