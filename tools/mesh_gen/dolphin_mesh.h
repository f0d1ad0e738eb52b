#pragma once
// Tessellates the procedural dolphin (dolphin_shape.h) at any resolution: a closed,
// watertight, outward-facing, genus-0 mesh without self-intersections, 2.0 m long.

#include "geometry/triangle_mesh.h"

#include <cstddef>

namespace mhd::mesh_gen {

struct DolphinLayout {
  int rings = 0;      ///< vertex rings between the two poles
  int ring_size = 0;  ///< vertices per ring (a multiple of 4)
  [[nodiscard]] std::size_t triangle_count() const;  ///< 2 * rings * ring_size
};

/// Rings and ring size for about `target_triangles` triangles (within 2 % from 3,000 up).
[[nodiscard]] DolphinLayout dolphin_layout(std::size_t target_triangles);

/// The dolphin in its output frame (see DolphinShape), metres. Deterministic: the same
/// layout gives the same mesh. Rings and ring vertices are spaced by where the surface
/// bends and stretches, so the fins stay sharp at low resolution. Throws
/// std::invalid_argument unless rings >= 2 and ring_size is a multiple of 4, >= 8.
[[nodiscard]] TriangleMesh make_dolphin(const DolphinLayout& layout);

}  // namespace mhd::mesh_gen
