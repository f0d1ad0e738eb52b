#include "mesh_gen/ring_surface.h"

#include <stdexcept>
#include <utility>

namespace mhd::mesh_gen {

TriangleMesh make_ring_surface(const std::vector<Eigen::Vector3d>& rings, int ring_count, int ring_size,
                               const Eigen::Vector3d& first_pole, const Eigen::Vector3d& last_pole) {
  if (ring_count < 1 || ring_size < 3 ||
      rings.size() != static_cast<std::size_t>(ring_count) * static_cast<std::size_t>(ring_size)) {
    throw std::invalid_argument("make_ring_surface: ring sizes do not match");
  }
  const auto n = static_cast<std::uint32_t>(ring_size);
  const auto m = static_cast<std::uint32_t>(ring_count);
  TriangleMesh mesh;
  mesh.vertices_m.reserve(rings.size() + 2);
  mesh.vertices_m.push_back(first_pole);
  mesh.vertices_m.insert(mesh.vertices_m.end(), rings.begin(), rings.end());
  mesh.vertices_m.push_back(last_pole);
  const std::uint32_t first = 0;
  const std::uint32_t last = 1 + m * n;
  auto at = [n](std::uint32_t ring, std::uint32_t j) { return 1 + ring * n + (j % n); };

  mesh.triangles.reserve(2 * static_cast<std::size_t>(m) * n);
  for (std::uint32_t j = 0; j < n; ++j) mesh.triangles.push_back({first, at(0, j + 1), at(0, j)});
  for (std::uint32_t i = 0; i + 1 < m; ++i) {
    for (std::uint32_t j = 0; j < n; ++j) {
      const std::uint32_t a = at(i, j), b = at(i, j + 1), c = at(i + 1, j + 1), d = at(i + 1, j);
      const auto& V = mesh.vertices_m;
      if ((V[a] - V[c]).squaredNorm() <= (V[b] - V[d]).squaredNorm()) {
        mesh.triangles.push_back({a, b, c});
        mesh.triangles.push_back({a, c, d});
      } else {
        mesh.triangles.push_back({a, b, d});
        mesh.triangles.push_back({b, c, d});
      }
    }
  }
  for (std::uint32_t j = 0; j < n; ++j) mesh.triangles.push_back({last, at(m - 1, j), at(m - 1, j + 1)});
  if (signed_volume(mesh) < 0.0) flip_orientation(mesh);
  return mesh;
}

double signed_volume(const TriangleMesh& mesh) {
  double six_volume = 0.0;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices_m[t[0]];
    six_volume += a.dot((mesh.vertices_m[t[1]] - a).cross(mesh.vertices_m[t[2]] - a));
  }
  return six_volume / 6.0;
}

void flip_orientation(TriangleMesh& mesh) {
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
}

}  // namespace mhd::mesh_gen
