#include "safety/force_safety.h"

#include <algorithm>
#include <cmath>

namespace mhd {

ForceSafety::ForceSafety(const ForceSafetySettings& settings) noexcept : settings_(settings) {}

void ForceSafety::reset() noexcept {
  recovery_ = 0.0;
  stale_gain_ = 1.0;
  has_hip_ = false;
  last_output_N_ = 0.0;
}

ForceSafetyOutput ForceSafety::apply(const ForceSafetyInput& in) noexcept {
  ForceSafetyOutput out;
  const double dt_s = std::isfinite(in.dt_s) && in.dt_s > 0.0 ? in.dt_s : 0.0;

  out.fault = !in.force_W_N.allFinite() || !in.p_W_hip.allFinite() || std::isnan(in.tracker_age_s);
  out.stale = !(in.tracker_age_s < settings_.tracker_timeout_s);
  if (out.fault || out.stale) {
    recovery_ = 0.0;
    stale_gain_ = 1.0;  // from zero, the fade-in ramp brings the force back
    if (out.fault) ++counters_.fault_ticks;
    if (out.stale) ++counters_.stale_ticks;
    if (in.p_W_hip.allFinite()) {
      last_p_W_hip_ = in.p_W_hip;
      has_hip_ = true;
    }
    last_output_N_ = 0.0;
    return out;  // zero force
  }

  recovery_ = settings_.fade_in_s > 0.0 ? std::min(1.0, recovery_ + dt_s / settings_.fade_in_s) : 1.0;
  double gain = recovery_;

  // Stale fade: 1 until timeout - fade, 0 at the timeout. A late sample brings the
  // pose back at once, but the gain rises only as fast as it fell: a tracker arriving
  // 20 +- 20 ms late would otherwise step the force by up to its full size in one tick.
  if (settings_.tracker_fade_s > 0.0) {
    const double target =
        std::clamp((settings_.tracker_timeout_s - in.tracker_age_s) / settings_.tracker_fade_s, 0.0, 1.0);
    stale_gain_ = target <= stale_gain_ ? target : std::min(target, stale_gain_ + dt_s / settings_.tracker_fade_s);
    gain *= stale_gain_;
  }

  Eigen::Vector3d force = in.force_W_N;
  double magnitude = force.norm();
  if (magnitude > settings_.max_force_N) {
    force *= settings_.max_force_N / magnitude;
    magnitude = settings_.max_force_N;
    out.clamped = true;
    ++counters_.clamped_ticks;
  }

  // The threshold is per millisecond: a late tick (dt > 1 ms) lets the hand move further.
  const double jump_threshold_m = settings_.hip_jump_m * std::max(1.0, dt_s / 0.001);
  out.jump = has_hip_ && (in.p_W_hip - last_p_W_hip_).norm() > jump_threshold_m;
  if (out.jump) {
    ++counters_.jumps;
    // Keep the previous tick's force magnitude; the ramp brings the rest back.
    if (magnitude * gain > last_output_N_ && magnitude > 0.0) {
      const double keep = last_output_N_ / magnitude;
      recovery_ = std::min(recovery_, keep);
      gain = std::min(gain, keep);
    }
  }
  last_p_W_hip_ = in.p_W_hip;
  has_hip_ = true;

  out.gain = gain;
  out.force_W_N = gain * force;
  last_output_N_ = out.force_W_N.norm();
  return out;
}

}  // namespace mhd
