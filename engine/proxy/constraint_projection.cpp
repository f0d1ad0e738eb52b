#include "proxy/constraint_projection.h"

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <utility>

namespace mhd {

// Eigen 3.4's PartialPivLU<Matrix3d>(N).solve(d) written out: the same pivots, the same
// operations in the same order, so the same bits (ProjectOntoHalfSpaces.
// ThreePlanesSolveBitForBitAsPartialPivLU), without its out-of-line factorization, its L1
// norm and its permutation matrix (about a third of the projection's cost).
Eigen::Vector3d solve_three_planes_like_lu(Eigen::Matrix3d lu, Eigen::Vector3d x) {
  for (int k = 0; k < 2; ++k) {
    // Pivot: the largest magnitude in column k from row k down, the first of equals.
    int pivot = k;
    double biggest = std::abs(lu(k, k));
    for (int i = k + 1; i < 3; ++i) {
      if (std::abs(lu(i, k)) > biggest) {
        biggest = std::abs(lu(i, k));
        pivot = i;
      }
    }
    if (biggest != 0.0) {
      if (pivot != k) {
        lu.row(k).swap(lu.row(pivot));
        std::swap(x(k), x(pivot));  // the transposition P applies to the right-hand side
      }
      for (int i = k + 1; i < 3; ++i) lu(i, k) /= lu(k, k);
    }
    for (int i = k + 1; i < 3; ++i) {
      for (int j = k + 1; j < 3; ++j) lu(i, j) -= lu(i, k) * lu(k, j);
    }
  }
  // L (unit diagonal) forwards, then U backwards, row by row as Eigen unrolls them.
  x(1) -= lu(1, 0) * x(0);
  x(2) -= lu(2, 0) * x(0) + lu(2, 1) * x(1);
  x(2) /= lu(2, 2);
  x(1) -= lu(1, 2) * x(2);
  x(1) /= lu(1, 1);
  x(0) -= lu(0, 1) * x(1) + lu(0, 2) * x(2);
  x(0) /= lu(0, 0);
  return x;
}

namespace {

// Below these the planes of a pair or triple are treated as parallel: their common
// line or point is ill-defined, and a single plane of the set covers the case.
constexpr double kMinSinSquaredPair = 1e-12;
constexpr double kMinTripleProduct = 1e-9;

bool satisfies_all(const Eigen::Vector3d& x, std::span<const HalfSpace> hs, double tolerance) {
  for (const auto& h : hs) {
    if (h.normal.dot(x) < h.offset - tolerance) return false;
  }
  return true;
}

// Projection of goal onto the intersection of the planes normal.x == offset of the
// chosen set (1, 2 or 3 planes).
std::optional<Eigen::Vector3d> project_onto_planes(const Eigen::Vector3d& goal, const HalfSpace* const* planes,
                                                   int count) {
  if (count == 1) {
    const HalfSpace& p = *planes[0];
    return goal + (p.offset - p.normal.dot(goal)) * p.normal;
  }
  if (count == 2) {
    const HalfSpace& p = *planes[0];
    const HalfSpace& q = *planes[1];
    const double c = p.normal.dot(q.normal);
    const double det = 1.0 - c * c;
    if (!(det > kMinSinSquaredPair)) return std::nullopt;
    const double rp = p.offset - p.normal.dot(goal);
    const double rq = q.offset - q.normal.dot(goal);
    // x = goal + a n_p + b n_q, with the 2x2 Gram system solved in closed form.
    const double alpha = (rp - c * rq) / det;
    const double beta = (rq - c * rp) / det;
    return goal + alpha * p.normal + beta * q.normal;
  }
  Eigen::Matrix3d n;
  n << planes[0]->normal.transpose(), planes[1]->normal.transpose(), planes[2]->normal.transpose();
  if (!(std::abs(n.determinant()) > kMinTripleProduct)) return std::nullopt;
  const Eigen::Vector3d d(planes[0]->offset, planes[1]->offset, planes[2]->offset);
  return solve_three_planes_like_lu(n, d);
}

}  // namespace

std::optional<Eigen::Vector3d> project_onto_half_spaces(const Eigen::Vector3d& goal,
                                                        std::span<const HalfSpace> half_spaces,
                                                        double tolerance) {
  if (satisfies_all(goal, half_spaces, tolerance)) return goal;
  const int k = static_cast<int>(half_spaces.size());
  std::optional<Eigen::Vector3d> best;
  double best_distance_sq = std::numeric_limits<double>::infinity();
  const HalfSpace* chosen[3];
  auto consider = [&](int count) {
    const auto x = project_onto_planes(goal, chosen, count);
    if (!x || !satisfies_all(*x, half_spaces, tolerance)) return;
    const double d2 = (*x - goal).squaredNorm();
    if (d2 < best_distance_sq) {
      best_distance_sq = d2;
      best = x;
    }
  };
  // The optimum of a convex QP lies on one face of the feasible region: the
  // projection onto that face's planes. Try every face of up to three planes
  // (at most 6 + 15 + 20 candidates) and keep the nearest feasible one.
  for (int i = 0; i < k; ++i) {
    chosen[0] = &half_spaces[static_cast<std::size_t>(i)];
    consider(1);
    for (int j = i + 1; j < k; ++j) {
      chosen[1] = &half_spaces[static_cast<std::size_t>(j)];
      consider(2);
      for (int l = j + 1; l < k; ++l) {
        chosen[2] = &half_spaces[static_cast<std::size_t>(l)];
        consider(3);
      }
    }
  }
  return best;
}

}  // namespace mhd
