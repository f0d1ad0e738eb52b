#include "geometry/triangle_mesh.h"

#include <algorithm>

namespace mhd {

void compute_vertex_normals(TriangleMesh& mesh) {
  mesh.vertex_normals.assign(mesh.vertices_m.size(), Eigen::Vector3d::Zero());
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices_m[t[0]];
    const Eigen::Vector3d& b = mesh.vertices_m[t[1]];
    const Eigen::Vector3d& c = mesh.vertices_m[t[2]];
    const Eigen::Vector3d area_normal = (b - a).cross(c - a);  // length = 2 * area
    for (auto i : t) mesh.vertex_normals[i] += area_normal;
  }
  for (auto& n : mesh.vertex_normals) {
    const double len = n.norm();
    n = len > 0.0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::Zero();
  }
}

Eigen::AlignedBox3d mesh_bounds(const TriangleMesh& mesh) {
  Eigen::AlignedBox3d box;
  for (const auto& v : mesh.vertices_m) box.extend(v);
  return box;
}

std::size_t remove_invalid_triangles(TriangleMesh& mesh) {
  const auto n = static_cast<std::uint32_t>(mesh.vertices_m.size());
  const auto before = mesh.triangles.size();
  std::erase_if(mesh.triangles, [n](const TriangleIndices& t) {
    return t[0] >= n || t[1] >= n || t[2] >= n || t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
  });
  return before - mesh.triangles.size();
}

}  // namespace mhd
