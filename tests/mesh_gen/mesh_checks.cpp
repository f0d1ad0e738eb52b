#include "mesh_checks.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdint>
#include <limits>
#include <numbers>
#include <unordered_map>
#include <utility>
#include <vector>

namespace mhd::mesh_gen::test {

EdgeStats edge_stats(const TriangleMesh& mesh) {
  // (undirected key, 1 if stored low -> high) for every half-edge, sorted by key.
  std::vector<std::pair<std::uint64_t, int>> half_edges;
  half_edges.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[static_cast<std::size_t>(k)];
      const std::uint32_t b = t[static_cast<std::size_t>((k + 1) % 3)];
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
      half_edges.emplace_back(key, a < b ? 1 : 0);
    }
  }
  std::sort(half_edges.begin(), half_edges.end());
  EdgeStats stats;
  for (std::size_t i = 0; i < half_edges.size();) {
    std::size_t j = i;
    int forward = 0;
    while (j < half_edges.size() && half_edges[j].first == half_edges[i].first) forward += half_edges[j++].second;
    const std::size_t uses = j - i;
    ++stats.edges;
    if (uses == 1) {
      ++stats.boundary;
    } else if (uses == 2 && forward == 1) {
      ++stats.manifold_oriented;
    } else {
      ++stats.bad;
    }
    i = j;
  }
  return stats;
}

long euler_characteristic(const TriangleMesh& mesh) {
  std::vector<char> used(mesh.vertices_m.size(), 0);
  for (const auto& t : mesh.triangles) {
    for (auto v : t) used[v] = 1;
  }
  const auto vertices = static_cast<long>(std::count(used.begin(), used.end(), 1));
  return vertices - static_cast<long>(edge_stats(mesh).edges) + static_cast<long>(mesh.triangles.size());
}

double enclosed_volume(const TriangleMesh& mesh) {
  double six_volume = 0.0;
  for (const auto& t : mesh.triangles) {
    six_volume += mesh.vertices_m[t[0]].dot(mesh.vertices_m[t[1]].cross(mesh.vertices_m[t[2]]));
  }
  return six_volume / 6.0;
}

double winding_number(const TriangleMesh& mesh, const Eigen::Vector3d& p) {
  // Van Oosterom & Strackee: tan(omega / 2) = a.(b x c) / (|a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|).
  double total = 0.0;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices_m[t[0]] - p;
    const Eigen::Vector3d b = mesh.vertices_m[t[1]] - p;
    const Eigen::Vector3d c = mesh.vertices_m[t[2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    total += 2.0 * std::atan2(numerator, denominator);
  }
  return total / (4.0 * std::numbers::pi);
}

double min_triangle_shape(const TriangleMesh& mesh) {
  double worst = std::numeric_limits<double>::infinity();
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices_m[t[0]];
    const Eigen::Vector3d& b = mesh.vertices_m[t[1]];
    const Eigen::Vector3d& c = mesh.vertices_m[t[2]];
    const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    const double twice_area = (b - a).cross(c - a).norm();
    worst = std::min(worst, longest > 0.0 ? twice_area / longest : 0.0);
  }
  return worst;
}

double min_triangle_area(const TriangleMesh& mesh) {
  double worst = std::numeric_limits<double>::infinity();
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices_m[t[0]];
    worst = std::min(worst, 0.5 * (mesh.vertices_m[t[1]] - a).cross(mesh.vertices_m[t[2]] - a).norm());
  }
  return worst;
}

namespace {

// Does the open segment pq cross the open triangle abc? (Coplanar contact is ignored.)
bool segment_crosses_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                              const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double dp = n.dot(p - a);
  const double dq = n.dot(q - a);
  if ((dp >= 0.0 && dq >= 0.0) || (dp <= 0.0 && dq <= 0.0)) return false;
  const Eigen::Vector3d x = p + (dp / (dp - dq)) * (q - p);
  return n.dot((b - a).cross(x - a)) > 0.0 && n.dot((c - b).cross(x - b)) > 0.0 &&
         n.dot((a - c).cross(x - c)) > 0.0;
}

bool shares(const TriangleIndices& t, std::uint32_t v) { return t[0] == v || t[1] == v || t[2] == v; }

bool pair_intersects(const TriangleMesh& mesh, const TriangleIndices& A, const TriangleIndices& B) {
  const auto& P = mesh.vertices_m;
  int shared = 0;
  for (auto v : A) shared += shares(B, v) ? 1 : 0;
  if (shared >= 2) {
    const Eigen::Vector3d na = (P[A[1]] - P[A[0]]).cross(P[A[2]] - P[A[0]]).normalized();
    const Eigen::Vector3d nb = (P[B[1]] - P[B[0]]).cross(P[B[2]] - P[B[0]]).normalized();
    return na.dot(nb) < -0.99999;  // folded flat onto its neighbour
  }
  // An edge that touches a shared vertex cannot cross the other triangle's interior
  // unless coplanar, so only the edges away from shared vertices are tested.
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t p = A[static_cast<std::size_t>(k)], q = A[static_cast<std::size_t>((k + 1) % 3)];
    if (!shares(B, p) && !shares(B, q) && segment_crosses_triangle(P[p], P[q], P[B[0]], P[B[1]], P[B[2]])) return true;
  }
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t p = B[static_cast<std::size_t>(k)], q = B[static_cast<std::size_t>((k + 1) % 3)];
    if (!shares(A, p) && !shares(A, q) && segment_crosses_triangle(P[p], P[q], P[A[0]], P[A[1]], P[A[2]])) return true;
  }
  return false;
}

}  // namespace

std::size_t count_self_intersections(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) return 0;
  const Eigen::AlignedBox3d box = mesh_bounds(mesh);
  double mean_edge = 0.0;
  for (const auto& t : mesh.triangles) mean_edge += (mesh.vertices_m[t[1]] - mesh.vertices_m[t[0]]).norm();
  mean_edge /= static_cast<double>(mesh.triangles.size());
  const double cell = std::max(2.0 * mean_edge, 1e-9);
  // Uniform grid of triangle boxes; every candidate pair is tested in the one cell that
  // holds the low corner of the two boxes' overlap, so each pair is counted once.
  using Cell = std::array<long, 3>;
  auto cell_of = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d g = (p - box.min()) / cell;
    return Cell{static_cast<long>(g.x()), static_cast<long>(g.y()), static_cast<long>(g.z())};
  };
  auto key = [](const Cell& c) {
    return (static_cast<std::uint64_t>(c[0]) * 73856093u) ^ (static_cast<std::uint64_t>(c[1]) * 19349663u) ^
           (static_cast<std::uint64_t>(c[2]) * 83492791u);
  };
  std::vector<Eigen::AlignedBox3d> boxes(mesh.triangles.size());
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    for (auto v : mesh.triangles[i]) boxes[i].extend(mesh.vertices_m[v]);
    const Cell lo = cell_of(boxes[i].min()), hi = cell_of(boxes[i].max());
    for (long x = lo[0]; x <= hi[0]; ++x)
      for (long y = lo[1]; y <= hi[1]; ++y)
        for (long z = lo[2]; z <= hi[2]; ++z) grid[key({x, y, z})].push_back(static_cast<std::uint32_t>(i));
  }
  std::size_t count = 0;
  for (const auto& [k, list] : grid) {
    for (std::size_t i = 0; i < list.size(); ++i) {
      for (std::size_t j = i + 1; j < list.size(); ++j) {
        const Eigen::AlignedBox3d& a = boxes[list[i]];
        const Eigen::AlignedBox3d& b = boxes[list[j]];
        if (!a.intersects(b)) continue;
        if (key(cell_of(a.min().cwiseMax(b.min()))) != k) continue;
        if (pair_intersects(mesh, mesh.triangles[list[i]], mesh.triangles[list[j]])) ++count;
      }
    }
  }
  return count;
}

}  // namespace mhd::mesh_gen::test
