#pragma once
// Hand-made meshes for the tests of the test support itself (independent of the
// engine's primitive tessellation, which those tests must not trust).

#include "geometry/triangle_mesh.h"

#include <Eigen/Core>

namespace mhd::test {

/// Axis-aligned box [lo, hi], outward CCW triangles; `welded` shares the 8 corners,
/// otherwise every face has its own 4 vertices (the same coordinates, as loaders give).
inline TriangleMesh make_test_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, bool welded = true) {
  TriangleMesh mesh;
  auto corner = [&](int i) {
    return Eigen::Vector3d((i & 1) ? hi.x() : lo.x(), (i & 2) ? hi.y() : lo.y(), (i & 4) ? hi.z() : lo.z());
  };
  // Each face as a quad of corner ids, CCW seen from outside.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  if (welded) {
    for (int i = 0; i < 8; ++i) mesh.vertices_m.push_back(corner(i));
  }
  for (const auto& q : quads) {
    std::uint32_t id[4];
    for (int k = 0; k < 4; ++k) {
      if (welded) {
        id[k] = static_cast<std::uint32_t>(q[k]);
      } else {
        id[k] = static_cast<std::uint32_t>(mesh.vertices_m.size());
        mesh.vertices_m.push_back(corner(q[k]));
      }
    }
    mesh.triangles.push_back({id[0], id[1], id[2]});
    mesh.triangles.push_back({id[0], id[2], id[3]});
  }
  return mesh;
}

/// Square [x0, x1] x [y0, y1] at height z, two triangles facing +z.
inline TriangleMesh make_test_square(double x0, double x1, double y0, double y1, double z) {
  TriangleMesh mesh;
  mesh.vertices_m = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

}  // namespace mhd::test
