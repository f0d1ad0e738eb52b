#include "planner/seed_planner.h"

#include "planner/keep_outs.h"
#include "planner/planner_geometry.h"

#include <algorithm>
#include <cmath>

namespace mhd {

namespace g = planner_geometry;

PlannerOutput SeedPlanner::plan(const PlannerInput& in) noexcept {
  const PlannerSettings& s = settings_;
  auto [out, base, hand] = planar_start(in, s);

  const Eigen::Vector2d rel = base - in.user_W;
  const double d = rel.norm();
  const double d_target = s.target_distance_m();
  const double r_collision = s.collision_radius_m();
  out.target_W = g::follow_target(in.user_W, hand, in.user_heading_rad, d_target);
  out.goal_heading_rad = g::facing_heading(base, in.user_W, s.facing_angle_rad);
  out.goal_W = base;

  // Ch. 3.8: plan only once the HIP leaves the usable workspace (and, MHD's addition, when
  // the base is within the safety band of the user).
  if (!active_ && (!out.hip_in_usable || d < r_collision + s.safety_margin_m)) active_ = true;
  if (!active_) return out;

  // Table 3.1.
  if (d < r_collision) {
    out.status = PlannerCase::Escape;  // pi' = 0: straight out along the user -> base ray
    const Eigen::Vector2d away =
        d > 1e-9 ? Eigen::Vector2d(rel / d) : -g::direction(in.base.heading_rad + s.facing_angle_rad);
    out.goal_W = in.user_W + d_target * away;
  } else {
    const double angle = g::signed_angle(rel, out.target_W - in.user_W);
    if (std::abs(angle) < s.step_angle_rad) {
      out.status = PlannerCase::Straight;
      out.goal_W = out.target_W;
    } else {
      out.status = PlannerCase::SubTarget;
      out.goal_W = g::point_on_circle(in.user_W, base, std::copysign(s.step_angle_rad, angle), d_target);
    }
  }

  // Ch. 3.8: speed in proportion to the distance, capped; deceleration and stop intervals.
  const Eigen::Vector2d to_goal = out.goal_W - base;
  const double dist = to_goal.norm();
  Eigen::Vector2d v_W = Eigen::Vector2d::Zero();
  if (out.status == PlannerCase::Straight && dist < s.stop_interval_m) {
    out.status = PlannerCase::Stopping;
  } else if (dist > 1e-12) {
    const double speed = out.status == PlannerCase::Escape
                             ? s.max_linear_speed_mps
                             : s.max_linear_speed_mps * std::min(1.0, dist / s.deceleration_interval_m);
    v_W = speed / dist * to_goal;
  }

  const double heading_error = wrap_angle(out.goal_heading_rad - in.base.heading_rad);
  double omega = 0.0;
  if (std::abs(heading_error) >= s.stop_angle_rad)
    omega = std::copysign(
        s.max_angular_speed_radps * std::min(1.0, std::abs(heading_error) / s.angular_deceleration_interval_rad),
        heading_error);

  if (out.status == PlannerCase::Stopping && omega == 0.0) active_ = false;  // arrived

  out.guard_active =
      guard_keep_outs(in.base, in.user_W, r_collision + s.safety_margin_m, in.keep_outs, s, omega, v_W);
  out.twist_B = g::body_twist(in.base.heading_rad, v_W, omega, s);
  return out;
}

}  // namespace mhd
