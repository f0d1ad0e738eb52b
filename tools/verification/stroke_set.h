#pragma once
// HIP trajectories for tests and benchmarks. make_anchor_strokes() is the benchmark
// stroke protocol (docs/benchmarks.md, "The stroke protocol": approach from 20 mm
// outside to 5 mm inside along the surface normal, slide 50 mm 5 mm deep, retract);
// make_fast_strokes() is a stress variant: straight pokes through the surface at random
// speeds and grazing angles.
// Both are deterministic for a seed (std::mt19937_64 and our own number mapping, so
// the same on every platform) and start every stroke in free space.

#include "verification/surface_crossing_oracle.h"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

namespace mhd::verify {

/// A point on the surface with the unit face normal (CCW winding) of its triangle.
struct SurfaceSample {
  TriangleRef where;
  std::size_t oracle_triangle = 0;  ///< index in the oracle's triangle list
  Eigen::Vector3d point_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal_W = Eigen::Vector3d::UnitZ();
};

struct Stroke {
  /// One HIP position per tick: consecutive samples are speed / rate apart along the
  /// corner polyline (closer only where a step cuts a corner, and at the very end).
  std::vector<Eigen::Vector3d> p_W_hip;
  /// The polyline the samples follow. Anchor: start, bottom of the approach, end of
  /// the slide, retracted end. Fast: start, deepest point[, start again].
  std::vector<Eigen::Vector3d> corners_W;
  SurfaceSample anchor;  ///< where the stroke enters the surface
  /// Unit slide direction (anchor strokes, tangent to the surface) or travel
  /// direction (fast strokes).
  Eigen::Vector3d direction_W = Eigen::Vector3d::Zero();
  double speed_m_per_s = 0.0;
  /// Fast strokes: angle between the travel direction and the surface plane.
  double grazing_angle_rad = 0.0;
  /// A continuous run that joins several strokes through free space: the index in
  /// p_W_hip where each of them begins. Empty for a single stroke.
  std::vector<std::size_t> stroke_starts;
};

struct StrokeSet {
  std::vector<Stroke> strokes;
  /// Surface points drawn and thrown away because the stroke would not have started in
  /// free space or would have met other surface before its anchor.
  std::size_t rejected = 0;
};

struct AnchorStrokeParams {
  double speed_m_per_s = 0.5;
  double rate_Hz = 1000.0;
  double outside_m = 0.020;  ///< start and retract height along the normal
  double depth_m = 0.005;    ///< depth below the surface during the slide
  double slide_m = 0.050;
  /// The start must be at least this far from every triangle (proxy reset).
  double min_start_clearance_m = 1e-3;
  /// Draws per stroke before giving up (std::runtime_error).
  int max_attempts_per_stroke = 10000;
};

struct FastStrokeParams {
  double min_speed_m_per_s = 0.05;
  double max_speed_m_per_s = 1.0;
  double rate_Hz = 1000.0;
  /// Angle between the path and the surface plane, drawn uniformly in [min, max].
  double min_grazing_angle_rad = 0.01;
  double max_grazing_angle_rad = 1.5707963267948966;
  /// Path length before reaching the anchor, and past it, each drawn uniformly.
  double min_before_m = 0.005;
  double max_before_m = 0.030;
  double min_after_m = 0.001;
  double max_after_m = 0.020;
  bool return_to_start = true;  ///< come back out along the same line
  double min_start_clearance_m = 1e-4;
  int max_attempts_per_stroke = 10000;
};

/// The benchmark protocol's strokes. The start (outside_m along the face normal) is kept only if
/// it is at least min_start_clearance_m from every triangle, not inside a closed object,
/// and the approach segment meets no surface before the anchor point.
/// Throws std::runtime_error if a stroke cannot be placed (e.g. an empty surface).
[[nodiscard]] StrokeSet make_anchor_strokes(const SurfaceCrossingOracle& surface, std::uint64_t seed, int count,
                                            const AnchorStrokeParams& params = {});
[[nodiscard]] StrokeSet make_anchor_strokes(const CollisionWorld& world, std::uint64_t seed, int count,
                                            const AnchorStrokeParams& params = {});

/// Random fast pokes: a random anchor, a direction into the surface at a random grazing
/// angle and azimuth, a random speed; start outside (same free-space rules as above).
[[nodiscard]] StrokeSet make_fast_strokes(const SurfaceCrossingOracle& surface, std::uint64_t seed, int count,
                                          const FastStrokeParams& params = {});
[[nodiscard]] StrokeSet make_fast_strokes(const CollisionWorld& world, std::uint64_t seed, int count,
                                          const FastStrokeParams& params = {});

/// Samples a polyline at constant speed: points at arc length 0, h, 2h, ... with
/// h = speed / rate, plus the last corner if the last sample is not on it.
/// Precondition: speed > 0, rate > 0, at least one corner.
[[nodiscard]] std::vector<Eigen::Vector3d> sample_polyline(std::span<const Eigen::Vector3d> corners_W,
                                                           double speed_m_per_s, double rate_Hz);

/// Area-weighted random surface points (zero-area triangles are never drawn).
class SurfaceSampler {
 public:
  /// Keeps a reference to `surface`. Throws std::runtime_error if its area is zero.
  explicit SurfaceSampler(const SurfaceCrossingOracle& surface);
  [[nodiscard]] SurfaceSample sample(std::mt19937_64& rng) const;

 private:
  const SurfaceCrossingOracle* surface_;
  std::vector<double> cumulative_area_;
};

/// Uniform double in [0, 1) from 53 random bits (same on every platform).
[[nodiscard]] double uniform01(std::mt19937_64& rng);

}  // namespace mhd::verify
