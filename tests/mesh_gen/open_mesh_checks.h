#pragma once
// Independent checks of open meshes such as range scans, written for the tests:
// connected pieces and distance to a reference surface (brute force, small meshes).

#include "geometry/triangle_mesh.h"

#include <Eigen/Core>

#include <cstddef>

namespace mhd::mesh_gen::test {

/// Pieces of the mesh whose triangles are joined through shared vertices (unused
/// vertices do not count).
[[nodiscard]] std::size_t connected_components(const TriangleMesh& mesh);

/// Distance from p to the closest point of any triangle of the mesh.
[[nodiscard]] double distance_to_mesh(const TriangleMesh& mesh, const Eigen::Vector3d& p);

}  // namespace mhd::mesh_gen::test
