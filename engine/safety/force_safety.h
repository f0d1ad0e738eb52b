#pragma once
// The last stage before a force reaches a device, for every backend: the force is made
// finite and clamped to the device's limit, and scaled by a gain in [0, 1] that
//  * fades out as the newest base pose ages: 1 while it is younger than
//    tracker_timeout_s - tracker_fade_s, falling linearly to exactly 0 at
//    tracker_timeout_s (stale tracking: the HIP in the world is no longer known); when a
//    late sample makes the pose young again, this factor rises back no faster than it
//    fell (1 / tracker_fade_s per second), so late tracking never steps the force up;
//  * drops to 0 on a fault (non-finite force or HIP, no base pose yet) and, once the fault
//    clears, rises back to 1 over fade_in_s (never a step);
//  * on a HIP jump (the HIP moved more than hip_jump_m per millisecond of the tick, e.g. a tracker glitch
//    or a pose reset), is lowered so that the output force keeps the magnitude it had
//    the tick before, then rises back over fade_in_s: the jump's force step is faded in,
//    not cut (a cut would itself be a jolt) and not passed on.
// Pure and allocation-free; one instance per haptic loop.

#include <Eigen/Core>

#include <cstdint>

namespace mhd {

struct ForceSafetySettings {
  double max_force_N = 8.5;        ///< the device's limit (the smaller of scene and device)
  double tracker_timeout_s = 0.05;  ///< force is zero when the newest base pose is this old
  double tracker_fade_s = 0.02;     ///< the fade before the timeout
  double hip_jump_m = 0.01;         ///< per millisecond (10 m/s), far above a hand's speed
  double fade_in_s = 0.5;           ///< from zero gain back to full force
};

struct ForceSafetyInput {
  double dt_s = 0.001;
  Eigen::Vector3d force_W_N = Eigen::Vector3d::Zero();  ///< from the proxy
  Eigen::Vector3d p_W_hip = Eigen::Vector3d::Zero();
  double tracker_age_s = 0.0;  ///< age of the newest base pose (+inf: none yet)
};

struct ForceSafetyOutput {
  Eigen::Vector3d force_W_N = Eigen::Vector3d::Zero();  ///< finite, |f| <= max_force_N
  double gain = 0.0;
  bool stale = false;    ///< tracking at or past its timeout
  bool fault = false;    ///< non-finite input this tick
  bool jump = false;     ///< HIP jump this tick
  bool clamped = false;  ///< the limit cut the force
};

struct ForceSafetyCounters {
  std::uint64_t stale_ticks = 0;
  std::uint64_t fault_ticks = 0;
  std::uint64_t jumps = 0;
  std::uint64_t clamped_ticks = 0;
};

class ForceSafety {
 public:
  explicit ForceSafety(const ForceSafetySettings& settings = {}) noexcept;

  ForceSafetyOutput apply(const ForceSafetyInput& in) noexcept;
  /// Back to zero gain (e.g. after a restart): force fades in again.
  void reset() noexcept;

  [[nodiscard]] const ForceSafetySettings& settings() const noexcept { return settings_; }
  [[nodiscard]] const ForceSafetyCounters& counters() const noexcept { return counters_; }

 private:
  ForceSafetySettings settings_;
  ForceSafetyCounters counters_;
  double recovery_ = 0.0;  ///< the fade-in ramp, 0..1
  double stale_gain_ = 1.0;  ///< the stale fade's factor, rising no faster than it falls
  bool has_hip_ = false;
  Eigen::Vector3d last_p_W_hip_ = Eigen::Vector3d::Zero();
  double last_output_N_ = 0.0;
};

}  // namespace mhd
