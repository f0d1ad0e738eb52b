#include "geometry/primitive_mesh.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>
#include <unordered_map>

// Every closed primitive shares its vertices along seams (one index per position), so
// each edge belongs to exactly two triangles that walk it in opposite directions, and
// every triangle is counter-clockwise seen from outside. Invalid parameters throw
// std::invalid_argument (the scene compiler checks them first and reports a diagnostic).

namespace mhd {
namespace {

bool positive_finite(double x) { return std::isfinite(x) && x > 0.0; }

void require(bool condition, const char* what) {
  if (!condition) throw std::invalid_argument(what);
}

std::uint32_t index_of(std::size_t i) { return static_cast<std::uint32_t>(i); }

/// Unit radial normals for shapes centred on the origin whose surface normal is the
/// position direction (spheres).
void set_radial_normals(TriangleMesh& mesh) {
  mesh.vertex_normals.resize(mesh.vertices_m.size());
  for (std::size_t i = 0; i < mesh.vertices_m.size(); ++i) {
    mesh.vertex_normals[i] = mesh.vertices_m[i].normalized().cast<float>();
  }
}

}  // namespace

TriangleMesh make_plane_mesh(double size_x_m, double size_y_m) {
  require(positive_finite(size_x_m) && positive_finite(size_y_m),
          "make_plane_mesh: sizes must be positive and finite");
  const double hx = 0.5 * size_x_m;
  const double hy = 0.5 * size_y_m;
  TriangleMesh mesh;
  mesh.vertices_m = {{-hx, -hy, 0.0}, {hx, -hy, 0.0}, {hx, hy, 0.0}, {-hx, hy, 0.0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  mesh.vertex_normals.assign(4, Eigen::Vector3f::UnitZ());
  return mesh;
}

TriangleMesh make_box_mesh(const Eigen::Vector3d& size_m) {
  require(positive_finite(size_m.x()) && positive_finite(size_m.y()) && positive_finite(size_m.z()),
          "make_box_mesh: sizes must be positive and finite");
  const Eigen::Vector3d h = 0.5 * size_m;
  TriangleMesh mesh;
  // Vertex i has x = +h.x if bit 0 is set, y = +h.y if bit 1, z = +h.z if bit 2.
  mesh.vertices_m.reserve(8);
  for (int i = 0; i < 8; ++i) {
    mesh.vertices_m.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(),
                                 (i & 4) ? h.z() : -h.z());
  }
  // Each face as a quad, counter-clockwise seen from outside.
  constexpr std::uint32_t quads[6][4] = {
      {0, 2, 3, 1},  // -z
      {4, 5, 7, 6},  // +z
      {0, 1, 5, 4},  // -y
      {2, 6, 7, 3},  // +y
      {0, 4, 6, 2},  // -x
      {1, 3, 7, 5},  // +x
  };
  mesh.triangles.reserve(12);
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  compute_vertex_normals(mesh);
  return mesh;
}

TriangleMesh make_sphere_mesh(double radius_m, int subdivisions) {
  require(positive_finite(radius_m), "make_sphere_mesh: radius must be positive and finite");
  require(subdivisions >= 0 && subdivisions <= 7, "make_sphere_mesh: subdivisions must be 0..7");

  // Icosahedron on the unit sphere.
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  MeshArray<Eigen::Vector3d> v = {
      {-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
      {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1},
  };
  for (auto& p : v) p.normalize();
  MeshArray<TriangleIndices> tris = {
      {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1},
  };

  // Final sizes: V = 10 * 4^n + 2, F = 20 * 4^n.
  const std::size_t final_faces = std::size_t{20} << (2 * subdivisions);
  v.reserve(final_faces / 2 + 2);

  for (int level = 0; level < subdivisions; ++level) {
    // Midpoint of each edge, shared by the two triangles of that edge.
    std::unordered_map<std::uint64_t, std::uint32_t> midpoints;
    midpoints.reserve(tris.size() * 3 / 2);
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const std::uint64_t key = a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a);
      auto [it, inserted] = midpoints.try_emplace(key, index_of(v.size()));
      if (inserted) v.push_back((v[a] + v[b]).normalized());
      return it->second;
    };
    MeshArray<TriangleIndices> next;
    next.reserve(tris.size() * 4);
    for (const auto& tri : tris) {
      const std::uint32_t ab = midpoint(tri[0], tri[1]);
      const std::uint32_t bc = midpoint(tri[1], tri[2]);
      const std::uint32_t ca = midpoint(tri[2], tri[0]);
      next.push_back({tri[0], ab, ca});
      next.push_back({tri[1], bc, ab});
      next.push_back({tri[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    tris = std::move(next);
  }

  TriangleMesh mesh;
  mesh.vertices_m = std::move(v);
  for (auto& p : mesh.vertices_m) p *= radius_m;
  mesh.triangles = std::move(tris);
  set_radial_normals(mesh);
  return mesh;
}

TriangleMesh make_capsule_mesh(double radius_m, double length_m, int rings, int segments) {
  require(positive_finite(length_m), "make_capsule_mesh: length must be positive and finite");
  require(rings >= 1, "make_capsule_mesh: rings must be at least 1");
  // An odd number of bands puts no vertex on the equator: the band across it becomes the
  // cylinder once the two halves move apart.
  TriangleMesh mesh = make_uv_sphere_mesh(radius_m, 2 * rings + 1, segments);
  for (Eigen::Vector3d& v : mesh.vertices_m) v.z() += v.z() > 0.0 ? 0.5 * length_m : -0.5 * length_m;
  compute_vertex_normals(mesh);
  return mesh;
}

TriangleMesh make_uv_sphere_mesh(double radius_m, int rings, int segments) {
  require(positive_finite(radius_m), "make_uv_sphere_mesh: radius must be positive and finite");
  require(rings >= 2, "make_uv_sphere_mesh: rings must be at least 2");
  require(segments >= 3, "make_uv_sphere_mesh: segments must be at least 3");
  const auto R = static_cast<std::size_t>(rings);
  const auto S = static_cast<std::size_t>(segments);
  require((R - 1) * S + 2 < std::size_t{UINT32_MAX}, "make_uv_sphere_mesh: too many vertices");

  TriangleMesh mesh;
  // Vertex 0: north pole; then rings - 1 latitude circles of `segments` vertices each
  // (north to south); last vertex: south pole.
  mesh.vertices_m.reserve((R - 1) * S + 2);
  mesh.vertices_m.emplace_back(0.0, 0.0, radius_m);
  for (std::size_t r = 1; r < R; ++r) {
    const double theta = std::numbers::pi * static_cast<double>(r) / static_cast<double>(R);
    const double z = radius_m * std::cos(theta);
    const double rho = radius_m * std::sin(theta);
    for (std::size_t s = 0; s < S; ++s) {
      const double phi = 2.0 * std::numbers::pi * static_cast<double>(s) / static_cast<double>(S);
      mesh.vertices_m.emplace_back(rho * std::cos(phi), rho * std::sin(phi), z);
    }
  }
  const std::uint32_t south = index_of(mesh.vertices_m.size());
  mesh.vertices_m.emplace_back(0.0, 0.0, -radius_m);

  auto ring_vertex = [S](std::size_t ring, std::size_t s) {  // ring 1..R-1
    return index_of(1 + (ring - 1) * S + s % S);
  };
  mesh.triangles.reserve(2 * S * (R - 1));
  for (std::size_t s = 0; s < S; ++s) {  // north cap
    mesh.triangles.push_back({0, ring_vertex(1, s), ring_vertex(1, s + 1)});
  }
  for (std::size_t r = 1; r + 1 < R; ++r) {  // bands between ring r and r + 1
    for (std::size_t s = 0; s < S; ++s) {
      const std::uint32_t a = ring_vertex(r, s), b = ring_vertex(r, s + 1);
      const std::uint32_t c = ring_vertex(r + 1, s), d = ring_vertex(r + 1, s + 1);
      mesh.triangles.push_back({a, c, d});
      mesh.triangles.push_back({a, d, b});
    }
  }
  for (std::size_t s = 0; s < S; ++s) {  // south cap
    mesh.triangles.push_back({south, ring_vertex(R - 1, s + 1), ring_vertex(R - 1, s)});
  }
  set_radial_normals(mesh);
  return mesh;
}

TriangleMesh make_cylinder_mesh(double radius_m, double height_m, int segments) {
  require(positive_finite(radius_m) && positive_finite(height_m),
          "make_cylinder_mesh: radius and height must be positive and finite");
  require(segments >= 3, "make_cylinder_mesh: segments must be at least 3");
  const auto S = static_cast<std::size_t>(segments);
  require(2 * S + 2 < std::size_t{UINT32_MAX}, "make_cylinder_mesh: too many vertices");
  const double hz = 0.5 * height_m;

  TriangleMesh mesh;
  // 0..S-1: bottom rim, S..2S-1: top rim, 2S: bottom centre, 2S+1: top centre.
  mesh.vertices_m.reserve(2 * S + 2);
  for (const double z : {-hz, hz}) {
    for (std::size_t s = 0; s < S; ++s) {
      const double phi = 2.0 * std::numbers::pi * static_cast<double>(s) / static_cast<double>(S);
      mesh.vertices_m.emplace_back(radius_m * std::cos(phi), radius_m * std::sin(phi), z);
    }
  }
  const std::uint32_t bottom_centre = index_of(2 * S);
  const std::uint32_t top_centre = index_of(2 * S + 1);
  mesh.vertices_m.emplace_back(0.0, 0.0, -hz);
  mesh.vertices_m.emplace_back(0.0, 0.0, hz);

  auto bottom = [S](std::size_t s) { return index_of(s % S); };
  auto top = [S](std::size_t s) { return index_of(S + s % S); };
  mesh.triangles.reserve(4 * S);
  for (std::size_t s = 0; s < S; ++s) {
    mesh.triangles.push_back({bottom(s), bottom(s + 1), top(s + 1)});  // side
    mesh.triangles.push_back({bottom(s), top(s + 1), top(s)});
    mesh.triangles.push_back({top_centre, top(s), top(s + 1)});              // +z cap
    mesh.triangles.push_back({bottom_centre, bottom(s + 1), bottom(s)});     // -z cap
  }
  compute_vertex_normals(mesh);
  return mesh;
}

}  // namespace mhd
