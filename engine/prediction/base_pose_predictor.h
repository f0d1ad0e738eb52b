#pragma once
// Predicts the mobile base's planar pose at any time, for the 1 kHz haptic loop, from
// tracker poses (~100 Hz, timestamped, late, jittery, sometimes out of order) and the
// commanded base velocity (10 Hz). Without it the HIP in the world leaps by the base's
// motion between samples (2 mm at 0.2 m/s and 100 Hz) each time a sample arrives.
//
// Two stages:
//  1. Estimator, run once per accepted sample: an alpha-beta filter on the pose with the
//     velocity held in the base frame (so a turning base is a constant twist), the twist
//     pulled towards the commanded one while that command is fresh. Between samples the
//     pose follows the twist along its exact arc. Started without a command, the filter
//     begins as a growing least-squares fit (expanding-memory gains) until its gains fall
//     to the steady ones.
//  2. Output, run every tick: the estimator's prediction plus a correction offset. When a
//     new sample changes the estimate, the offset absorbs the difference at the last
//     output, so the output never jumps; the offset then decays with a time constant, at a
//     bounded rate. Only a reset (first sample, a long gap, a jump larger than
//     reset_distance_m) lets the output jump.
//
// Not thread-safe: feed it and query it from one thread (hand the samples over to the
// haptic thread). Nothing allocates.

#include "kinematics/base_pose.h"

#include <cstdint>
#include <string_view>

namespace mhd {

struct BasePosePredictorSettings {
  double nominal_period_s = 0.01;  ///< tracker sample period the gains are tuned for
  /// Alpha-beta gains per accepted sample (position and heading alike): pose correction,
  /// and velocity correction (beta / dt per unit of innovation).
  double position_gain = 0.08;
  double velocity_gain = 0.002;
  double heading_gain = 0.05;
  double yaw_rate_gain = 0.0008;
  /// After a restart without a fresh command (no velocity prior), the gains start at a
  /// least-squares line fit over the samples so far and fall to the values above; the
  /// output follows the estimate directly (it may jump) for this many samples.
  int startup_samples = 10;
  /// Per accepted sample, the estimated twist moves this fraction of the way to the
  /// commanded twist while the command is no older than command_timeout_s.
  double command_weight = 0.05;
  double command_timeout_s = 0.25;
  /// Output correction: offset decays as exp(-t / tau), never faster than these rates.
  double smoothing_time_constant_s = 0.1;
  double max_correction_speed_mps = 0.02;
  double max_correction_rate_radps = 0.03;
  /// The twist a prediction extrapolates with is clamped to what a base can do (twice
  /// the planner's default limits): a start-up fit on a few noisy samples can estimate
  /// metres per second and radians per second, projected a metre out to the HIP.
  double max_speed_mps = 1.0;
  double max_yaw_rate_radps = 1.4;
  /// Predictions run at most this far past the last sample, then the pose is held.
  double max_extrapolation_s = 0.1;
  /// A sample this far from the prediction, or after this long a gap, restarts the estimate.
  double reset_distance_m = 0.25;
  double reset_heading_rad = 0.5;
  double reset_gap_s = 1.0;
  /// Subtracted from every sample's timestamp: latency the tracker's clock does not cover.
  double latency_s = 0.0;
};

enum class BaseSampleStatus {
  Accepted,    ///< folded into the estimate
  Reset,       ///< accepted, and the estimate restarted from it (first sample, gap, jump)
  OutOfOrder,  ///< ignored: not newer than the last accepted sample (stale, duplicate)
  Invalid,     ///< ignored: non-finite values
};

[[nodiscard]] std::string_view to_string(BaseSampleStatus status) noexcept;

class BasePosePredictor {
 public:
  explicit BasePosePredictor(const BasePosePredictorSettings& settings = {}) noexcept;

  /// A tracker sample: the base pose measured at t_s (host clock, seconds).
  BaseSampleStatus add_measurement(double t_s, const BasePose& pose) noexcept;
  /// The commanded twist in the base frame, issued at t_s. Returns false (and ignores it)
  /// when it is older than the latest command or not finite.
  bool add_command(double t_s, const BaseTwist& twist_B) noexcept;

  /// The pose at t_s, for the tick at t_s; call with non-decreasing times. Continuous from
  /// one call to the next except after a reset. Heading wrapped to (-pi, pi]. A zero pose
  /// until the first sample (see has_estimate).
  [[nodiscard]] BasePose predict(double t_s) noexcept;

  [[nodiscard]] bool has_estimate() const noexcept { return has_estimate_; }
  /// Seconds from the last accepted sample's measurement time to t_s (+inf before any).
  [[nodiscard]] double age_s(double t_s) const noexcept;
  /// True when no sample is younger than max_age_s at t_s (always, before the first).
  [[nodiscard]] bool is_stale(double t_s, double max_age_s) const noexcept;
  /// The estimator's current twist, in the base frame.
  [[nodiscard]] BaseTwist estimated_twist() const noexcept { return twist_B_; }
  [[nodiscard]] const BasePosePredictorSettings& settings() const noexcept { return settings_; }

  [[nodiscard]] std::uint64_t accepted_count() const noexcept { return accepted_; }
  [[nodiscard]] std::uint64_t ignored_count() const noexcept { return ignored_; }
  [[nodiscard]] std::uint64_t reset_count() const noexcept { return resets_; }

  /// Forgets every sample and command.
  void reset() noexcept;

 private:
  [[nodiscard]] BasePose model_at(double t_s) const noexcept;
  void restart(double t_s, const BasePose& pose) noexcept;
  [[nodiscard]] bool command_fresh(double t_s) const noexcept;

  BasePosePredictorSettings settings_;

  // Estimator.
  bool has_estimate_ = false;
  double t_estimate_s_ = 0.0;  ///< measurement time of the last accepted sample
  BasePose pose_;              ///< estimate at t_estimate_s_ (heading unwrapped)
  BaseTwist twist_B_;
  bool expanding_ = false;       ///< restarted without a velocity prior: fading gains
  std::uint64_t samples_since_restart_ = 0;
  std::uint64_t generation_ = 0;  ///< bumps whenever the estimate changes

  bool has_command_ = false;
  double t_command_s_ = 0.0;
  BaseTwist command_B_;

  // Output.
  bool has_output_ = false;
  std::uint64_t output_generation_ = 0;
  bool rebase_output_ = false;  ///< after a reset: start the output afresh
  double t_output_s_ = 0.0;
  BasePose output_;  ///< last output (heading unwrapped)
  double offset_x_m_ = 0.0, offset_z_m_ = 0.0, offset_heading_rad_ = 0.0;

  std::uint64_t accepted_ = 0, ignored_ = 0, resets_ = 0;
};

}  // namespace mhd
