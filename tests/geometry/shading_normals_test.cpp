#include "geometry/shading_normals.h"

#include "geometry/primitive_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace mhd {
namespace {

using V = Eigen::Vector3d;
constexpr double kDeg = std::numbers::pi / 180.0;

V face_normal(const TriangleMesh& m, std::size_t t) {
  const auto& i = m.triangles[t];
  return (m.vertices_m[i[1]] - m.vertices_m[i[0]]).cross(m.vertices_m[i[2]] - m.vertices_m[i[0]]).normalized();
}

V corner(const ShadingNormals& n, std::size_t t, std::size_t i) { return n.corner_normals_O[t][i].cast<double>(); }

TEST(ShadingNormals, ACubeBelowItsCreaseAngleKeepsEveryCornerOnItsFaceNormal) {
  const TriangleMesh box = make_box_mesh(V(0.1, 0.2, 0.3));
  const ShadingNormals n = compute_shading_normals(box, 60 * kDeg);
  ASSERT_EQ(n.corner_normals_O.size(), box.triangle_count());
  EXPECT_DOUBLE_EQ(n.crease_angle_rad, 60 * kDeg);
  for (std::size_t t = 0; t < box.triangle_count(); ++t) {
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR((corner(n, t, i) - face_normal(box, t)).norm(), 0.0, 1e-7);
  }
}

TEST(ShadingNormals, AboveTheCreaseAngleTheCubeIsSmoothedAndAngleWeighting) {
  // Each face meets a box corner with 90 degrees however it is split into triangles, so
  // angle weighting gives the corner the exact diagonal (area weighting would not: a
  // corner lies in one or two triangles of a face, and the faces differ in size).
  const TriangleMesh box = make_box_mesh(V(0.1, 0.2, 0.3));
  const ShadingNormals n = compute_shading_normals(box, 100 * kDeg);
  for (std::size_t t = 0; t < box.triangle_count(); ++t) {
    for (std::size_t i = 0; i < 3; ++i) {
      const V& p = box.vertices_m[box.triangles[t][i]];
      const V diagonal = V(p.x() > 0 ? 1 : -1, p.y() > 0 ? 1 : -1, p.z() > 0 ? 1 : -1).normalized();
      EXPECT_NEAR((corner(n, t, i) - diagonal).norm(), 0.0, 1e-7) << "triangle " << t << " corner " << i;
    }
  }
}

TEST(ShadingNormals, ACoarseSphereSharesOneNearlyRadialNormalPerVertex) {
  const TriangleMesh sphere = make_sphere_mesh(0.05, 1);  // 80 triangles, faces ~20 degrees apart
  const ShadingNormals smooth = compute_shading_normals(sphere, 60 * kDeg);
  const ShadingNormals faceted = compute_shading_normals(sphere, 0.0);
  double worst_off_radial_rad = 0.0;
  for (std::size_t t = 0; t < sphere.triangle_count(); ++t) {
    for (std::size_t i = 0; i < 3; ++i) {
      const V radial = sphere.vertices_m[sphere.triangles[t][i]].normalized();
      worst_off_radial_rad = std::max(worst_off_radial_rad, std::acos(std::min(1.0, corner(smooth, t, i).dot(radial))));
      // At a crease angle of zero every edge is a crease: the facets stay.
      EXPECT_NEAR((corner(faceted, t, i) - face_normal(sphere, t)).norm(), 0.0, 1e-7);
    }
  }
  // Faces tilt ~10 degrees off the radial at their corners; the shared normals far less.
  EXPECT_LT(worst_off_radial_rad, 1.0 * kDeg);
}

TEST(ShadingNormals, UnweldedCopiesOfAVertexShadeAsOne) {
  // An STL file repeats every vertex per triangle: the normals must not fall back to facets.
  const TriangleMesh welded = make_sphere_mesh(0.05, 1);
  TriangleMesh unwelded;
  for (const auto& t : welded.triangles) {
    const auto base = static_cast<std::uint32_t>(unwelded.vertices_m.size());
    for (const auto i : t) unwelded.vertices_m.push_back(welded.vertices_m[i]);
    unwelded.triangles.push_back({base, base + 1, base + 2});
  }
  const ShadingNormals a = compute_shading_normals(welded, 60 * kDeg);
  const ShadingNormals b = compute_shading_normals(unwelded, 60 * kDeg);
  for (std::size_t t = 0; t < welded.triangle_count(); ++t) {
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR((corner(a, t, i) - corner(b, t, i)).norm(), 0.0, 1e-6);
  }
}

TEST(ShadingNormals, InterpolationIsTheCornerNormalAtACornerAndABlendInside) {
  TriangleMesh m;
  m.vertices_m = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}};
  ShadingNormals n;
  n.corner_normals_O = {{Eigen::Vector3f(0, 0, 1), Eigen::Vector3f(1, 0, 1).normalized(), Eigen::Vector3f(0, 0, 1)}};
  EXPECT_NEAR((interpolated_normal_O(m, n, 0, V(1, 0, 0.3)) - V(1, 0, 1).normalized()).norm(), 0.0, 1e-7);
  EXPECT_NEAR((interpolated_normal_O(m, n, 0, V(0, 0, -0.2)) - V(0, 0, 1)).norm(), 0.0, 1e-7);
  const V mid = interpolated_normal_O(m, n, 0, V(0.5, 0, 0));
  EXPECT_NEAR(mid.norm(), 1.0, 1e-12);
  EXPECT_NEAR(mid.y(), 0.0, 1e-12);
  EXPECT_GT(mid.x(), 0.3);
  // Outside the triangle the weights are clamped: as at the nearest edge point.
  EXPECT_NEAR((interpolated_normal_O(m, n, 0, V(2, -1, 0)) - V(1, 0, 1).normalized()).norm(), 0.0, 1e-7);
}

TEST(ShadingNormals, ADegenerateTriangleGetsNoNormal) {
  TriangleMesh m;
  m.vertices_m = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  m.triangles = {{0, 1, 2}};
  const ShadingNormals n = compute_shading_normals(m, 60 * kDeg);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(corner(n, 0, i), V::Zero());
  EXPECT_EQ(interpolated_normal_O(m, n, 0, V(0.5, 0, 0)), V::Zero());
}

}  // namespace
}  // namespace mhd
