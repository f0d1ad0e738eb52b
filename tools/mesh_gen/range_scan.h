#pragma once
// A synthesized single-view range scan of a mesh: an orthographic depth grid, first hits
// only, neighbouring samples triangulated and cut wherever the depth jumps. The result
// is an open surface with many patches, holes and jagged boundaries, like a real scan.

#include "geometry/triangle_mesh.h"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>

namespace mhd::mesh_gen {

struct RangeScanParams {
  /// Where the scanner stands, seen from the source's origin (y up): azimuth about +y
  /// from +z towards +x, elevation above the x-z plane. (0, 0) looks along -z.
  double azimuth_deg = 0.0;
  double elevation_deg = 0.0;
  int columns = 330;  ///< samples per row, >= 2
  int rows = 330;     ///< samples per column, >= 2
  /// A triangle is dropped when its corners' depths differ by more than this many grid
  /// spacings (cuts silhouettes and self-occlusions, and grazing surfaces).
  double max_depth_jump_cells = 4.0;
  /// Each sample moves along its ray by a uniform amount in [-noise_m, +noise_m]
  /// (0: exact samples); must be below 1 mm.
  double noise_m = 0.0;
  std::uint64_t seed = 0;  ///< picks the noise; the same seed gives the same scan
};

struct RangeScanStats {
  double spacing_m = 0.0;           ///< grid spacing (square cells)
  std::size_t samples_hit = 0;      ///< rays that hit the source
  std::size_t dropped_depth_jump = 0;
  std::size_t dropped_degenerate = 0;
  std::size_t patches = 0;          ///< connected components (sharing a vertex)
};

struct RangeScan {
  /// In the source's frame, metres. Triangles face the scanner (counter-clockwise seen
  /// from it); vertices are the hit points in row-major grid order.
  TriangleMesh mesh;
  Eigen::Vector3d to_scanner_O = Eigen::Vector3d::UnitZ();  ///< unit, from the object towards the scanner
  RangeScanStats stats;
};

/// The unit direction towards the scanner for the params' azimuth and elevation.
[[nodiscard]] Eigen::Vector3d scan_direction(double azimuth_deg, double elevation_deg);

/// Scans `source` (two-sided: back faces are hit too) with a grid of square cells
/// fitted to the source's projected bounds. Deterministic. Throws
/// std::invalid_argument for an empty source, a non-finite or out-of-range angle
/// (|elevation| <= 90), fewer than 2 columns or rows or over 100 million samples, a
/// negative or non-finite jump threshold, or noise outside [0, 1 mm).
[[nodiscard]] RangeScan make_range_scan(const TriangleMesh& source, const RangeScanParams& params);

}  // namespace mhd::mesh_gen
