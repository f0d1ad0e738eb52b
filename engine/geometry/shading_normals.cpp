#include "geometry/shading_normals.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace mhd {
namespace {

// Faces whose unit normals agree this closely are one direction at a vertex: summed once,
// so a vertex with thousands of coplanar triangles (a cylinder's cap centre) costs one
// comparison per other direction, not one per triangle.
constexpr double kSameDirectionDot = 1.0 - 1e-12;

// Position groups: vertices with bitwise equal coordinates share a group id.
std::vector<std::uint32_t> position_groups(const TriangleMesh& mesh, std::uint32_t& group_count) {
  const std::size_t n = mesh.vertices_m.size();
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  auto less = [&](std::uint32_t a, std::uint32_t b) {
    const Eigen::Vector3d& p = mesh.vertices_m[a];
    const Eigen::Vector3d& q = mesh.vertices_m[b];
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    return p.z() < q.z();
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<std::uint32_t> group(n, 0);
  group_count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (i == 0 || less(order[i - 1], order[i])) ++group_count;
    group[order[i]] = group_count - 1;
  }
  return group;
}

// Unit normal and corner angles of one triangle; zero normal and angles if degenerate.
struct FaceInfo {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  std::array<double, 3> angle_rad{};
};

FaceInfo face_info(const TriangleMesh& mesh, const TriangleIndices& t) {
  FaceInfo f;
  const std::array<Eigen::Vector3d, 3> v{mesh.vertices_m[t[0]], mesh.vertices_m[t[1]], mesh.vertices_m[t[2]]};
  const Eigen::Vector3d n = (v[1] - v[0]).cross(v[2] - v[0]);
  const double len = n.norm();
  if (!(len > 0.0)) return f;
  f.normal = n / len;
  for (std::size_t i = 0; i < 3; ++i) {
    const Eigen::Vector3d e1 = v[(i + 1) % 3] - v[i];
    const Eigen::Vector3d e2 = v[(i + 2) % 3] - v[i];
    f.angle_rad[i] = std::atan2(e1.cross(e2).norm(), e1.dot(e2));
  }
  return f;
}

}  // namespace

ShadingNormals compute_shading_normals(const TriangleMesh& mesh, double crease_angle_rad) {
  ShadingNormals out;
  out.crease_angle_rad = crease_angle_rad;
  const std::size_t triangle_count = mesh.triangles.size();
  out.corner_normals_O.resize(triangle_count);

  std::vector<FaceInfo> faces(triangle_count);
  for (std::size_t t = 0; t < triangle_count; ++t) faces[t] = face_info(mesh, mesh.triangles[t]);

  // Corners grouped by position (compressed rows: corners of group g are
  // corners[first[g] .. first[g + 1]), each corner as 3 * triangle + i).
  std::uint32_t group_count = 0;
  const std::vector<std::uint32_t> group = position_groups(mesh, group_count);
  std::vector<std::size_t> first(group_count + 1, 0);
  for (const auto& t : mesh.triangles) {
    for (const std::uint32_t v : t) ++first[group[v] + 1];
  }
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<std::size_t> corners(3 * triangle_count);
  {
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for (std::size_t t = 0; t < triangle_count; ++t) {
      for (std::size_t i = 0; i < 3; ++i) corners[fill[group[mesh.triangles[t][i]]]++] = 3 * t + i;
    }
  }

  const double min_dot = std::cos(crease_angle_rad);
  struct Direction {
    Eigen::Vector3d normal;  // unit face normal
    double weight_rad;       // summed corner angles of the faces along it
  };
  std::vector<Direction> directions;
  for (std::uint32_t g = 0; g < group_count; ++g) {
    // The distinct face directions at this position, with their angle weights.
    directions.clear();
    for (std::size_t k = first[g]; k < first[g + 1]; ++k) {
      const FaceInfo& f = faces[corners[k] / 3];
      const double w = f.angle_rad[corners[k] % 3];
      std::size_t d = 0;
      while (d < directions.size() && !(directions[d].normal.dot(f.normal) > kSameDirectionDot)) ++d;
      if (d == directions.size()) directions.push_back({f.normal, 0.0});
      directions[d].weight_rad += w;
    }
    // Each corner sums the directions within the crease angle of its own face.
    for (std::size_t k = first[g]; k < first[g + 1]; ++k) {
      const std::size_t t = corners[k] / 3;
      const Eigen::Vector3d& own = faces[t].normal;
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (const Direction& d : directions) {
        if (d.normal.dot(own) >= min_dot) sum += d.weight_rad * d.normal;
      }
      const double len = sum.norm();
      const Eigen::Vector3d n = len > 0.0 ? Eigen::Vector3d(sum / len) : own;
      out.corner_normals_O[t][corners[k] % 3] = n.cast<float>();
    }
  }
  return out;
}

Eigen::Vector3d interpolated_normal_O(const TriangleMesh& mesh, const ShadingNormals& normals, std::uint32_t t,
                                      const Eigen::Vector3d& p_O) {
  const TriangleIndices& tri = mesh.triangles[t];
  const Eigen::Vector3d& a = mesh.vertices_m[tri[0]];
  const Eigen::Vector3d& b = mesh.vertices_m[tri[1]];
  const Eigen::Vector3d& c = mesh.vertices_m[tri[2]];
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double denom = n.squaredNorm();
  if (!(denom > 0.0)) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d face = n / std::sqrt(denom);
  // Barycentric weights of p's projection, clamped into the triangle.
  const double ua = n.dot((b - p_O).cross(c - p_O)) / denom;
  const double ub = n.dot((c - p_O).cross(a - p_O)) / denom;
  const double wa = std::max(ua, 0.0);
  const double wb = std::max(ub, 0.0);
  const double wc = std::max(1.0 - ua - ub, 0.0);
  const double sum = wa + wb + wc;
  if (!(sum > 0.0)) return face;
  const auto& corner = normals.corner_normals_O[t];
  const Eigen::Vector3d blended =
      (wa * corner[0].cast<double>() + wb * corner[1].cast<double>() + wc * corner[2].cast<double>()) / sum;
  const double len = blended.norm();
  return len > 0.0 ? Eigen::Vector3d(blended / len) : face;
}

}  // namespace mhd
