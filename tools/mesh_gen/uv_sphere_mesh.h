#pragma once
// Latitude/longitude ("UV") sphere: the benchmark sphere (docs/benchmarks.md), whose
// triangles shrink to slivers at the poles.

#include "geometry/triangle_mesh.h"

#include <cstddef>

namespace mhd::mesh_gen {

struct UvSphereLayout {
  int bands = 0;     ///< latitude bands, pole to pole (bands - 1 vertex rings)
  int segments = 0;  ///< longitude segments
  [[nodiscard]] std::size_t triangle_count() const;  ///< 2 * segments * (bands - 1)
};

/// Bands and segments (segments ~ 2 * bands) whose triangle count is closest to the
/// target; 1,000,000 gives exactly 501 bands x 1000 segments.
[[nodiscard]] UvSphereLayout uv_sphere_layout(std::size_t target_triangles);

/// UV sphere centred on the origin, poles on +/-y, outward-facing.
/// Preconditions: radius_m > 0, layout.bands >= 2, layout.segments >= 3.
[[nodiscard]] TriangleMesh make_uv_sphere(double radius_m, const UvSphereLayout& layout);

}  // namespace mhd::mesh_gen
