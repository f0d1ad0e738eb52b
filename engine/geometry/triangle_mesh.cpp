#include "geometry/triangle_mesh.h"

#include <algorithm>

namespace mhd {

void compute_vertex_normals(TriangleMesh& mesh) {
  // Summed in double, so that many small faces round as one; stored in single precision.
  std::vector<Eigen::Vector3d> sums(mesh.vertices_m.size(), Eigen::Vector3d::Zero());
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices_m[t[0]];
    const Eigen::Vector3d& b = mesh.vertices_m[t[1]];
    const Eigen::Vector3d& c = mesh.vertices_m[t[2]];
    const Eigen::Vector3d area_normal = (b - a).cross(c - a);  // length = 2 * area
    for (auto i : t) sums[i] += area_normal;
  }
  mesh.vertex_normals.resize(sums.size());
  for (std::size_t i = 0; i < sums.size(); ++i) {
    const double len = sums[i].norm();
    mesh.vertex_normals[i] = len > 0.0 ? Eigen::Vector3f((sums[i] / len).cast<float>()) : Eigen::Vector3f::Zero();
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
