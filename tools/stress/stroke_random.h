#pragma once
// Random draws shared by the stress stroke kinds (stress_strokes.cpp, tour_strokes.cpp).
// Internal to tools/stress: every draw takes the stroke's own stream, so one stroke can
// be rebuilt from (seed, object key, index) alone.

#include "stress/stress_strokes.h"
#include "verification/stroke_set.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace mhd::stress {

inline std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

inline double uniform_in(std::mt19937_64& rng, double lo, double hi) { return lo + (hi - lo) * verify::uniform01(rng); }

/// Uniform on the unit sphere: z uniform in [-1, 1], azimuth uniform.
inline Eigen::Vector3d random_unit(std::mt19937_64& rng) {
  const double z = uniform_in(rng, -1.0, 1.0);
  const double phi = uniform_in(rng, 0.0, 2.0 * std::numbers::pi);
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

/// A unit vector perpendicular to n (n unit).
inline Eigen::Vector3d any_perpendicular(const Eigen::Vector3d& n) {
  Eigen::Index axis = 0;
  n.cwiseAbs().minCoeff(&axis);
  return n.cross(Eigen::Vector3d::Unit(axis)).normalized();
}

/// An area-weighted random point p of the surface and its unit normal n; open surfaces
/// have two sides to touch, so there n is flipped half the time.
inline void draw_surface_point(const ObjectSurface& s, std::mt19937_64& rng, Eigen::Vector3d& p, Eigen::Vector3d& n) {
  const double u = verify::uniform01(rng) * s.cumulative_area.back();
  auto it = std::upper_bound(s.cumulative_area.begin(), s.cumulative_area.end(), u);
  if (it == s.cumulative_area.end()) --it;
  const auto t = static_cast<std::size_t>(it - s.cumulative_area.begin());
  double r1 = verify::uniform01(rng);
  double r2 = verify::uniform01(rng);
  if (r1 + r2 > 1.0) {
    r1 = 1.0 - r1;
    r2 = 1.0 - r2;
  }
  const auto& v = s.triangles_W[t];
  p = v[0] + r1 * (v[1] - v[0]) + r2 * (v[2] - v[0]);
  n = s.normals_W[t];
  if (!s.closed && verify::uniform01(rng) < 0.5) n = -n;
}

/// A feature of `list` drawn uniformly. Precondition: list is not empty.
inline const SurfaceFeature& draw_feature(const std::vector<SurfaceFeature>& list, std::mt19937_64& rng) {
  const auto i = static_cast<std::size_t>(verify::uniform01(rng) * static_cast<double>(list.size()));
  return list[std::min(list.size() - 1, i)];
}

}  // namespace mhd::stress
