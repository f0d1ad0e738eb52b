#include "calibration/sample_synthesis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace mhd {

namespace {

/// splitmix64-seeded xoshiro256** with its own uniform and Box-Muller normal, so a seed
/// gives the same samples with any standard library.
class Random {
 public:
  explicit Random(std::uint64_t seed) {
    for (std::uint64_t& s : state_) {
      seed += 0x9E3779B97F4A7C15ULL;
      std::uint64_t z = seed;
      z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
      z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
      s = z ^ (z >> 31U);
    }
  }

  /// Uniform in [0, 1).
  double uniform() { return static_cast<double>(next() >> 11U) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  double normal() {
    const double u1 = 1.0 - uniform();  // (0, 1]
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }
  Eigen::Vector3d normal3() {
    const double a = normal();
    const double b = normal();
    const double c = normal();
    return {a, b, c};
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, unsigned k) { return (x << k) | (x >> (64U - k)); }
  std::uint64_t next() {
    const std::uint64_t result = rotl(state_[1] * 5U, 7U) * 9U;
    const std::uint64_t t = state_[1] << 17U;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotl(state_[3], 45U);
    return result;
  }
  std::array<std::uint64_t, 4> state_{};
};

std::string mm3(const Eigen::Vector3d& v_m) {
  std::array<char, 96> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "(%.2f, %.2f, %.2f) mm", v_m.x() * 1e3, v_m.y() * 1e3, v_m.z() * 1e3);
  return std::string(buffer.data());
}

std::string number(double value, int digits) {
  std::array<char, 64> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.*g", digits, value);
  return std::string(buffer.data());
}

}  // namespace

std::vector<CalibrationSample> synthesize_samples(const Rig& rig, const SynthesisOptions& options) {
  Random random(options.seed);
  const PhantomJointLimits& limits = rig.device().limits;
  std::vector<CalibrationSample> samples;
  samples.reserve(static_cast<std::size_t>(std::max(options.samples, 0)));
  for (int i = 0; i < options.samples; ++i) {
    BasePose base;
    base.x_m = random.uniform(-options.half_range_m, options.half_range_m);
    base.z_m = random.uniform(-options.half_range_m, options.half_range_m);
    base.heading_rad = random.uniform(-std::numbers::pi, std::numbers::pi);
    Eigen::Vector3d q_rad;
    do {
      for (Eigen::Index k = 0; k < 3; ++k) q_rad(k) = random.uniform(limits.lower_rad(k), limits.upper_rad(k));
    } while (!limits.contains(q_rad));

    // A rig with a lift is sampled over its whole range (the lift's reading is exact).
    const double lift_m = rig.lift() ? random.uniform(rig.lift()->min_m, rig.lift()->max_m) : 0.0;

    const Pose X_is900_S_true = rig.X_is900_base_sensor_from_base(base);
    const Eigen::Vector3d p_W_hip = predicted_p_W_hip(rig, options.truth, X_is900_S_true, q_rad, lift_m);

    CalibrationSample sample;
    sample.X_is900_base_sensor = X_is900_S_true;
    sample.X_is900_base_sensor.translation() += options.sensor_noise_m * random.normal3();
    const Eigen::Vector3d tilt_rad = options.sensor_noise_rad * random.normal3();
    if (tilt_rad.norm() > 0.0) {
      sample.X_is900_base_sensor.linear() =
          Eigen::AngleAxisd(tilt_rad.norm(), tilt_rad.normalized()).toRotationMatrix() * X_is900_S_true.linear();
    }
    sample.q_rad = q_rad;
    sample.lift_m = lift_m;
    sample.p_W_hip_measured_m = p_W_hip + options.hip_noise_m * random.normal3();
    samples.push_back(sample);
  }
  return samples;
}

double position_noise_floor_m(const SynthesisOptions& options) noexcept {
  return std::hypot(options.sensor_noise_m, options.hip_noise_m);
}

std::vector<std::string> describe_synthesis(const SynthesisOptions& options) {
  return {
      "synthesized by mhd calibrate --synthesize: " + std::to_string(options.samples) + " samples, seed " +
          std::to_string(options.seed) + ", base x and z within +-" + number(options.half_range_m, 3) + " m",
      "truth SR (p_S_robot) = " + mm3(options.truth.p_S_robot_m),
      "truth RP (p_R_phantom) = " + mm3(options.truth.p_R_phantom_m),
      "truth psi = " + number(options.truth.psi_rad * 180.0 / std::numbers::pi, 5) + " deg",
      "noise sigma per axis: sensor " + number(options.sensor_noise_m * 1e3, 3) + " mm, HIP " +
          number(options.hip_noise_m * 1e3, 3) + " mm, sensor orientation " +
          number(options.sensor_noise_rad * 180.0 / std::numbers::pi, 3) + " deg",
  };
}

}  // namespace mhd
