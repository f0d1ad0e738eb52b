#include "geometry/coherent_winding.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace mhd {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
// Rows of edges leaving a vertex up to this long are checked pair by pair; longer ones sorted.
constexpr std::uint64_t kMaxRowComparedPairwise = 32;

// The triangles at each vertex, in compressed rows: those of vertex v are
// triangles[first[v] .. first[v + 1]).
struct VertexTriangles {
  std::vector<std::uint64_t> first;  // 3 T may pass 2^32
  std::vector<std::uint32_t> triangles;
};

VertexTriangles triangles_at_vertices(const TriangleMesh& mesh) {
  VertexTriangles at;
  at.first.assign(mesh.vertices_m.size() + 1, 0);
  for (const TriangleIndices& t : mesh.triangles) {
    for (const std::uint32_t v : t) ++at.first[v + 1];
  }
  std::partial_sum(at.first.begin(), at.first.end(), at.first.begin());
  at.triangles.assign(3 * mesh.triangles.size(), 0);
  // Filled through `first` as cursors (each ends at the next row's start), then shifted
  // back: no second array of a vertex's size.
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (const std::uint32_t v : mesh.triangles[t]) at.triangles[at.first[v]++] = static_cast<std::uint32_t>(t);
  }
  for (std::size_t v = at.first.size() - 1; v > 0; --v) at.first[v] = at.first[v - 1];
  at.first[0] = 0;
  return at;
}

// The other triangle on edge a -> b of triangle t when exactly one other has that edge,
// else kNone. `same_way` tells whether it walks the edge a -> b too (wound against t).
std::uint32_t across_edge(const TriangleMesh& mesh, const VertexTriangles& at, std::uint32_t t, std::uint32_t a,
                          std::uint32_t b, bool& same_way) {
  std::uint32_t found = kNone;
  // Through the end with fewer triangles: a pole or a fan's centre may have thousands.
  const bool from_a = at.first[a + 1] - at.first[a] <= at.first[b + 1] - at.first[b];
  const std::uint32_t v = from_a ? a : b;
  for (std::uint64_t k = at.first[v]; k < at.first[v + 1]; ++k) {
    const std::uint32_t s = at.triangles[k];
    if (s == t) continue;
    const TriangleIndices& c = mesh.triangles[s];
    const int i = c[0] == a ? 0 : (c[1] == a ? 1 : (c[2] == a ? 2 : -1));
    if (i < 0) continue;
    const bool forward = c[static_cast<std::size_t>((i + 1) % 3)] == b;
    if (!forward && c[static_cast<std::size_t>((i + 2) % 3)] != b) continue;
    if (found != kNone) return kNone;  // three or more on this edge: a seam
    found = s;
    same_way = forward;
  }
  return found;
}

// Whether some edge is walked the same way by two triangles: two neighbours wound
// against each other, or three or more triangles on one edge. Without one, every surface
// is wound one way already. Cheaper than the walk (each vertex's own row, read in order,
// no triangle looked up), so a mesh wound one way, as most are, pays only this.
bool some_edge_walked_twice(const TriangleMesh& mesh) {
  // The vertex each edge leaving a vertex goes to, in compressed rows as in VertexTriangles.
  std::vector<std::uint64_t> first(mesh.vertices_m.size() + 1, 0);
  for (const TriangleIndices& t : mesh.triangles) {
    for (const std::uint32_t v : t) ++first[v + 1];
  }
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<std::uint32_t> to(3 * mesh.triangles.size(), 0);
  for (const TriangleIndices& t : mesh.triangles) {
    for (std::size_t i = 0; i < 3; ++i) to[first[t[i]]++] = t[(i + 1) % 3];
  }
  // `first` now holds each row's end; a row starts where the one before it ends.
  std::uint64_t begin = 0;
  for (std::size_t v = 0; v + 1 < first.size(); ++v) {
    const std::uint64_t end = first[v];
    if (end - begin > kMaxRowComparedPairwise) {
      // A fan's centre or a pole: sorted, so that a million triangles round one vertex
      // cost a sort, not a million squared comparisons.
      const auto row = to.begin() + static_cast<std::ptrdiff_t>(begin);
      const auto row_end = to.begin() + static_cast<std::ptrdiff_t>(end);
      std::sort(row, row_end);
      if (std::adjacent_find(row, row_end) != row_end) return true;
    } else {
      for (std::uint64_t i = begin; i < end; ++i) {
        for (std::uint64_t j = i + 1; j < end; ++j) {
          if (to[i] == to[j]) return true;
        }
      }
    }
    begin = end;
  }
  return false;
}

double area_of(const TriangleMesh& mesh, const TriangleIndices& t) {
  const Eigen::Vector3d& a = mesh.vertices_m[t[0]];
  return (mesh.vertices_m[t[1]] - a).cross(mesh.vertices_m[t[2]] - a).norm();
}

}  // namespace

std::size_t orient_coherently(TriangleMesh& mesh) {
  const std::size_t count = mesh.triangles.size();
  if (count < 2 || !some_edge_walked_twice(mesh)) return 0;
  const VertexTriangles at = triangles_at_vertices(mesh);
  // 0: not reached yet; 1: wound as its surface's first triangle; 2: the other way.
  std::vector<std::uint8_t> side(count, 0);
  // Each surface's triangles in the order reached, one surface after another.
  std::vector<std::uint32_t> reached(count);
  std::size_t tail = 0;
  std::size_t turned = 0;
  for (std::size_t seed = 0; seed < count; ++seed) {
    if (side[seed] != 0) continue;
    const std::size_t begin = tail;
    side[seed] = 1;
    reached[tail++] = static_cast<std::uint32_t>(seed);
    bool mixed = false;
    for (std::size_t head = begin; head < tail; ++head) {
      const std::uint32_t t = reached[head];
      const TriangleIndices c = mesh.triangles[t];
      mixed = mixed || side[t] == 2;
      for (std::size_t e = 0; e < 3; ++e) {
        bool same_way = false;
        const std::uint32_t s = across_edge(mesh, at, t, c[e], c[(e + 1) % 3], same_way);
        if (s == kNone || side[s] != 0) continue;
        side[s] = same_way ? static_cast<std::uint8_t>(3 - side[t]) : side[t];
        reached[tail++] = s;
      }
    }
    if (!mixed) continue;  // wound one way already, as most surfaces are
    std::array<double, 3> area{};  // by side
    for (std::size_t k = begin; k < tail; ++k) area[side[reached[k]]] += area_of(mesh, mesh.triangles[reached[k]]);
    // Ties keep the first triangle's winding.
    const std::uint8_t minority = area[2] > area[1] ? 1 : 2;
    for (std::size_t k = begin; k < tail; ++k) {
      TriangleIndices& c = mesh.triangles[reached[k]];
      if (side[reached[k]] != minority) continue;
      std::swap(c[1], c[2]);
      ++turned;
    }
  }
  return turned;
}

}  // namespace mhd
