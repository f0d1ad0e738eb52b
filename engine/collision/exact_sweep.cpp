#include "collision/exact_sweep.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mhd {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Where the line a + t d is inside a convex set: [enter, exit] (empty when enter > exit).
struct Interval {
  double enter = -kInf;
  double exit = kInf;
  void meet(double lo, double hi) {
    enter = std::max(enter, lo);
    exit = std::min(exit, hi);
  }
  [[nodiscard]] bool empty() const { return !(enter <= exit); }
};

Interval nothing() { return Interval{kInf, -kInf}; }

// The line inside |x_k| <= h along one axis.
void meet_slab(Interval& in, double a, double d, double h) {
  if (d == 0.0) {
    if (std::abs(a) > h) in = nothing();
    return;
  }
  const double t0 = (-h - a) / d;
  const double t1 = (h - a) / d;
  in.meet(std::min(t0, t1), std::max(t0, t1));
}

// The roots of |p + t d|^2 = r^2 over the components the mask keeps (a ball, or an
// infinite cylinder round z when z is left out).
void meet_quadric(Interval& in, const Eigen::Vector3d& a, const Eigen::Vector3d& d, double r, bool with_z) {
  const Eigen::Vector3d mask(1.0, 1.0, with_z ? 1.0 : 0.0);
  const Eigen::Vector3d am = a.cwiseProduct(mask);
  const Eigen::Vector3d dm = d.cwiseProduct(mask);
  const double qa = dm.squaredNorm();
  const double qb = am.dot(dm);
  const double qc = am.squaredNorm() - r * r;
  if (qa == 0.0) {
    if (qc > 0.0) in = nothing();
    return;
  }
  const double disc = qb * qb - qa * qc;
  if (disc < 0.0) {
    in = nothing();
    return;
  }
  // The numerically stable pair of roots.
  const double s = std::sqrt(disc);
  const double q = qb >= 0.0 ? -(qb + s) : -(qb - s);
  double t0 = q / qa;
  double t1 = q != 0.0 ? qc / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  in.meet(t0, t1);
}

// The line inside the shape grown by `g`.
Interval grown_interval(const ExactShape& s, const Eigen::Vector3d& a, const Eigen::Vector3d& d, double g) {
  Interval in;
  switch (s.kind) {
    case ExactKind::Sphere:
      meet_quadric(in, a, d, s.radius_m + g, true);
      break;
    case ExactKind::HalfSpace:
      if (d.z() == 0.0) {
        if (a.z() > g) in = nothing();
      } else {
        const double t = (g - a.z()) / d.z();
        if (d.z() > 0.0) in.meet(-kInf, t); else in.meet(t, kInf);
      }
      break;
    case ExactKind::Box:
      for (int k = 0; k < 3; ++k) meet_slab(in, a[k], d[k], s.half_extents_m[k] + g);
      break;
    case ExactKind::Cylinder:
      meet_quadric(in, a, d, s.radius_m + g, false);
      meet_slab(in, a.z(), d.z(), s.half_height_m + g);
      break;
    case ExactKind::Capsule: {
      // The union of a finite cylinder and two balls: enters at the earliest entry of the
      // three, leaves at the latest exit (the union is convex, so one interval).
      Interval side;
      meet_quadric(side, a, d, s.radius_m + g, false);
      meet_slab(side, a.z(), d.z(), s.half_height_m);
      Interval result = nothing();
      const auto join = [&](const Interval& part) {
        if (part.empty()) return;
        result.enter = std::min(result.enter, part.enter);
        result.exit = std::max(result.exit, part.exit);
      };
      join(side);
      for (const double z : {-s.half_height_m, s.half_height_m}) {
        Interval ball;
        meet_quadric(ball, a - Eigen::Vector3d(0.0, 0.0, z), d, s.radius_m + g, true);
        join(ball);
      }
      in = result;
      break;
    }
  }
  return in;
}

// The contact seen from p outside a clamped shape, whose nearest point is q.
std::optional<ExactContact> nearest_clamped(const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
  const Eigen::Vector3d v = p - q;
  const double len = v.norm();
  if (!(len > 0.0)) return std::nullopt;
  return ExactContact{q, v / len};
}

}  // namespace

std::optional<ExactContact> exact_nearest_surface(const ExactShape& s, const Eigen::Vector3d& p) {
  switch (s.kind) {
    case ExactKind::Sphere: {
      const double len = p.norm();
      if (!(len >= s.radius_m) || !(len > 0.0)) return std::nullopt;
      const Eigen::Vector3d n = p / len;
      return ExactContact{s.radius_m * n, n};
    }
    case ExactKind::HalfSpace:
      if (p.z() < 0.0) return std::nullopt;
      return ExactContact{Eigen::Vector3d(p.x(), p.y(), 0.0), Eigen::Vector3d::UnitZ()};
    case ExactKind::Capsule: {
      const Eigen::Vector3d c(0.0, 0.0, std::clamp(p.z(), -s.half_height_m, s.half_height_m));
      const Eigen::Vector3d v = p - c;
      const double len = v.norm();
      if (!(len >= s.radius_m) || !(len > 0.0)) return std::nullopt;
      const Eigen::Vector3d n = v / len;
      return ExactContact{c + s.radius_m * n, n};
    }
    case ExactKind::Box: {
      const Eigen::Vector3d& h = s.half_extents_m;
      const Eigen::Vector3d q = p.cwiseMax(-h).cwiseMin(h);
      if (q != p) return nearest_clamped(p, q);
      for (int k = 0; k < 3; ++k) {  // on a face (inside otherwise)
        if (std::abs(p[k]) == h[k]) {
          Eigen::Vector3d n = Eigen::Vector3d::Zero();
          n[k] = p[k] > 0.0 ? 1.0 : -1.0;
          return ExactContact{p, n};
        }
      }
      return std::nullopt;
    }
    case ExactKind::Cylinder: {
      const double rho = std::hypot(p.x(), p.y());
      const double z = std::clamp(p.z(), -s.half_height_m, s.half_height_m);
      const double scale = rho > s.radius_m ? s.radius_m / rho : 1.0;
      const Eigen::Vector3d q(p.x() * scale, p.y() * scale, z);
      if (q != p) return nearest_clamped(p, q);
      if (rho == s.radius_m) return ExactContact{p, Eigen::Vector3d(p.x() / rho, p.y() / rho, 0.0)};
      if (std::abs(p.z()) == s.half_height_m) {
        return ExactContact{p, Eigen::Vector3d(0.0, 0.0, p.z() > 0.0 ? 1.0 : -1.0)};
      }
      return std::nullopt;
    }
  }
  return std::nullopt;
}

double exact_signed_distance(const ExactShape& s, const Eigen::Vector3d& p) {
  switch (s.kind) {
    case ExactKind::Sphere:
      return p.norm() - s.radius_m;
    case ExactKind::HalfSpace:
      return p.z();
    case ExactKind::Capsule: {
      const Eigen::Vector3d c(0.0, 0.0, std::clamp(p.z(), -s.half_height_m, s.half_height_m));
      return (p - c).norm() - s.radius_m;
    }
    case ExactKind::Box: {
      const Eigen::Vector3d q = p.cwiseAbs() - s.half_extents_m;
      return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
    }
    case ExactKind::Cylinder: {
      const double qr = std::hypot(p.x(), p.y()) - s.radius_m;
      const double qz = std::abs(p.z()) - s.half_height_m;
      return std::hypot(std::max(qr, 0.0), std::max(qz, 0.0)) + std::min(std::max(qr, qz), 0.0);
    }
  }
  return kInf;
}

std::optional<ExactSweep> sweep_point_exact(const ExactShape& s, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                            double skin) {
  const Eigen::Vector3d d = b - a;
  if (d == Eigen::Vector3d::Zero()) return std::nullopt;
  const Interval in = grown_interval(s, a, d, skin);
  if (in.empty() || in.exit < 0.0 || in.enter > 1.0) return std::nullopt;
  if (in.enter > 0.0) {
    if (const auto contact = exact_nearest_surface(s, a + in.enter * d)) return ExactSweep{in.enter, *contact};
    // Rounding put the entry inside the solid (cannot happen at skin scale): stop at the start.
    if (const auto contact = exact_nearest_surface(s, a)) return ExactSweep{0.0, *contact};
    return std::nullopt;
  }
  // Starts within the skin: stopped at once if approaching; inside the solid: let out.
  const auto contact = exact_nearest_surface(s, a);
  if (!contact || !(contact->normal_O.dot(d) < 0.0)) return std::nullopt;
  return ExactSweep{0.0, *contact};
}

}  // namespace mhd
