#pragma once
// Conservative sweep of a point against one triangle. No absolute area epsilon: a
// triangle of any size with a non-zero normal is tested; zero-area triangles have no
// surface of their own and are covered by their inflated neighbours.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
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

/// The triangle's unit normal, counter-clockwise (v1 - v0) x (v2 - v0) over its length, or
/// zero for a triangle of zero area. MeshBvh keeps it per triangle; computed here and
/// there by this one function, so the stored normal is the computed one, bit for bit.
[[nodiscard]] inline Eigen::Vector3d unit_face_normal(const Eigen::Vector3d& v0, const Eigen::Vector3d& v1,
                                                      const Eigen::Vector3d& v2) {
  const Eigen::Vector3d area_normal = (v1 - v0).cross(v2 - v0);
  const double twice_area = area_normal.norm();
  if (!(twice_area > 0.0)) return Eigen::Vector3d::Zero();
  return area_normal / twice_area;
}

/// Reports a hit when the point moving from a to b comes towards the triangle's plane
/// and either crosses it, or ends within `skin` of it, at a place whose projection
/// lies in the triangle grown by `inflate` on every edge. Every segment that crosses
/// the closed triangle is reported (the inflation absorbs rounding at shared edges and
/// vertices, so no segment slips between neighbours).
/// `n_ccw` is unit_face_normal(v0, v1, v2) (zero: no surface, never a hit).
/// Preconditions: skin > 0, inflate >= 0, inputs finite.
[[nodiscard]] inline std::optional<TriangleSweep> sweep_point_triangle(
    const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& v0, const Eigen::Vector3d& v1,
    const Eigen::Vector3d& v2, const Eigen::Vector3d& n_ccw, double skin, double inflate) {
  // Absorbs rounding of a point that slides along the plane exactly one skin away; a
  // crossing needs db < 0, far below it.
  constexpr double kSkinSlack = 1e-6;
  double da = n_ccw.dot(a - v0);
  double db = n_ccw.dot(b - v0);
  Eigen::Vector3d n = n_ccw;
  // Orient the plane towards the start point; a start exactly on the plane counts as
  // being on the side the segment leaves from.
  if (da < 0.0 || (da == 0.0 && db > 0.0)) {
    n = -n;
    da = -da;
    db = -db;
  }
  if (!(db < da)) return std::nullopt;  // parallel, moving away, or no surface: cannot cross
  if (db >= skin * (1.0 - kSkinSlack)) return std::nullopt;  // never comes within the skin

  const double approach = da - db;
  const double t_plane = da / approach;
  // Where the point crosses the plane, or where it ends inside the skin.
  const double t_test = std::min(t_plane, 1.0);
  const Eigen::Vector3d x = a + t_test * (b - a);

  // Distance of x's projection outside each edge, measured in the plane: outside by more
  // than `inflate` when outward . (x - p) > inflate |outward|. A non-positive dot product
  // never is (inflate |outward| >= 0), so the length is only taken for a positive one.
  const Eigen::Vector3d* corners[3] = {&v0, &v1, &v2};
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d& p = *corners[i];
    const Eigen::Vector3d& q = *corners[(i + 1) % 3];
    const Eigen::Vector3d outward = (q - p).cross(n_ccw);
    const double outside = outward.dot(x - p);
    if (!(outside > 0.0)) continue;
    const double len = outward.norm();
    if (!(len > 0.0)) continue;  // cannot happen for non-zero area; keeps it conservative
    if (outside > inflate * len) return std::nullopt;
  }

  TriangleSweep hit;
  hit.t_plane = t_plane;
  hit.t_stop = std::clamp((da - skin) / approach, 0.0, 1.0);
  hit.normal = n;
  return hit;
}

/// The same test, computing the triangle's normal first.
[[nodiscard]] inline std::optional<TriangleSweep> sweep_point_triangle(const Eigen::Vector3d& a,
                                                                       const Eigen::Vector3d& b,
                                                                       const Eigen::Vector3d& v0,
                                                                       const Eigen::Vector3d& v1,
                                                                       const Eigen::Vector3d& v2, double skin,
                                                                       double inflate) {
  return sweep_point_triangle(a, b, v0, v1, v2, unit_face_normal(v0, v1, v2), skin, inflate);
}

}  // namespace mhd
