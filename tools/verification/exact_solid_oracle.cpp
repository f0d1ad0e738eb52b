#include "verification/exact_solid_oracle.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mhd::verify {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Golden-section steps over [0, 1]: 0.618^100 is far below double resolution.
constexpr int kSearchSteps = 100;

}  // namespace

void ExactSolids::add(int object, const ExactShape& shape, const Pose& X_WO) {
  solids_.push_back(Solid{object, shape, X_WO.inverse(Eigen::Isometry)});
}

double ExactSolids::distance_O(const ExactShape& s, const Eigen::Vector3d& p) {
  switch (s.kind) {
    case ExactKind::Sphere:
      return p.norm() - s.radius_m;
    case ExactKind::HalfSpace:
      return p.z();
    case ExactKind::Capsule: {
      const double z = std::max(std::abs(p.z()) - s.half_height_m, 0.0);
      return std::sqrt(p.x() * p.x() + p.y() * p.y() + z * z) - s.radius_m;
    }
    case ExactKind::Cylinder: {
      const double out_r = std::sqrt(p.x() * p.x() + p.y() * p.y()) - s.radius_m;
      const double out_z = std::abs(p.z()) - s.half_height_m;
      if (out_r <= 0.0 && out_z <= 0.0) return std::max(out_r, out_z);
      return std::sqrt(std::pow(std::max(out_r, 0.0), 2) + std::pow(std::max(out_z, 0.0), 2));
    }
    case ExactKind::Box: {
      double outside2 = 0.0;
      double inside = -kInf;
      for (int k = 0; k < 3; ++k) {
        const double e = std::abs(p[k]) - s.half_extents_m[k];
        if (e > 0.0) outside2 += e * e;
        inside = std::max(inside, e);
      }
      return outside2 > 0.0 ? std::sqrt(outside2) : inside;
    }
  }
  return kInf;
}

std::pair<double, double> ExactSolids::segment_minimum(const Solid& s, const Eigen::Vector3d& a_W,
                                                       const Eigen::Vector3d& b_W) {
  const Eigen::Vector3d a = s.X_OW * a_W;
  const Eigen::Vector3d b = s.X_OW * b_W;
  const Eigen::Vector3d ab = b - a;
  if (s.shape.kind == ExactKind::HalfSpace) return a.z() <= b.z() ? std::pair{a.z(), 0.0} : std::pair{b.z(), 1.0};
  if (s.shape.kind == ExactKind::Sphere) {  // closed form: the point of the segment nearest the centre
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp(-a.dot(ab) / len2, 0.0, 1.0) : 0.0;
    return {(a + t * ab).norm() - s.shape.radius_m, t};
  }
  // The distance to a convex solid is convex along a line: golden-section search.
  const auto f = [&](double t) { return distance_O(s.shape, a + t * ab); };
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double lo = 0.0, hi = 1.0;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < kSearchSteps && hi - lo > 0.0; ++i) {
    if (f1 <= f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = f(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = f(x2);
    }
  }
  std::pair<double, double> best{f1, x1};
  for (const double t : {0.0, 1.0, x2}) {
    if (f(t) < best.first) best = {f(t), t};
  }
  return best;
}

double ExactSolids::signed_distance(const Eigen::Vector3d& p_W) const {
  double d = kInf;
  for (const Solid& s : solids_) d = std::min(d, distance_O(s.shape, s.X_OW * p_W));
  return d;
}

bool ExactSolids::touches(const Eigen::Vector3d& a_W, const Eigen::Vector3d& b_W) const {
  return std::any_of(solids_.begin(), solids_.end(),
                     [&](const Solid& s) { return segment_minimum(s, a_W, b_W).first <= 0.0; });
}

std::optional<ExactSolids::Touch> ExactSolids::first_touch(const Eigen::Vector3d& a_W,
                                                           const Eigen::Vector3d& b_W) const {
  std::optional<Touch> first;
  for (const Touch& t : all_touches(a_W, b_W)) {
    if (!first || t.t < first->t) first = t;
  }
  return first;
}

std::vector<ExactSolids::Touch> ExactSolids::all_touches(const Eigen::Vector3d& a_W,
                                                         const Eigen::Vector3d& b_W) const {
  std::vector<Touch> touches;
  for (const Solid& s : solids_) {
    const auto [d_min, t_min] = segment_minimum(s, a_W, b_W);
    if (d_min > 0.0) continue;
    // Bisect between the start (outside) and the minimum (touching) for the first touch.
    double lo = 0.0, hi = t_min;
    const Eigen::Vector3d a = s.X_OW * a_W, ab = s.X_OW * b_W - a;
    if (distance_O(s.shape, a) <= 0.0) hi = 0.0;
    for (int i = 0; i < 200 && hi - lo > 0.0 && lo < hi; ++i) {
      const double mid = 0.5 * (lo + hi);
      if (mid == lo || mid == hi) break;
      if (distance_O(s.shape, a + mid * ab) <= 0.0) hi = mid; else lo = mid;
    }
    touches.push_back(Touch{s.object, hi});
  }
  return touches;
}

bool ExactSolids::brushes(const Eigen::Vector3d& a_W, const Eigen::Vector3d& b_W, double clearance_m) const {
  return std::any_of(solids_.begin(), solids_.end(), [&](const Solid& s) {
    return distance_O(s.shape, s.X_OW * a_W) > 2.0 * clearance_m &&
           segment_minimum(s, a_W, b_W).first < clearance_m;
  });
}

}  // namespace mhd::verify
