#pragma once
// Conservative sweep of a point against one triangle. No absolute area epsilon: a
// triangle of any size with a non-zero normal is tested; zero-area triangles have no
// surface of their own and are covered by their inflated neighbours.

#include <Eigen/Core>

#include <optional>

namespace mhd {

struct TriangleSweep {
  /// Fraction of a->b the point may travel while keeping skin from the plane.
  double t_stop = 0.0;
  /// Fraction at which the point would reach the plane (may exceed 1 when the segment
  /// ends inside the skin without reaching it).
  double t_plane = 0.0;
  /// Unit normal oriented towards a's side of the plane.
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
};

/// Reports a hit when the point moving from a to b comes towards the triangle's plane
/// and either crosses it, or ends within `skin` of it, at a place whose projection
/// lies in the triangle grown by `inflate` on every edge. Every segment that crosses
/// the closed triangle is reported (the inflation absorbs rounding at shared edges and
/// vertices, so no segment slips between neighbours).
/// Preconditions: skin > 0, inflate >= 0, inputs finite.
[[nodiscard]] std::optional<TriangleSweep> sweep_point_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                                                const Eigen::Vector3d& v0, const Eigen::Vector3d& v1,
                                                                const Eigen::Vector3d& v2, double skin, double inflate);

}  // namespace mhd
