#pragma once
// Orthographic first-hit depth of a mesh on a regular grid of parallel rays: a z-buffer
// rasterizer, each ray tested against the triangles whose projection covers it.

#include "geometry/triangle_mesh.h"

#include <Eigen/Core>

#include <vector>

namespace mhd::mesh_gen {

/// Orthonormal scanner axes in the object frame O: right x up = to_scanner.
struct ScanAxes {
  Eigen::Vector3d right_O;
  Eigen::Vector3d up_O;
  Eigen::Vector3d to_scanner_O;
};

/// Axes for a unit direction towards the scanner; up is the projection of +y (of +z
/// when the scanner looks straight along y).
[[nodiscard]] ScanAxes scan_axes(const Eigen::Vector3d& to_scanner_O);

struct DepthGrid {
  ScanAxes axes;
  int columns = 0;
  int rows = 0;
  double spacing_m = 0.0;
  double right0_m = 0.0;  ///< right coordinate of column 0
  double up0_m = 0.0;     ///< up coordinate of row 0 (rows go up)
  /// Row-major (row * columns + column): distance along the ray from the plane through
  /// O facing the scanner, larger = farther; +infinity where the ray hits nothing.
  std::vector<double> depth_m;

  [[nodiscard]] double depth(int column, int row) const { return depth_m[index(column, row)]; }
  [[nodiscard]] std::size_t index(int column, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(column);
  }
  /// The point of the ray (column, row) at depth_m.
  [[nodiscard]] Eigen::Vector3d point_O(int column, int row, double depth_m) const;
};

/// Casts columns x rows rays along -to_scanner through a grid of square cells that
/// just covers the projection of the mesh's vertices, centred on it. Both sides of
/// every triangle are hit; triangles seen edge-on are skipped.
/// Preconditions: mesh has vertices, columns >= 2, rows >= 2, and its projection is
/// not a single point.
[[nodiscard]] DepthGrid cast_depth_grid(const TriangleMesh& mesh, const ScanAxes& axes, int columns, int rows);

}  // namespace mhd::mesh_gen
