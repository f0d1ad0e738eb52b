#pragma once
// A mesh just past the 2^21 triangles one Bullet part can index, whose last triangles
// are the only ones near the point the tests touch: a tree that names a wrong triangle
// for a leaf past 2^21 misses them.

#include "geometry/triangle_mesh.h"

#include <cstdint>
#include <memory>

namespace mhd::test {

/// Index of the first triangle of the patch: the grid before it has exactly 2^21.
inline constexpr std::uint32_t kPatchFirstTriangle = std::uint32_t{1} << 21;

/// A 1024 x 1024 grid of quads over [0, 1]^2 at z = 0 (2^21 triangles), then a 32 x 32
/// grid of quads over [0.4, 0.6]^2 at z = 0.5 (2048 triangles), both facing +z.
inline std::shared_ptr<TriangleMesh> mesh_past_one_bullet_part() {
  auto mesh = std::make_shared<TriangleMesh>();
  auto add_grid = [&mesh](int n, double lo, double hi, double z) {
    const auto first = static_cast<std::uint32_t>(mesh->vertices_m.size());
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        mesh->vertices_m.emplace_back(lo + (hi - lo) * i / n, lo + (hi - lo) * j / n, z);
      }
    }
    auto id = [first, n](int i, int j) { return first + static_cast<std::uint32_t>(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        mesh->triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        mesh->triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  };
  mesh->vertices_m.reserve(1025 * 1025 + 33 * 33);
  mesh->triangles.reserve(kPatchFirstTriangle + 2048);
  add_grid(1024, 0.0, 1.0, 0.0);
  add_grid(32, 0.4, 0.6, 0.5);
  return mesh;
}

}  // namespace mhd::test
