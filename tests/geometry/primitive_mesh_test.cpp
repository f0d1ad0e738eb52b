#include "geometry/primitive_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace mhd {
namespace {

// Vertex normals are single precision: unit within a few float roundings.
constexpr float kUnitFloat = 4 * std::numeric_limits<float>::epsilon();

constexpr double kPi = std::numbers::pi;

/// Signed volume enclosed by the mesh (positive for outward-facing CCW triangles).
double signed_volume(const TriangleMesh& m) {
  double six_v = 0.0;
  for (const auto& t : m.triangles) {
    six_v += m.vertices_m[t[0]].dot(m.vertices_m[t[1]].cross(m.vertices_m[t[2]]));
  }
  return six_v / 6.0;
}

double surface_area(const TriangleMesh& m) {
  double a = 0.0;
  for (const auto& t : m.triangles) {
    a += 0.5 * (m.vertices_m[t[1]] - m.vertices_m[t[0]]).cross(m.vertices_m[t[2]] - m.vertices_m[t[0]]).norm();
  }
  return a;
}

/// Every directed edge appears exactly once and its reverse exactly once: each edge is
/// shared by exactly two triangles that walk it in opposite directions.
::testing::AssertionResult is_closed_and_consistent(const TriangleMesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : m.triangles) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[static_cast<std::size_t>(k)];
      const std::uint32_t b = t[static_cast<std::size_t>((k + 1) % 3)];
      if (a >= m.vertices_m.size() || b >= m.vertices_m.size()) {
        return ::testing::AssertionFailure() << "index out of range";
      }
      if (a == b) return ::testing::AssertionFailure() << "degenerate triangle";
      ++directed[{a, b}];
    }
  }
  for (const auto& [edge, count] : directed) {
    if (count != 1) {
      return ::testing::AssertionFailure()
             << "directed edge " << edge.first << "->" << edge.second << " used " << count << " times";
    }
    const auto rev = directed.find({edge.second, edge.first});
    if (rev == directed.end()) {
      return ::testing::AssertionFailure()
             << "edge " << edge.first << "-" << edge.second << " has only one triangle (hole or flipped triangle)";
    }
  }
  return ::testing::AssertionSuccess();
}

std::size_t edge_count(const TriangleMesh& m) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const auto& t : m.triangles) {
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = t[static_cast<std::size_t>(k)];
      std::uint32_t b = t[static_cast<std::size_t>((k + 1) % 3)];
      if (a > b) std::swap(a, b);
      edges.insert({a, b});
    }
  }
  return edges.size();
}

/// No two vertices at the same position (seams share their vertices).
bool positions_unique(const TriangleMesh& m) {
  std::set<std::tuple<double, double, double>> seen;
  for (const auto& v : m.vertices_m) {
    if (!seen.insert({v.x(), v.y(), v.z()}).second) return false;
  }
  return true;
}

/// Every face normal points away from the origin (shapes centred on the origin are
/// convex, so the origin is inside and behind every outward face).
bool faces_point_away_from_origin(const TriangleMesh& m) {
  for (const auto& t : m.triangles) {
    const Eigen::Vector3d& a = m.vertices_m[t[0]];
    const Eigen::Vector3d n = (m.vertices_m[t[1]] - a).cross(m.vertices_m[t[2]] - a);
    if (!(n.dot(a) > 0.0)) return false;
  }
  return true;
}

/// Smallest distance from the origin to a face plane: a convex mesh with all face
/// planes at least this far contains the ball of that radius.
double min_face_plane_distance(const TriangleMesh& m) {
  double d = std::numeric_limits<double>::infinity();
  for (const auto& t : m.triangles) {
    const Eigen::Vector3d& a = m.vertices_m[t[0]];
    const Eigen::Vector3d n = (m.vertices_m[t[1]] - a).cross(m.vertices_m[t[2]] - a).normalized();
    d = std::min(d, n.dot(a));
  }
  return d;
}

void expect_unit_outward_normals(const TriangleMesh& m) {
  ASSERT_EQ(m.vertex_normals.size(), m.vertices_m.size());
  for (std::size_t i = 0; i < m.vertex_normals.size(); ++i) {
    EXPECT_NEAR(m.vertex_normals[i].norm(), 1.0f, kUnitFloat) << "vertex " << i;
    EXPECT_GT(m.vertex_normals[i].cast<double>().dot(m.vertices_m[i]), 0.0) << "vertex " << i;
  }
}

void expect_closed_primitive(const TriangleMesh& m) {
  EXPECT_TRUE(is_closed_and_consistent(m));
  EXPECT_TRUE(positions_unique(m));
  EXPECT_TRUE(faces_point_away_from_origin(m));
  // Genus 0: V - E + F = 2.
  EXPECT_EQ(static_cast<long long>(m.vertices_m.size()) - static_cast<long long>(edge_count(m)) +
                static_cast<long long>(m.triangles.size()),
            2);
  expect_unit_outward_normals(m);
}

TEST(PrimitiveMesh, PlaneIsTwoUpwardTrianglesOfTheRightArea) {
  const TriangleMesh m = make_plane_mesh(2.0, 0.5);
  ASSERT_EQ(m.triangle_count(), 2u);
  ASSERT_EQ(m.vertices_m.size(), 4u);
  for (const auto& t : m.triangles) {
    const Eigen::Vector3d n =
        (m.vertices_m[t[1]] - m.vertices_m[t[0]]).cross(m.vertices_m[t[2]] - m.vertices_m[t[0]]);
    EXPECT_GT(n.z(), 0.0);
    EXPECT_NEAR(n.normalized().dot(Eigen::Vector3d::UnitZ()), 1.0, 1e-15);
  }
  EXPECT_NEAR(surface_area(m), 1.0, 1e-15);
  const auto box = mesh_bounds(m);
  EXPECT_TRUE(box.min().isApprox(Eigen::Vector3d(-1.0, -0.25, 0.0)));
  EXPECT_TRUE(box.max().isApprox(Eigen::Vector3d(1.0, 0.25, 0.0)));
  ASSERT_EQ(m.vertex_normals.size(), 4u);
  for (const auto& n : m.vertex_normals) EXPECT_EQ(n, Eigen::Vector3f::UnitZ());
}

TEST(PrimitiveMesh, BoxIsClosedOutwardWithExactVolume) {
  const Eigen::Vector3d size(0.3, 0.2, 0.1);
  const TriangleMesh m = make_box_mesh(size);
  EXPECT_EQ(m.triangle_count(), 12u);
  EXPECT_EQ(m.vertices_m.size(), 8u);
  expect_closed_primitive(m);
  EXPECT_NEAR(signed_volume(m), size.prod(), 1e-15);
  EXPECT_NEAR(surface_area(m), 2.0 * (0.3 * 0.2 + 0.2 * 0.1 + 0.3 * 0.1), 1e-15);
  const auto box = mesh_bounds(m);
  EXPECT_TRUE(box.min().isApprox(-0.5 * size));
  EXPECT_TRUE(box.max().isApprox(0.5 * size));
}

TEST(PrimitiveMesh, IcosphereCountsClosednessAndVolume) {
  const double r = 0.05;
  const double exact = 4.0 / 3.0 * kPi * r * r * r;
  double previous_error = std::numeric_limits<double>::infinity();
  for (int n = 0; n <= 5; ++n) {
    SCOPED_TRACE(n);
    const TriangleMesh m = make_sphere_mesh(r, n);
    const std::size_t four_n = std::size_t{1} << (2 * n);
    EXPECT_EQ(m.triangle_count(), 20 * four_n);
    EXPECT_EQ(m.vertices_m.size(), 10 * four_n + 2);
    expect_closed_primitive(m);
    for (const auto& v : m.vertices_m) EXPECT_NEAR(v.norm(), r, 1e-15);
    for (std::size_t i = 0; i < m.vertices_m.size(); ++i) {
      EXPECT_NEAR(m.vertex_normals[i].cast<double>().dot(m.vertices_m[i].normalized()), 1.0, 1e-6);
    }
    // Inscribed convex polyhedron: it lies inside the sphere and contains the ball
    // touching its nearest face plane.
    const double v = signed_volume(m);
    const double d = min_face_plane_distance(m);
    EXPECT_LT(v, exact);
    EXPECT_GE(v, 4.0 / 3.0 * kPi * d * d * d * (1.0 - 1e-12));
    const double error = (exact - v) / exact;
    EXPECT_LT(error, previous_error);  // refinement converges
    previous_error = error;
  }
  EXPECT_LT(previous_error, 0.005);  // 20480 triangles: well under 0.5 %
}

TEST(PrimitiveMesh, IcosphereHighestSubdivision) {
  const TriangleMesh m = make_sphere_mesh(1.0, 7);
  EXPECT_EQ(m.triangle_count(), 20u * 16384u);
  EXPECT_EQ(m.vertices_m.size(), 10u * 16384u + 2u);
  EXPECT_NEAR(signed_volume(m), 4.0 / 3.0 * kPi, 4.0 / 3.0 * kPi * 1e-4);
}

TEST(PrimitiveMesh, UvSphereCountsClosednessAndVolume) {
  const double r = 0.2;
  const double exact = 4.0 / 3.0 * kPi * r * r * r;
  for (const auto& [rings, segments] : {std::pair{2, 3}, std::pair{3, 4}, std::pair{8, 16},
                                        std::pair{64, 128}, std::pair{31, 7}}) {
    SCOPED_TRACE(::testing::Message() << rings << "x" << segments);
    const TriangleMesh m = make_uv_sphere_mesh(r, rings, segments);
    EXPECT_EQ(m.triangle_count(), static_cast<std::size_t>(2 * segments * (rings - 1)));
    EXPECT_EQ(m.vertices_m.size(), static_cast<std::size_t>(segments * (rings - 1) + 2));
    expect_closed_primitive(m);
    for (const auto& v : m.vertices_m) EXPECT_NEAR(v.norm(), r, 1e-15);
    const double v = signed_volume(m);
    const double d = min_face_plane_distance(m);
    EXPECT_LT(v, exact);
    EXPECT_GE(v, 4.0 / 3.0 * kPi * d * d * d * (1.0 - 1e-12));
  }
  // Fine tessellation approaches the sphere.
  const TriangleMesh fine = make_uv_sphere_mesh(r, 64, 128);
  EXPECT_NEAR(signed_volume(fine), exact, exact * 0.002);
  // Poles are single vertices on the axis.
  const auto box = mesh_bounds(fine);
  EXPECT_NEAR(box.max().z(), r, 1e-15);
  EXPECT_NEAR(box.min().z(), -r, 1e-15);
}

TEST(PrimitiveMesh, CylinderCountsClosednessAndVolume) {
  const double r = 0.03, h = 0.12;
  for (int segments : {3, 4, 7, 64}) {
    SCOPED_TRACE(segments);
    const TriangleMesh m = make_cylinder_mesh(r, h, segments);
    EXPECT_EQ(m.triangle_count(), static_cast<std::size_t>(4 * segments));
    EXPECT_EQ(m.vertices_m.size(), static_cast<std::size_t>(2 * segments + 2));
    expect_closed_primitive(m);
    // Inscribed regular prism: base area (S/2) r^2 sin(2 pi / S).
    const double s = segments;
    const double prism = 0.5 * s * r * r * std::sin(2.0 * kPi / s) * h;
    EXPECT_NEAR(signed_volume(m), prism, prism * 1e-12);
    EXPECT_LE(signed_volume(m), kPi * r * r * h);
    const auto box = mesh_bounds(m);
    EXPECT_NEAR(box.min().z(), -h / 2, 1e-15);
    EXPECT_NEAR(box.max().z(), h / 2, 1e-15);
    for (const auto& v : m.vertices_m) EXPECT_LE(v.head<2>().norm(), r * (1 + 1e-15));
  }
  EXPECT_NEAR(signed_volume(make_cylinder_mesh(r, h, 256)), kPi * r * r * h, kPi * r * r * h * 1e-3);
}

TEST(PrimitiveMesh, InvalidParametersThrow) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)make_plane_mesh(0.0, 1.0), std::invalid_argument);
  EXPECT_THROW((void)make_plane_mesh(1.0, nan), std::invalid_argument);
  EXPECT_THROW((void)make_box_mesh(Eigen::Vector3d(1, -1, 1)), std::invalid_argument);
  EXPECT_THROW((void)make_sphere_mesh(-1.0, 2), std::invalid_argument);
  EXPECT_THROW((void)make_sphere_mesh(1.0, 8), std::invalid_argument);
  EXPECT_THROW((void)make_sphere_mesh(1.0, -1), std::invalid_argument);
  EXPECT_THROW((void)make_uv_sphere_mesh(1.0, 1, 8), std::invalid_argument);
  EXPECT_THROW((void)make_uv_sphere_mesh(1.0, 8, 2), std::invalid_argument);
  EXPECT_THROW((void)make_cylinder_mesh(1.0, 0.0, 8), std::invalid_argument);
  EXPECT_THROW((void)make_cylinder_mesh(1.0, 1.0, 2), std::invalid_argument);
  EXPECT_THROW((void)make_cylinder_mesh(std::numeric_limits<double>::infinity(), 1.0, 8),
               std::invalid_argument);
}

}  // namespace
}  // namespace mhd
