#include "collision/segment_triangle.h"

#include <Eigen/Geometry>

#include <algorithm>

namespace mhd {
namespace {
constexpr double kSkinSlack = 1e-6;
}  // namespace

std::optional<TriangleSweep> sweep_point_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                                  const Eigen::Vector3d& v0, const Eigen::Vector3d& v1,
                                                  const Eigen::Vector3d& v2, double skin, double inflate) {
  const Eigen::Vector3d area_normal = (v1 - v0).cross(v2 - v0);
  const double twice_area = area_normal.norm();
  if (!(twice_area > 0.0)) return std::nullopt;
  const Eigen::Vector3d n_ccw = area_normal / twice_area;

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
  if (!(db < da)) return std::nullopt;  // parallel or moving away: cannot cross
  // Never comes within the skin. The slack absorbs rounding of a point that slides
  // along the plane exactly one skin away; a crossing needs db < 0, far below it.
  if (db >= skin * (1.0 - kSkinSlack)) return std::nullopt;

  const double approach = da - db;
  const double t_plane = da / approach;
  // Where the point crosses the plane, or where it ends inside the skin.
  const double t_test = std::min(t_plane, 1.0);
  const Eigen::Vector3d x = a + t_test * (b - a);

  // Distance of x's projection outside each edge, measured in the plane.
  const Eigen::Vector3d* corners[3] = {&v0, &v1, &v2};
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d& p = *corners[i];
    const Eigen::Vector3d& q = *corners[(i + 1) % 3];
    const Eigen::Vector3d edge = q - p;
    const Eigen::Vector3d outward = edge.cross(n_ccw);
    const double len = outward.norm();
    if (!(len > 0.0)) continue;  // cannot happen for non-zero area; keeps it conservative
    if (outward.dot(x - p) > inflate * len) return std::nullopt;
  }

  TriangleSweep hit;
  hit.t_plane = t_plane;
  hit.t_stop = std::clamp((da - skin) / approach, 0.0, 1.0);
  hit.normal = n;
  return hit;
}

}  // namespace mhd
