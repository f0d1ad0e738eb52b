// The planner thread: the base planner at the base rate, on the newest HIP, base pose,
// the user's motion (UserMotionEstimate) and the other rigs on the floor; and, on a rig
// with a lift, the lift's planner (LiftPlanner), which keeps the middle of the arm's reach
// at the hand's height.
#include "haptic_server/server_impl.h"

#include "haptic_server/floor_tracker.h"
#include "haptic_server/user_motion_estimate.h"
#include "realtime/periodic_timer.h"
#include "realtime/thread_name.h"

#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace mhd {

void HapticServer::Impl::planner_thread() {
  realtime::name_current_thread("mhd-planner");
  realtime::PeriodicTimer timer(1.0 / settings.base_rate_hz);
  UserMotionEstimate user_motion;
  // The newest the io thread gave (kept when nothing new came); until then every declared
  // rig is unseen, which holds the base.
  FloorView floor = FloorTracker(settings.other_rigs).view();
  const std::optional<LiftPlanner> lift_planner =
      rig.lift() ? std::optional<LiftPlanner>(std::in_place, *rig.lift(), reach_centre_above_phantom_m(rig))
                 : std::nullopt;
  while (!stop.load(std::memory_order_relaxed)) {
    (void)timer.wait_next();
    const HapticSnapshot snap = snapshot_for_planner.latest();
    status_counters.base.set(snap.base);
    const HeadState h = head.get();
    user_motion.update(h);
    if (lift_planner) planned_lift_vmps.store(plan_lift(*lift_planner, snap, host.now_s() - snap.t_s));
    if (!options.plan_base) continue;  // no planner: the base holds still (zero twist)
    BasePlanInput in;
    in.t_s = host.now_s();
    in.base = snap.base;
    in.hip_valid = snap.valid;
    in.p_W_hip = snap.p_W_hip;
    in.user_known = h.known;
    in.user_xz_W_m = Eigen::Vector2d(h.p_W_m.x(), h.p_W_m.z());
    in.user_heading_rad = user_motion.heading_rad();
    in.user_velocity_W_mps = user_motion.velocity_W_mps();
    in.max_input_age_s = settings.base_guard.tracker_timeout_s;
    in.hip_age_s = in.t_s - snap.t_s;
    in.base_age_s = in.t_s - base_sample_newest_t_s.load(std::memory_order_relaxed);
    if (h.known) in.head_age_s = in.t_s - h.t_s;
    if (FloorView newest; floor_view.read(newest)) floor = newest;
    in.floor = floor;
    in.floor_timeout_s = settings.other_rigs_timeout_s;
    const BaseTwist twist = options.plan_base(in);
    planned_command.write(twist);
  }
}

double HapticServer::Impl::plan_lift(const LiftPlanner& planner, const HapticSnapshot& snap, double hip_age_s) const {
  const std::array<double, 3> reading = lift_reading.read();
  const LiftState now{reading[0], reading[1]};
  if (!std::isfinite(now.height_m) || !std::isfinite(now.velocity_mps)) return 0.0;  // no lift reading yet
  // No hand, or a stale one: the target is no number, and the lift brakes to a stop.
  double target_m = std::numeric_limits<double>::quiet_NaN();
  if (snap.valid && hip_age_s <= settings.base_guard.tracker_timeout_s) {
    const double phantom_y_W_m = rig.X_W_phantom(rig.X_W_robot_from_base(snap.base)).translation().y();
    target_m = planner.target_for_hand(snap.p_W_hip.y(), phantom_y_W_m);
  }
  // The speed the lift should have one base period from now: commanded now, it is what
  // the lift's own controller accelerates to within the period.
  return planner.step(now, target_m, 1.0 / settings.base_rate_hz).velocity_mps;
}

}  // namespace mhd
