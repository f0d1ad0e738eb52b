// A mesh put in its tree's leaf order (MeshBvh::MeshOrder::Leaves): the same triangles,
// corners and normals, renumbered so that leaf k names triangle k and each vertex is
// numbered where a triangle first uses it; the tree answers every query with the same
// triangles as one built over the given order, and its serialized form passes the check.

#include "collision/collision_world.h"
#include "collision/mesh_bvh.h"
#include "collision/segment_triangle.h"
#include "support/large_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <vector>

namespace mhd {
namespace {

using Corners = std::array<std::array<double, 3>, 3>;

std::array<double, 3> key(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

Corners corners(const TriangleMesh& mesh, std::uint32_t t) {
  Corners c{};
  for (std::size_t i = 0; i < 3; ++i) c[i] = key(mesh.vertices_m[mesh.triangles[t][i]]);
  return c;
}

/// A wavy n x n grid of quads, its triangles shuffled (so the given order is far from any
/// tree's), with vertex normals and one vertex no triangle uses (the first).
std::shared_ptr<TriangleMesh> shuffled_wavy_grid(int n) {
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices_m.emplace_back(5.0, 5.0, 5.0);  // unused
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      mesh->vertices_m.emplace_back(double(i) / n, double(j) / n, 0.05 * std::sin(0.3 * i) * std::cos(0.2 * j));
    }
  }
  const auto id = [n](int i, int j) { return static_cast<std::uint32_t>(1 + j * (n + 1) + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      mesh->triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh->triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  std::mt19937 rng(77);
  std::shuffle(mesh->triangles.begin(), mesh->triangles.end(), rng);
  compute_vertex_normals(*mesh);
  return mesh;
}

/// The triangles a query of `box` reports, as their corners (numbering aside).
std::vector<Corners> reported_corners(const MeshBvh& bvh, const Eigen::AlignedBox3d& box) {
  std::vector<Corners> out;
  bvh.for_each_triangle_overlapping(box, [&](std::uint32_t t) { out.push_back(corners(bvh.mesh(), t)); });
  std::sort(out.begin(), out.end());
  return out;
}

/// Every leaf in walk order names the next triangle: 0, 1, 2 ...
void expect_leaves_in_order(const MeshBvh& bvh) {
  std::uint32_t next = 0;
  bool in_order = true;
  bvh.for_each_triangle_overlapping(bvh.bounds(), [&](std::uint32_t t) { in_order = in_order && t == next++; });
  EXPECT_TRUE(in_order);
  EXPECT_EQ(next, bvh.mesh().triangle_count());
}

void expect_same_mesh_renumbered(const TriangleMesh& given, const MeshBvh& ordered_bvh) {
  const TriangleMesh& ordered = ordered_bvh.mesh();
  ASSERT_NE(&ordered, &given);
  ASSERT_EQ(ordered.triangle_count(), given.triangle_count());
  ASSERT_EQ(ordered.vertices_m.size(), given.vertices_m.size());
  ASSERT_EQ(ordered.vertex_normals.size(), given.vertex_normals.size());
  // The same triangles, each with its corners in the same turn.
  std::vector<Corners> a, b;
  for (std::uint32_t t = 0; t < given.triangle_count(); ++t) a.push_back(corners(given, t));
  for (std::uint32_t t = 0; t < ordered.triangle_count(); ++t) b.push_back(corners(ordered, t));
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  EXPECT_TRUE(a == b);
  // Vertices numbered by first use, and each keeps its normal.
  std::map<std::array<double, 3>, Eigen::Vector3f> normal_at;
  for (std::size_t v = 0; v < given.vertices_m.size(); ++v) {
    normal_at[key(given.vertices_m[v])] = given.vertex_normals.empty() ? Eigen::Vector3f::Zero() : given.vertex_normals[v];
  }
  std::uint32_t seen = 0;
  bool first_use_order = true;
  for (const auto& t : ordered.triangles) {
    for (const std::uint32_t v : t) {
      if (v == seen) ++seen;
      first_use_order = first_use_order && v < seen;
    }
  }
  EXPECT_TRUE(first_use_order);
  for (std::size_t v = 0; v < ordered.vertices_m.size(); ++v) {
    const auto it = normal_at.find(key(ordered.vertices_m[v]));
    ASSERT_NE(it, normal_at.end()) << "vertex " << v << " is not one of the given";
    if (!ordered.vertex_normals.empty()) {
      EXPECT_EQ(ordered.vertex_normals[v], it->second) << "vertex " << v;
    }
  }
  // The face normals are the renumbered triangles' own.
  for (std::uint32_t t = 0; t < ordered.triangle_count(); ++t) {
    const auto& c = ordered.triangles[t];
    ASSERT_EQ(ordered_bvh.face_normal_O(t),
              unit_face_normal(ordered.vertices_m[c[0]], ordered.vertices_m[c[1]], ordered.vertices_m[c[2]]))
        << "triangle " << t;
  }
}

TEST(LeafOrder, TheMeshIsRenumberedInLeafOrderAndAnswersAsTheGivenOne) {
  const auto given = shuffled_wavy_grid(40);
  const MeshBvh as_given(given);
  const MeshBvh ordered(given, MeshBvh::MeshOrder::Leaves);
  expect_same_mesh_renumbered(*given, ordered);
  expect_leaves_in_order(ordered);
  EXPECT_EQ(ordered.mesh().vertices_m.back(), Eigen::Vector3d(5.0, 5.0, 5.0)) << "the unused vertex comes last";
  EXPECT_EQ(&as_given.mesh(), given.get()) << "the given order stays the default";
  EXPECT_TRUE(ordered.bounds().isApprox(as_given.bounds()));
  // The given order was scattered: had it been the leaves' already, this would not test much.
  std::uint32_t next = 0;
  bool given_in_order = true;
  as_given.for_each_triangle_overlapping(as_given.bounds(), [&](std::uint32_t t) { given_in_order = given_in_order && t == next++; });
  EXPECT_FALSE(given_in_order);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.1, 1.1);
  for (int i = 0; i < 300; ++i) {
    const Eigen::Vector3d c(u(rng), u(rng), 0.1 * u(rng) - 0.05);
    const Eigen::Vector3d half = Eigen::Vector3d::Constant(0.002 + 0.1 * (u(rng) + 0.1) * (u(rng) + 0.1));
    const Eigen::AlignedBox3d box(c - half, c + half);
    ASSERT_EQ(reported_corners(ordered, box), reported_corners(as_given, box)) << "box " << i;
  }
  // What the cache stores: the renumbered mesh and its tree, adopted after the full check.
  const auto adopted = MeshBvh::from_serialized(ordered.mesh_ptr(), ordered.serialize_bvh());
  ASSERT_NE(adopted, nullptr);
  expect_leaves_in_order(*adopted);
}

TEST(LeafOrder, AMeshPastOneBulletPartIsRenumberedAndItsPatchStillStopsTheHand) {
  // Built in pieces: the leaves past 2^21 name triangles past 2^21 of the new order, and
  // the patch above the grid (the given mesh's last triangles) still stops a sweep.
  const auto given = test::mesh_past_one_bullet_part();
  const auto ordered = std::make_shared<const MeshBvh>(given, MeshBvh::MeshOrder::Leaves);
  ASSERT_GT(ordered->mesh().triangle_count(), std::size_t{1} << 21);
  expect_leaves_in_order(*ordered);
  CollisionWorld world;
  (void)world.add_object(ordered, Pose::Identity());
  const auto hit = world.sweep(Eigen::Vector3d(0.503, 0.497, 1.0), Eigen::Vector3d(0.503, 0.497, 0.2), 1e-4);
  ASSERT_TRUE(hit) << "the hand passed through the patch";
  EXPECT_NEAR(hit->plane_offset_m, 0.5, 1e-12);
  const auto& c = ordered->mesh().triangles[hit->where.triangle];
  for (const auto v : c) EXPECT_EQ(ordered->mesh().vertices_m[v].z(), 0.5);
  // The last triangles of the new order are found where they lie, by the built tree and
  // by the adopted one.
  const auto adopted = MeshBvh::from_serialized(ordered->mesh_ptr(), ordered->serialize_bvh());
  ASSERT_NE(adopted, nullptr);
  const std::uint32_t last = static_cast<std::uint32_t>(ordered->mesh().triangle_count() - 1);
  Eigen::AlignedBox3d box;
  for (const auto v : ordered->mesh().triangles[last]) box.extend(ordered->mesh().vertices_m[v]);
  for (const MeshBvh* bvh : std::array<const MeshBvh*, 2>{ordered.get(), adopted.get()}) {
    bool found = false;
    bvh->for_each_triangle_overlapping(box, [&](std::uint32_t t) { found = found || t == last; });
    EXPECT_TRUE(found);
  }
}

TEST(LeafOrder, AMeshWithAStrayTriangleIsAdoptedInLeafOrderOnTheGridItWasBuiltOn) {
  // A stray triangle 1000 km away makes the tree's grid span the mesh's bulk, found from a
  // sample of its vertices (over 65,536 of them here, so a sample it is). The cache stores
  // the mesh renumbered in leaf order: the same sample must come from it, or its tree
  // would fail the check on every load and be built again.
  const auto given = shuffled_wavy_grid(300);
  const auto first = static_cast<std::uint32_t>(given->vertices_m.size());
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(1e6, 0, 0), Eigen::Vector3d(1e6 + 1, 0, 0), Eigen::Vector3d(1e6, 1, 0)}) {
    given->vertices_m.push_back(p);
    given->vertex_normals.emplace_back(0.0f, 0.0f, 1.0f);
  }
  given->triangles.push_back({first, first + 1, first + 2});
  ASSERT_GT(given->vertices_m.size(), std::size_t{1} << 16);
  const MeshBvh ordered(given, MeshBvh::MeshOrder::Leaves);
  const auto adopted = MeshBvh::from_serialized(ordered.mesh_ptr(), ordered.serialize_bvh());
  ASSERT_NE(adopted, nullptr);
  const Eigen::AlignedBox3d near(Eigen::Vector3d(0.5, 0.5, -0.06), Eigen::Vector3d(0.501, 0.501, 0.06));
  for (const MeshBvh* bvh : std::array<const MeshBvh*, 2>{&ordered, adopted.get()}) {
    std::size_t found = 0;
    bvh->for_each_triangle_overlapping(near, [&](std::uint32_t) { ++found; });
    EXPECT_GT(found, 0u);
    EXPECT_LE(found, 64u) << "a grid over the 1000 km holds the whole grid in one cell";
  }
}

}  // namespace
}  // namespace mhd
