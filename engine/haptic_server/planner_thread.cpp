// The planner thread: the base planner at the base rate, on the newest HIP, base pose
// and the user's motion (UserMotionEstimate).
#include "haptic_server/server_impl.h"

#include "haptic_server/user_motion_estimate.h"
#include "realtime/periodic_timer.h"
#include "realtime/thread_name.h"

namespace mhd {

void HapticServer::Impl::planner_thread() {
  realtime::name_current_thread("mhd-planner");
  realtime::PeriodicTimer timer(1.0 / settings.base_rate_hz);
  UserMotionEstimate user_motion;
  while (!stop.load(std::memory_order_relaxed)) {
    (void)timer.wait_next();
    const HapticSnapshot snap = snapshot_for_planner.latest();
    status_counters.base.set(snap.base);
    const HeadState h = head.get();
    user_motion.update(h);
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
    const BaseTwist twist = options.plan_base(in);
    planned_command.write(twist);
  }
}

}  // namespace mhd
