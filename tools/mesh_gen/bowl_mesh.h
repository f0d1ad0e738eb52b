#pragma once
// An open, single-layer spherical cap ("bowl"): a thin shell with a boundary, for the
// proxy's thin-shell and open-mesh cases.

#include "geometry/triangle_mesh.h"

#include <cstddef>

namespace mhd::mesh_gen {

struct BowlLayout {
  int rings = 0;     ///< vertex rings from the bottom pole to the rim
  int segments = 0;  ///< vertices per ring
  [[nodiscard]] std::size_t triangle_count() const;  ///< segments * (2 * rings - 1)
};

/// Rings and segments with roughly square cells whose count is closest to the target.
/// cap_angle_rad is the polar angle of the rim seen from the sphere's centre (pi/2: a
/// hemisphere).
[[nodiscard]] BowlLayout bowl_layout(std::size_t target_triangles, double cap_angle_rad);

/// Spherical cap of the sphere of radius_m about the origin, bottom pole at (0, -r, 0),
/// rim at polar angle cap_angle_rad from the bottom (so a hemisphere's rim lies in y = 0
/// and it opens upward, +y). Triangles face away from the centre (the bowl's convex
/// underside is the "front"); the inside is touched from the back.
/// Preconditions: radius_m > 0, 0 < cap_angle_rad < pi, layout.rings >= 1, layout.segments >= 3.
[[nodiscard]] TriangleMesh make_bowl(double radius_m, double cap_angle_rad, const BowlLayout& layout);

}  // namespace mhd::mesh_gen
