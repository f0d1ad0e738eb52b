#include "geometry/coherent_winding.h"

#include "geometry/primitive_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace mhd {
namespace {

using V = Eigen::Vector3d;

// Edges that two triangles walk the same way (neighbours wound against each other).
std::size_t edges_walked_twice(const TriangleMesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> walked;
  for (const auto& t : m.triangles) {
    for (std::size_t k = 0; k < 3; ++k) ++walked[{t[k], t[(k + 1) % 3]}];
  }
  std::size_t twice = 0;
  for (const auto& [edge, n] : walked) twice += n > 1 ? 1 : 0;
  return twice;
}

void flip(TriangleMesh& m, std::size_t t) { std::swap(m.triangles[t][1], m.triangles[t][2]); }

TEST(CoherentWinding, EveryPrimitiveIsLeftAsMade) {
  for (const TriangleMesh& made : {make_box_mesh(V(0.1, 0.2, 0.3)), make_sphere_mesh(0.1, 3),
                                   make_uv_sphere_mesh(0.1, 16, 32), make_capsule_mesh(0.05, 0.2, 8, 16),
                                   make_cylinder_mesh(0.05, 0.2, 24), make_plane_mesh(1.0, 2.0)}) {
    TriangleMesh m = made;
    EXPECT_EQ(orient_coherently(m), 0U);
    EXPECT_TRUE(m.triangles == made.triangles);
  }
}

TEST(CoherentWinding, ATriangleTurnedOnAClosedMeshIsTurnedBackWhereverItIs) {
  // Each triangle of a sphere in turn (the first met included, whose winding a surface
  // does not simply take): the one turned is the one turned back.
  const TriangleMesh made = make_sphere_mesh(0.1, 2);
  for (std::size_t t = 0; t < made.triangle_count(); ++t) {
    TriangleMesh m = made;
    flip(m, t);
    ASSERT_EQ(orient_coherently(m), 1U) << t;
    ASSERT_TRUE(m.triangles == made.triangles) << t;
  }
}

TEST(CoherentWinding, SheetsMeetingAtAnEdgeOfThreeAreEachTheirOwnSurface) {
  // Three square sheets hinged on the z axis (a book's pages, an edge three triangles
  // share), the middle one wound the other way: no neighbour across that edge, so each
  // sheet keeps its winding. Then a fourth sheet joined to the first along its far edge,
  // wound against it: turned.
  TriangleMesh m;
  m.vertices_m = {V(0, 0, 0), V(0, 0, 1)};
  for (int page = 0; page < 3; ++page) {
    const double a = 2.0 * std::numbers::pi * page / 3.0;
    const V out(std::cos(a), std::sin(a), 0.0);
    const auto b = static_cast<std::uint32_t>(m.vertices_m.size());
    m.vertices_m.push_back(out);
    m.vertices_m.push_back(out + V(0, 0, 1));
    if (page == 1) {
      m.triangles.push_back({0, b + 1, b});
      m.triangles.push_back({0, 1, b + 1});
    } else {
      m.triangles.push_back({0, b, b + 1});
      m.triangles.push_back({0, b + 1, 1});
    }
  }
  TriangleMesh book = m;
  EXPECT_EQ(orient_coherently(book), 0U);
  EXPECT_TRUE(book.triangles == m.triangles);

  // The first page's far edge is vertices 2 -> 3 in its first triangle {0, 2, 3}.
  const auto b = static_cast<std::uint32_t>(m.vertices_m.size());
  m.vertices_m.push_back(V(2, 0, 0));
  m.vertices_m.push_back(V(2, 0, 1));
  m.triangles.push_back({2, 3, b});  // walks 2 -> 3 as its neighbour does: wound against it
  EXPECT_EQ(orient_coherently(m), 1U);
  EXPECT_EQ(m.triangles.back(), (TriangleIndices{2, b, 3}));
}

TEST(CoherentWinding, AFanOfAQuarterMillionTrianglesRoundOneVertexIsWorkedInBoundedTime) {
  // A disc of 2^18 triangles round its centre, wound one way, then with one turned: the
  // centre has 2^18 edges leaving it, which compared pair by pair would take 2^35 steps.
  constexpr std::uint32_t kRim = 1U << 18;
  TriangleMesh made;
  made.vertices_m.push_back(V::Zero());
  for (std::uint32_t k = 0; k < kRim; ++k) {
    const double a = 2.0 * std::numbers::pi * k / kRim;
    made.vertices_m.push_back(V(std::cos(a), std::sin(a), 0.0));
  }
  for (std::uint32_t k = 0; k < kRim; ++k) made.triangles.push_back({0, 1 + k, 1 + (k + 1) % kRim});
  TriangleMesh m = made;
  EXPECT_EQ(orient_coherently(m), 0U);
  flip(m, kRim / 3);
  EXPECT_EQ(orient_coherently(m), 1U);
  EXPECT_TRUE(m.triangles == made.triangles);
}

TEST(CoherentWinding, ASurfaceWithNoWindingEndsWithOneSeam) {
  // A Moebius strip has no consistent winding: whatever is done, some edge is walked
  // twice. Every other edge agrees, and the work ends.
  TriangleMesh m;
  constexpr int kSegments = 24;
  for (int k = 0; k < kSegments; ++k) {
    const double a = 2.0 * std::numbers::pi * k / kSegments;
    const V centre(std::cos(a), std::sin(a), 0.0);
    const V across = 0.2 * (std::cos(a / 2) * centre + std::sin(a / 2) * V(0, 0, 1));
    m.vertices_m.push_back(centre - across);
    m.vertices_m.push_back(centre + across);
  }
  for (int k = 0; k < kSegments; ++k) {
    const auto i = static_cast<std::uint32_t>(2 * k);
    // The last segment joins the first with its sides swapped: the half twist.
    const bool last = k == kSegments - 1;
    const std::uint32_t j0 = last ? 1U : i + 2, j1 = last ? 0U : i + 3;
    m.triangles.push_back({i, j0, j1});
    m.triangles.push_back({i, j1, i + 1});
  }
  EXPECT_GE(edges_walked_twice(m), 1U);
  (void)orient_coherently(m);
  EXPECT_EQ(edges_walked_twice(m), 1U);
}

}  // namespace
}  // namespace mhd
