#include "mesh_gen/bowl_mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mhd::mesh_gen {

std::size_t BowlLayout::triangle_count() const {
  return static_cast<std::size_t>(segments) * static_cast<std::size_t>(2 * rings - 1);
}

BowlLayout bowl_layout(std::size_t target_triangles, double cap_angle_rad) {
  const double target = std::max(static_cast<double>(target_triangles), 8.0);
  // Square cells at mid-depth: segments / rings = 2 pi sin(angle / 2) / angle.
  const double ratio = std::max(2.0 * std::numbers::pi * std::sin(0.5 * cap_angle_rad) / cap_angle_rad, 0.5);
  const int rings = std::max(1, static_cast<int>(std::lround(std::sqrt(target / (2.0 * ratio)))));
  const int segments = std::max(3, static_cast<int>(std::lround(target / (2.0 * rings - 1.0))));
  return {rings, segments};
}

TriangleMesh make_bowl(double radius_m, double cap_angle_rad, const BowlLayout& layout) {
  if (!(radius_m > 0.0) || !(cap_angle_rad > 0.0 && cap_angle_rad < std::numbers::pi) || layout.rings < 1 ||
      layout.segments < 3) {
    throw std::invalid_argument("make_bowl: needs radius > 0, 0 < cap angle < pi, rings >= 1, segments >= 3");
  }
  const auto n = static_cast<std::uint32_t>(layout.segments);
  const auto m = static_cast<std::uint32_t>(layout.rings);
  TriangleMesh mesh;
  mesh.vertices_m.reserve(1 + static_cast<std::size_t>(m) * n);
  mesh.vertices_m.emplace_back(0.0, -radius_m, 0.0);
  for (int i = 1; i <= layout.rings; ++i) {
    const double polar = cap_angle_rad * i / layout.rings;  // from the bottom pole
    const double y = -radius_m * std::cos(polar);
    const double rho = radius_m * std::sin(polar);
    for (int j = 0; j < layout.segments; ++j) {
      const double azimuth = 2.0 * std::numbers::pi * j / layout.segments;
      mesh.vertices_m.emplace_back(rho * std::cos(azimuth), y, -rho * std::sin(azimuth));
    }
  }
  auto at = [n](std::uint32_t ring, std::uint32_t j) { return 1 + ring * n + (j % n); };
  // Azimuth turns clockwise seen from below, so (pole, j + 1, j) faces away from the centre.
  mesh.triangles.reserve(static_cast<std::size_t>(n) * (2 * m - 1));
  for (std::uint32_t j = 0; j < n; ++j) mesh.triangles.push_back({0, at(0, j + 1), at(0, j)});
  for (std::uint32_t i = 0; i + 1 < m; ++i) {
    for (std::uint32_t j = 0; j < n; ++j) {
      const std::uint32_t a = at(i, j), b = at(i, j + 1), c = at(i + 1, j + 1), d = at(i + 1, j);
      mesh.triangles.push_back({a, b, c});
      mesh.triangles.push_back({a, c, d});
    }
  }
  return mesh;
}

}  // namespace mhd::mesh_gen
