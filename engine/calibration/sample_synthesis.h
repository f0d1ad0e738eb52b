#pragma once
// Synthetic calibration samples like the thesis's (ch. 4.4.2): random base positions
// within +-1 m, random headings, random joint angles (within the device's limits, where
// the thesis drew 0-360 degrees), a rig with known offsets and psi, and tracker noise.
// Deterministic for a seed (own generator and distributions, not the standard library's).

#include "calibration/calibration_sample.h"
#include "calibration/rig_calibration.h"
#include "kinematics/rig.h"

#include <cstdint>
#include <string>
#include <vector>

namespace mhd {

struct SynthesisOptions {
  int samples = 100;
  std::uint64_t seed = 1;
  double half_range_m = 1.0;                        ///< base x and z uniform in [-h, h]
  RigOffsets truth = thesis_calibrated_offsets();   ///< the rig the samples come from
  double sensor_noise_m = 0.002;  ///< sigma per axis on the base station's tracked position
  double hip_noise_m = 0.002;     ///< sigma per axis on the HIP marker's tracked position
  double sensor_noise_rad = 0.0;  ///< sigma per axis of a small rotation on the station's orientation
};

/// The samples; the sensor poses follow the rig's planar base path (the station's height
/// stays what the rig's nominal pose says), the HIP comes from `truth` plus noise. On a
/// rig with a lift each sample's lift height is drawn over the lift's range.
[[nodiscard]] std::vector<CalibrationSample> synthesize_samples(const Rig& rig, const SynthesisOptions& options);

/// The per-axis residual RMS that perfect offsets leave with position noise only:
/// sqrt(sensor_noise^2 + hip_noise^2).
[[nodiscard]] double position_noise_floor_m(const SynthesisOptions& options) noexcept;

/// Comment lines recording the truth and the noise (for the CSV's header).
[[nodiscard]] std::vector<std::string> describe_synthesis(const SynthesisOptions& options);

}  // namespace mhd
