#include "mesh_gen/depth_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mhd::mesh_gen {

ScanAxes scan_axes(const Eigen::Vector3d& to_scanner_O) {
  const Eigen::Vector3d c = to_scanner_O.normalized();
  // Up is +y projected off the view; near a vertical view, +z projected off it.
  const Eigen::Vector3d reference = std::abs(c.y()) < 0.999 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d right = reference.cross(c).normalized();
  return {right, c.cross(right), c};
}

Eigen::Vector3d DepthGrid::point_O(int column, int row, double depth) const {
  return (right0_m + column * spacing_m) * axes.right_O + (up0_m + row * spacing_m) * axes.up_O -
         depth * axes.to_scanner_O;
}

DepthGrid cast_depth_grid(const TriangleMesh& mesh, const ScanAxes& axes, int columns, int rows) {
  // Every vertex in scanner coordinates (right, up, depth).
  std::vector<Eigen::Vector3d> q(mesh.vertices_m.size());
  Eigen::AlignedBox2d box;
  for (std::size_t k = 0; k < q.size(); ++k) {
    const Eigen::Vector3d& p = mesh.vertices_m[k];
    q[k] = {p.dot(axes.right_O), p.dot(axes.up_O), -p.dot(axes.to_scanner_O)};
    box.extend(q[k].head<2>());
  }

  DepthGrid grid;
  grid.axes = axes;
  grid.columns = columns;
  grid.rows = rows;
  grid.spacing_m = std::max(box.sizes().x() / (columns - 1), box.sizes().y() / (rows - 1));
  grid.right0_m = box.center().x() - 0.5 * (columns - 1) * grid.spacing_m;
  grid.up0_m = box.center().y() - 0.5 * (rows - 1) * grid.spacing_m;
  grid.depth_m.assign(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows),
                      std::numeric_limits<double>::infinity());

  const double h = grid.spacing_m;
  for (const TriangleIndices& t : mesh.triangles) {
    const Eigen::Vector3d& a = q[t[0]];
    const Eigen::Vector3d& b = q[t[1]];
    const Eigen::Vector3d& c = q[t[2]];
    const double area2 = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    if (!(std::abs(area2) > 0.0)) continue;  // seen edge-on: its neighbours cover it
    // Rays through the triangle's projected bounds (clamped to the grid).
    const auto first = [](double lo, double origin, double step) {
      return std::max(0, static_cast<int>(std::ceil((lo - origin) / step)));
    };
    const auto last = [](double hi, double origin, double step, int count) {
      return std::min(count - 1, static_cast<int>(std::floor((hi - origin) / step)));
    };
    const int i0 = first(std::min({a.x(), b.x(), c.x()}), grid.right0_m, h);
    const int i1 = last(std::max({a.x(), b.x(), c.x()}), grid.right0_m, h, columns);
    const int j0 = first(std::min({a.y(), b.y(), c.y()}), grid.up0_m, h);
    const int j1 = last(std::max({a.y(), b.y(), c.y()}), grid.up0_m, h, rows);
    // Barycentric weights by signed sub-areas; a hair of slack so that a ray through a
    // shared edge or vertex never falls between two triangles.
    constexpr double kSlack = 1e-12;
    for (int j = j0; j <= j1; ++j) {
      const double y = grid.up0_m + j * h;
      for (int i = i0; i <= i1; ++i) {
        const double x = grid.right0_m + i * h;
        const double wa = ((b.x() - x) * (c.y() - y) - (b.y() - y) * (c.x() - x)) / area2;
        const double wb = ((c.x() - x) * (a.y() - y) - (c.y() - y) * (a.x() - x)) / area2;
        const double wc = 1.0 - wa - wb;
        if (wa < -kSlack || wb < -kSlack || wc < -kSlack) continue;
        const double depth = wa * a.z() + wb * b.z() + wc * c.z();
        double& best = grid.depth_m[grid.index(i, j)];
        best = std::min(best, depth);
      }
    }
  }
  return grid;
}

}  // namespace mhd::mesh_gen
