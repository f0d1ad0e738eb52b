#pragma once
// The proxy's goal projected onto the free side of its constraint planes: the point
// nearest the goal with normal_i . x >= offset_i for every plane (a small convex QP,
// solved exactly by trying each face of the feasible region).

#include <Eigen/Core>

#include <optional>
#include <span>

namespace mhd {

struct HalfSpace {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< unit
  double offset = 0.0;                                ///< feasible: normal . x >= offset
};

/// Largest number of half-spaces project_onto_half_spaces accepts.
inline constexpr int kMaxHalfSpaces = 8;

/// Nearest point to `goal` that satisfies every half-space within `tolerance`.
/// Returns nullopt if none is found (numerically empty or degenerate set);
/// the caller then keeps its proxy where it is.
/// Precondition: half_spaces.size() <= kMaxHalfSpaces.
[[nodiscard]] std::optional<Eigen::Vector3d> project_onto_half_spaces(const Eigen::Vector3d& goal,
                                                                      std::span<const HalfSpace> half_spaces,
                                                                      double tolerance);

/// The point x on three planes, N x = d (rows of N the unit normals), bit for bit what
/// Eigen 3.4's N.partialPivLu().solve(d) gives. Precondition: N not singular.
[[nodiscard]] Eigen::Vector3d solve_three_planes_like_lu(Eigen::Matrix3d lu, Eigen::Vector3d x);

}  // namespace mhd
