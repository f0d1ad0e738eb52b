#include "mesh_gen/uv_sphere_mesh.h"

#include "mesh_gen/ring_surface.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mhd::mesh_gen {

std::size_t UvSphereLayout::triangle_count() const {
  return 2 * static_cast<std::size_t>(segments) * static_cast<std::size_t>(bands - 1);
}

UvSphereLayout uv_sphere_layout(std::size_t target_triangles) {
  const double target = std::max(static_cast<double>(target_triangles), 12.0);
  // 2 * s * (b - 1) triangles with s = 2 (b - 1) gives 4 (b - 1)^2.
  const int interior_rings = std::max(1, static_cast<int>(std::lround(std::sqrt(target / 4.0))));
  const int segments = std::max(3, static_cast<int>(std::lround(target / (2.0 * interior_rings))));
  return {interior_rings + 1, segments};
}

TriangleMesh make_uv_sphere(double radius_m, const UvSphereLayout& layout) {
  if (!(radius_m > 0.0) || layout.bands < 2 || layout.segments < 3) {
    throw std::invalid_argument("make_uv_sphere: needs radius > 0, bands >= 2, segments >= 3");
  }
  const int rings = layout.bands - 1;
  std::vector<Eigen::Vector3d> points;
  points.reserve(static_cast<std::size_t>(rings) * static_cast<std::size_t>(layout.segments));
  for (int i = 1; i <= rings; ++i) {
    const double polar = std::numbers::pi * i / layout.bands;
    const double y = radius_m * std::cos(polar);
    const double rho = radius_m * std::sin(polar);
    for (int j = 0; j < layout.segments; ++j) {
      const double azimuth = 2.0 * std::numbers::pi * j / layout.segments;
      points.emplace_back(rho * std::cos(azimuth), y, -rho * std::sin(azimuth));
    }
  }
  return make_ring_surface(points, rings, layout.segments, Eigen::Vector3d(0.0, radius_m, 0.0),
                           Eigen::Vector3d(0.0, -radius_m, 0.0));
}

}  // namespace mhd::mesh_gen
