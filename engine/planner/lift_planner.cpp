#include "planner/lift_planner.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mhd {

double LiftPlanner::target_for_hand(double hand_y_W_m, double phantom_y_W_m) const noexcept {
  if (!std::isfinite(hand_y_W_m) || !std::isfinite(phantom_y_W_m)) return std::nan("");
  return std::clamp(hand_y_W_m - phantom_y_W_m - reach_centre_above_phantom_m_, lift_.min_m, lift_.max_m);
}

LiftState LiftPlanner::step(const LiftState& now, double target_height_m, double dt_s) const noexcept {
  if (!(dt_s > 0.0) || !std::isfinite(dt_s)) return now;
  const double a_max = lift_.max_acceleration_mps2;
  const double v_max = lift_.max_speed_mps;
  double v_wanted = 0.0;  // a target that is no number: stop
  if (std::isfinite(target_height_m)) {
    const double error_m = std::clamp(target_height_m, lift_.min_m, lift_.max_m) - now.height_m;
    // The fastest speed from which braking at a_max, starting one step from now, still
    // stops on the target: v dt + v^2 / (2 a) = |e|.
    const double d = std::abs(error_m);
    const double v_stop = a_max * (std::sqrt(dt_s * dt_s + 2.0 * d / a_max) - dt_s);
    v_wanted = std::copysign(std::min({v_max, v_stop, d / dt_s}), error_m);
  }
  const double dv_max = a_max * dt_s;
  LiftState next;
  next.velocity_mps = now.velocity_mps + std::clamp(v_wanted - now.velocity_mps, -dv_max, dv_max);
  next.height_m = now.height_m + next.velocity_mps * dt_s;
  // The range is hard: a lift that reaches an end stops there.
  if (next.height_m <= lift_.min_m || next.height_m >= lift_.max_m) {
    next.height_m = std::clamp(next.height_m, lift_.min_m, lift_.max_m);
    next.velocity_mps = 0.0;
  }
  return next;
}

double reach_centre_above_phantom_m(const Rig& rig) noexcept {
  const Pose X_B_P = rig.X_robot_base().inverse(Eigen::Isometry) * rig.X_robot_phantom();
  const WorkspaceBox box = rig.device().usable_workspace();
  double y_min = std::numeric_limits<double>::infinity();
  double y_max = -std::numeric_limits<double>::infinity();
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p_P((corner & 1) ? box.max_P_m.x() : box.min_P_m.x(),
                              (corner & 2) ? box.max_P_m.y() : box.min_P_m.y(),
                              (corner & 4) ? box.max_P_m.z() : box.min_P_m.z());
    const double y_B = (X_B_P * p_P).y();
    y_min = std::min(y_min, y_B);
    y_max = std::max(y_max, y_B);
  }
  return 0.5 * (y_min + y_max) - X_B_P.translation().y();
}

}  // namespace mhd
