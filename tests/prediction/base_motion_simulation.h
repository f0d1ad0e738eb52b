#pragma once
// A base driving at a constant twist, sampled by a simulated IS-900 (100 Hz, noisy, late,
// jittery, sometimes out of order or lost) and commanded at 10 Hz, replayed through a
// 1 kHz haptic loop. Measures the per-tick leap of the predicted pose against the truth.

#include "kinematics/base_pose.h"
#include "prediction/base_pose_predictor.h"

#include <cstdint>
#include <string>

namespace mhd::test {

struct BaseMotionScenario {
  BaseTwist twist_B{0.2, 0.0, 0.0};   ///< true (and commanded) twist
  BasePose start{0.3, -0.2, 0.4};
  double duration_s = 10.0;
  double warmup_s = 1.0;              ///< not scored: the estimator converging
  double sample_period_s = 0.01;
  double position_noise_m = 0.0025;   ///< standard deviation per axis
  double heading_noise_rad = 0.4 * 3.14159265358979323846 / 180.0;
  double latency_s = 0.004;           ///< measurement to arrival
  double arrival_jitter_s = 0.002;    ///< uniform extra delay
  double late_probability = 0.03;     ///< delayed past the next sample (arrives out of order)
  double drop_probability = 0.01;
  bool send_commands = true;
  double tick_s = 0.001;
  double lever_m = 0.5;               ///< the scored point ahead of the base centre (the HIP)
  std::uint64_t seed = 1;
};

struct LeapFigures {
  double max_leap_m = 0;      ///< max over ticks of |(o_i - o_i-1) - (truth_i - truth_i-1)|
  double rms_leap_m = 0;
  double max_error_m = 0;     ///< max |o_i - truth_i|
  double rms_error_m = 0;
};

struct BaseMotionResult {
  LeapFigures predicted_base, predicted_point;
  LeapFigures held_base, held_point;  ///< sample and hold: the newest sample, as is
  std::uint64_t samples_sent = 0, samples_ignored = 0, resets = 0;
  [[nodiscard]] std::string summary() const;
};

/// True pose at t for the scenario.
[[nodiscard]] BasePose true_base_pose(const BaseMotionScenario& scenario, double t_s);

[[nodiscard]] BaseMotionResult run_base_motion(const BaseMotionScenario& scenario,
                                               const BasePosePredictorSettings& settings = {});

}  // namespace mhd::test
