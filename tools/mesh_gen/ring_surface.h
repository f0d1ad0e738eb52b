#pragma once
// A closed genus-0 surface from a stack of vertex rings between two poles: the
// tessellation shared by the UV sphere and the dolphin.

#include "geometry/triangle_mesh.h"

#include <vector>

namespace mhd::mesh_gen {

/// `rings` holds ring_count rings of ring_size points each, ring after ring, ordered
/// from `first_pole` to `last_pole`; every ring runs the same way round its axis.
/// Each band quad is split along its shorter diagonal. The result is oriented outward
/// (positive signed volume), so the rings may run either way round.
/// Preconditions: ring_count >= 1, ring_size >= 3, and the rings form an embedded surface.
[[nodiscard]] TriangleMesh make_ring_surface(const std::vector<Eigen::Vector3d>& rings, int ring_count,
                                             int ring_size, const Eigen::Vector3d& first_pole,
                                             const Eigen::Vector3d& last_pole);

/// Signed volume enclosed by a closed mesh (positive when it faces outward).
[[nodiscard]] double signed_volume(const TriangleMesh& mesh);

/// Reverses the winding of every triangle.
void flip_orientation(TriangleMesh& mesh);

}  // namespace mhd::mesh_gen
