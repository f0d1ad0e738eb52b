#include "verification/stroke_set.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace mhd::verify {
namespace {

// Unit vectors u, v with (u, v, n) right-handed and orthonormal.
void tangent_basis(const Eigen::Vector3d& n, Eigen::Vector3d& u, Eigen::Vector3d& v) {
  Eigen::Index axis = 0;
  n.cwiseAbs().minCoeff(&axis);
  u = n.cross(Eigen::Vector3d::Unit(axis)).normalized();
  v = n.cross(u);
}

double uniform_in(std::mt19937_64& rng, double lo, double hi) { return lo + (hi - lo) * uniform01(rng); }

// Whether a stroke may start at `start` and head for `through` (a point past the anchor):
// the start is clear of every triangle and outside closed objects, and the first
// surface the segment meets is at the anchor (fraction t_anchor), not before it.
bool start_is_free(const SurfaceCrossingOracle& surface, const Eigen::Vector3d& start,
                   const Eigen::Vector3d& through, double t_anchor, double min_clearance_m) {
  if (!start.allFinite() || !through.allFinite()) return false;
  if (surface.distance_to_surface(start) < min_clearance_m) return false;
  if (surface.point_inside_closed_mesh(start)) return false;
  const std::optional<OracleHit> first = surface.first_touched_triangle(start, through);
  if (!first) return false;  // must meet the anchor's triangle
  const double length = (through - start).norm();
  constexpr double kAnchorTolerance_m = 1e-9;  // the anchor point itself is rounded
  return first->t * length >= t_anchor * length - kAnchorTolerance_m;
}

[[noreturn]] void give_up(const char* what, int stroke, int attempts) {
  throw std::runtime_error(std::string(what) + ": no free start found for stroke " + std::to_string(stroke) +
                           " in " + std::to_string(attempts) + " draws");
}

}  // namespace

double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

SurfaceSampler::SurfaceSampler(const SurfaceCrossingOracle& surface) : surface_(&surface) {
  cumulative_area_.reserve(surface.triangle_count());
  double total = 0.0;
  for (std::size_t i = 0; i < surface.triangle_count(); ++i) {
    const auto& [a, b, c] = surface.triangle_W(i);
    total += 0.5 * (b - a).cross(c - a).norm();
    cumulative_area_.push_back(total);
  }
  if (!(total > 0.0)) throw std::runtime_error("SurfaceSampler: the surface has no area");
}

SurfaceSample SurfaceSampler::sample(std::mt19937_64& rng) const {
  const double total = cumulative_area_.back();
  const double u = uniform01(rng) * total;
  // upper_bound never lands on a zero-area triangle (its interval is empty).
  auto it = std::upper_bound(cumulative_area_.begin(), cumulative_area_.end(), u);
  if (it == cumulative_area_.end()) --it;
  const std::size_t i = static_cast<std::size_t>(it - cumulative_area_.begin());
  double r1 = uniform01(rng);
  double r2 = uniform01(rng);
  if (r1 + r2 > 1.0) {
    r1 = 1.0 - r1;
    r2 = 1.0 - r2;
  }
  const auto& [a, b, c] = surface_->triangle_W(i);
  SurfaceSample s;
  s.where = surface_->triangle_ref(i);
  s.oracle_triangle = i;
  s.point_W = a + r1 * (b - a) + r2 * (c - a);
  s.normal_W = (b - a).cross(c - a).normalized();
  return s;
}

std::vector<Eigen::Vector3d> sample_polyline(std::span<const Eigen::Vector3d> corners_W, double speed_m_per_s,
                                             double rate_Hz) {
  if (corners_W.empty() || !(speed_m_per_s > 0.0) || !(rate_Hz > 0.0)) {
    throw std::invalid_argument("sample_polyline: needs corners, speed > 0 and rate > 0");
  }
  const double step_m = speed_m_per_s / rate_Hz;
  std::vector<double> cumulative{0.0};
  for (std::size_t i = 1; i < corners_W.size(); ++i) {
    cumulative.push_back(cumulative.back() + (corners_W[i] - corners_W[i - 1]).norm());
  }
  const double length_m = cumulative.back();
  std::vector<Eigen::Vector3d> samples{corners_W.front()};
  // Arc length k * step, k = 1..n; the factor keeps an exact multiple from being lost
  // to rounding in the division.
  const auto n = static_cast<std::size_t>(std::floor(length_m / step_m * (1.0 + 1e-12)));
  samples.reserve(n + 2);
  std::size_t leg = 0;
  for (std::size_t k = 1; k <= n; ++k) {
    const double s = std::min(static_cast<double>(k) * step_m, length_m);
    while (leg + 2 < cumulative.size() && cumulative[leg + 1] < s) ++leg;
    const double leg_length = cumulative[leg + 1] - cumulative[leg];
    const double f = leg_length > 0.0 ? std::clamp((s - cumulative[leg]) / leg_length, 0.0, 1.0) : 1.0;
    samples.push_back(corners_W[leg] + f * (corners_W[leg + 1] - corners_W[leg]));
  }
  if ((samples.back() - corners_W.back()).norm() > 1e-12) {
    samples.push_back(corners_W.back());
  } else {
    samples.back() = corners_W.back();
  }
  return samples;
}

StrokeSet make_anchor_strokes(const SurfaceCrossingOracle& surface, std::uint64_t seed, int count,
                              const AnchorStrokeParams& params) {
  const SurfaceSampler sampler(surface);
  std::mt19937_64 rng(seed);
  StrokeSet set;
  set.strokes.reserve(static_cast<std::size_t>(std::max(count, 0)));
  const double t_anchor = params.outside_m / (params.outside_m + params.depth_m);
  for (int i = 0; i < count; ++i) {
    int attempt = 0;
    for (;; ++attempt) {
      if (attempt >= params.max_attempts_per_stroke) give_up("make_anchor_strokes", i, attempt);
      const SurfaceSample s = sampler.sample(rng);
      const double azimuth = 2.0 * std::numbers::pi * uniform01(rng);
      Eigen::Vector3d u, v;
      tangent_basis(s.normal_W, u, v);
      const Eigen::Vector3d tangent = std::cos(azimuth) * u + std::sin(azimuth) * v;
      const Eigen::Vector3d& p = s.point_W;
      const Eigen::Vector3d& n = s.normal_W;
      const Eigen::Vector3d start = p + params.outside_m * n;
      const Eigen::Vector3d bottom = p - params.depth_m * n;
      if (!start_is_free(surface, start, bottom, t_anchor, params.min_start_clearance_m)) {
        ++set.rejected;
        continue;
      }
      Stroke stroke;
      stroke.corners_W = {start, bottom, bottom + params.slide_m * tangent,
                          p + params.slide_m * tangent + params.outside_m * n};
      stroke.p_W_hip = sample_polyline(stroke.corners_W, params.speed_m_per_s, params.rate_Hz);
      stroke.anchor = s;
      stroke.direction_W = tangent;
      stroke.speed_m_per_s = params.speed_m_per_s;
      set.strokes.push_back(std::move(stroke));
      break;
    }
  }
  return set;
}

StrokeSet make_anchor_strokes(const CollisionWorld& world, std::uint64_t seed, int count,
                              const AnchorStrokeParams& params) {
  const SurfaceCrossingOracle surface(world);
  return make_anchor_strokes(surface, seed, count, params);
}

StrokeSet make_fast_strokes(const SurfaceCrossingOracle& surface, std::uint64_t seed, int count,
                            const FastStrokeParams& params) {
  const SurfaceSampler sampler(surface);
  std::mt19937_64 rng(seed);
  StrokeSet set;
  set.strokes.reserve(static_cast<std::size_t>(std::max(count, 0)));
  for (int i = 0; i < count; ++i) {
    int attempt = 0;
    for (;; ++attempt) {
      if (attempt >= params.max_attempts_per_stroke) give_up("make_fast_strokes", i, attempt);
      const SurfaceSample s = sampler.sample(rng);
      const double azimuth = 2.0 * std::numbers::pi * uniform01(rng);
      const double grazing = uniform_in(rng, params.min_grazing_angle_rad, params.max_grazing_angle_rad);
      const double speed = uniform_in(rng, params.min_speed_m_per_s, params.max_speed_m_per_s);
      const double before = uniform_in(rng, params.min_before_m, params.max_before_m);
      const double after = uniform_in(rng, params.min_after_m, params.max_after_m);
      Eigen::Vector3d u, v;
      tangent_basis(s.normal_W, u, v);
      const Eigen::Vector3d tangent = std::cos(azimuth) * u + std::sin(azimuth) * v;
      // Into the surface: down the normal, along the tangent.
      const Eigen::Vector3d d = (std::cos(grazing) * tangent - std::sin(grazing) * s.normal_W).normalized();
      const Eigen::Vector3d start = s.point_W - before * d;
      const Eigen::Vector3d deepest = s.point_W + after * d;
      if (!start_is_free(surface, start, deepest, before / (before + after), params.min_start_clearance_m)) {
        ++set.rejected;
        continue;
      }
      Stroke stroke;
      stroke.corners_W = {start, deepest};
      if (params.return_to_start) stroke.corners_W.push_back(start);
      stroke.p_W_hip = sample_polyline(stroke.corners_W, speed, params.rate_Hz);
      stroke.anchor = s;
      stroke.direction_W = d;
      stroke.speed_m_per_s = speed;
      stroke.grazing_angle_rad = grazing;
      set.strokes.push_back(std::move(stroke));
      break;
    }
  }
  return set;
}

StrokeSet make_fast_strokes(const CollisionWorld& world, std::uint64_t seed, int count,
                            const FastStrokeParams& params) {
  const SurfaceCrossingOracle surface(world);
  return make_fast_strokes(surface, seed, count, params);
}

}  // namespace mhd::verify
