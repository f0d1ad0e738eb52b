// Meshes past the 2^21 triangles that one Bullet part can index: every leaf of the tree
// must still name the triangle it bounds, in a tree built here and in one adopted from
// its serialized form (the mesh cache).

#include "collision/collision_world.h"
#include "support/large_mesh.h"
#include "collision/mesh_bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <vector>

namespace mhd {
namespace {

using test::kPatchFirstTriangle;

std::vector<std::uint32_t> reported(const MeshBvh& bvh, const Eigen::AlignedBox3d& box_O) {
  std::vector<std::uint32_t> out;
  bvh.for_each_triangle_overlapping(box_O, [&](std::uint32_t t) { out.push_back(t); });
  std::sort(out.begin(), out.end());
  return out;
}

// The triangles whose own bounds overlap box_O: what any tree must report (and may add to).
std::vector<std::uint32_t> overlapping(const TriangleMesh& mesh, const Eigen::AlignedBox3d& box_O) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t t = 0; t < mesh.triangle_count(); ++t) {
    Eigen::AlignedBox3d b;
    for (auto v : mesh.triangles[t]) b.extend(mesh.vertices_m[v]);
    if (b.intersects(box_O)) out.push_back(t);
  }
  return out;
}

void expect_names_the_patch(const MeshBvh& bvh, const char* which) {
  SCOPED_TRACE(which);
  const TriangleMesh& mesh = bvh.mesh();
  // Only the last triangles (the patch at z = 0.5) lie in this box.
  const Eigen::AlignedBox3d box_O(Eigen::Vector3d(0.45, 0.45, 0.4), Eigen::Vector3d(0.55, 0.55, 0.6));
  const auto must = overlapping(mesh, box_O);
  ASSERT_FALSE(must.empty());
  ASSERT_GE(must.front(), kPatchFirstTriangle);
  const auto got = reported(bvh, box_O);
  EXPECT_TRUE(std::includes(got.begin(), got.end(), must.begin(), must.end()))
      << got.size() << " reported, " << must.size() << " overlap";
  for (const std::uint32_t t : got) {
    ASSERT_LT(t, mesh.triangle_count());
    EXPECT_GE(t, kPatchFirstTriangle) << "a leaf names triangle " << t << ", which is far from its box";
  }

  // The hand comes down onto the patch: the sweep stops on it, at the triangle it hit.
  CollisionWorld world;
  const int id = world.add_object(std::shared_ptr<const MeshBvh>(&bvh, [](const MeshBvh*) {}), Pose::Identity());
  const auto hit = world.sweep(Eigen::Vector3d(0.503, 0.497, 1.0), Eigen::Vector3d(0.503, 0.497, 0.2), 1e-4);
  ASSERT_TRUE(hit) << "the hand passed through the last triangles";
  EXPECT_EQ(hit->where.object, id);
  EXPECT_GE(hit->where.triangle, kPatchFirstTriangle);
  EXPECT_NEAR(hit->plane_offset_m, 0.5, 1e-12);
  // Below the patch the grid at z = 0, the first triangles, is found as well.
  const auto grid = world.sweep(Eigen::Vector3d(0.9, 0.9, 0.2), Eigen::Vector3d(0.9, 0.9, -0.2), 1e-4);
  ASSERT_TRUE(grid);
  EXPECT_LT(grid->where.triangle, kPatchFirstTriangle);
}

TEST(LargeMesh, LeavesPastTwoToTheTwentyOneNameTheirTrianglesBuiltAndAdopted) {
  const auto mesh = test::mesh_past_one_bullet_part();
  ASSERT_GT(mesh->triangle_count(), std::size_t{1} << 21);
  const MeshBvh built(mesh);
  expect_names_the_patch(built, "built");
  // The serialized tree (what the cache stores) is adopted, not refused, and answers alike.
  const auto adopted = MeshBvh::from_serialized(mesh, built.serialize_bvh());
  ASSERT_NE(adopted, nullptr) << "a valid tree of a mesh past 2^21 triangles was refused";
  expect_names_the_patch(*adopted, "adopted");
}

/// A serialized tree of mesh_past_one_bullet_part() and where its nodes lie in it: large
/// enough (over 2^20 nodes) that an adopted copy is checked as two halves on two threads.
struct SerializedLargeTree {
  std::shared_ptr<TriangleMesh> mesh = test::mesh_past_one_bullet_part();
  std::vector<std::byte> bytes;
  std::size_t nodes_at = 0, node_count = 0, first_end = 0;  // first_end: where the root's second subtree starts

  SerializedLargeTree() {
    const MeshBvh built(mesh);
    bytes = built.serialize_bvh();
    auto& shape = const_cast<btBvhTriangleMeshShape&>(built.shape());  // NOLINT: Bullet is not const-correct
    auto& nodes = shape.getOptimizedBvh()->getQuantizedNodeArray();
    node_count = static_cast<std::size_t>(nodes[0].getEscapeIndex());
    first_end = 1 + (nodes[1].isLeafNode() ? 1 : static_cast<std::size_t>(nodes[1].getEscapeIndex()));
    // Bullet's format: the tree object, then its nodes.
    nodes_at = sizeof(btQuantizedBvh) + btQuantizedBvh::getAlignmentSerializationPadding();
    if (std::memcmp(bytes.data() + nodes_at, &nodes[0], node_count * sizeof(btQuantizedBvhNode)) != 0) nodes_at = 0;
  }
  btQuantizedBvhNode* node(std::vector<std::byte>& copy, std::size_t i) const {
    return reinterpret_cast<btQuantizedBvhNode*>(copy.data() + nodes_at) + i;
  }
  std::size_t leaf_from(std::vector<std::byte>& copy, std::size_t i) const {
    while (!node(copy, i)->isLeafNode()) ++i;
    return i;
  }
};

TEST(LargeMesh, ATreeCheckedInTwoHalvesRefusesAFaultInEitherHalfAndAcceptsAWholeOne) {
  static const SerializedLargeTree tree;
  ASSERT_NE(tree.nodes_at, 0u) << "the nodes lie after the tree object";
  ASSERT_GE(tree.node_count, std::size_t{1} << 20);
  ASSERT_GT(tree.first_end, 2u);
  ASSERT_LT(tree.first_end, tree.node_count);
  // Whole, it is adopted and answers.
  const auto whole = MeshBvh::from_serialized(tree.mesh, tree.bytes);
  ASSERT_NE(whole, nullptr);
  expect_names_the_patch(*whole, "checked in two halves");

  const auto refused = [&](const char* what, const std::function<void(std::vector<std::byte>&)>& edit) {
    auto copy = tree.bytes;
    edit(copy);
    EXPECT_EQ(MeshBvh::from_serialized(tree.mesh, copy), nullptr) << what;
  };
  refused("a leaf of the second half naming a triangle of the first", [&](std::vector<std::byte>& c) {
    const std::size_t a = tree.leaf_from(c, tree.first_end / 2);
    const std::size_t b = tree.leaf_from(c, tree.first_end + (tree.node_count - tree.first_end) / 2);
    tree.node(c, b)->m_escapeIndexOrTriangleIndex = tree.node(c, a)->m_escapeIndexOrTriangleIndex;
  });
  refused("a leaf of the first half naming a triangle of the second", [&](std::vector<std::byte>& c) {
    const std::size_t a = tree.leaf_from(c, tree.first_end / 3);
    const std::size_t b = tree.leaf_from(c, tree.node_count - 9);
    tree.node(c, a)->m_escapeIndexOrTriangleIndex = tree.node(c, b)->m_escapeIndexOrTriangleIndex;
  });
  refused("a leaf box of the second half shrunk off its triangle", [&](std::vector<std::byte>& c) {
    btQuantizedBvhNode* leaf = tree.node(c, tree.leaf_from(c, tree.node_count - 100));
    leaf->m_quantizedAabbMax[1] = leaf->m_quantizedAabbMin[1];
  });
  refused("the first subtree spanning into the second", [&](std::vector<std::byte>& c) {
    tree.node(c, 1)->m_escapeIndexOrTriangleIndex -= 2;  // stored negated: two nodes further
  });
  refused("the first subtree ending early", [&](std::vector<std::byte>& c) {
    tree.node(c, 1)->m_escapeIndexOrTriangleIndex += 2;
  });
  refused("an inner node of the second half turned leaf", [&](std::vector<std::byte>& c) {
    std::size_t inner = tree.first_end + 1;
    while (tree.node(c, inner)->isLeafNode()) ++inner;
    tree.node(c, inner)->m_escapeIndexOrTriangleIndex = 0;
  });
  refused("the second subtree's root outside the root's box", [&](std::vector<std::byte>& c) {
    btQuantizedBvhNode* root = tree.node(c, 0);
    root->m_quantizedAabbMax[2] = root->m_quantizedAabbMin[2];
  });
}

TEST(LargeMesh, ATreeTooLargeForBulletsSerializedFormatIsNotSerialized) {
  // 2n - 1 nodes for n triangles. 100 M fit the format's 32-bit size; 2^30 - 1 (the most
  // a tree holds) and 135 M do not, and serializing them must refuse, not overrun.
  const auto bytes_for = [](std::uint64_t triangles) { return MeshBvh::serialized_bytes(2 * triangles - 1, 64); };
  EXPECT_LE(bytes_for(100'000'000), MeshBvh::kMaxSerializedBytes);
  EXPECT_GT(bytes_for(135'000'000), MeshBvh::kMaxSerializedBytes);
  EXPECT_GT(bytes_for(MeshBvh::kMaxTriangles), MeshBvh::kMaxSerializedBytes);
  // The count is Bullet's own where both fit: the tree below serializes to exactly it.
  const auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices_m = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  mesh->triangles = {{0, 1, 2}, {1, 3, 2}};
  const MeshBvh small(mesh);
  auto* tree = const_cast<btBvhTriangleMeshShape&>(small.shape()).getOptimizedBvh();
  EXPECT_EQ(small.serialize_bvh().size(),
            MeshBvh::serialized_bytes(3, static_cast<std::uint64_t>(tree->getSubtreeInfoArray().size())));
}

TEST(LargeMesh, TheTreeHoldsEveryCountTheSceneAllows) {
  // Bullet's node array has 2n entries in an int, and a leaf has 10 bits of part and 21
  // of triangle: 2^30 - 1 triangles at most, above the 10^9 a scene may declare.
  EXPECT_TRUE(MeshBvh::holds(1));
  EXPECT_TRUE(MeshBvh::holds((std::uint64_t{1} << 21) + 1));
  EXPECT_TRUE(MeshBvh::holds(1'000'000'000));
  EXPECT_TRUE(MeshBvh::holds(MeshBvh::kMaxTriangles));
  EXPECT_FALSE(MeshBvh::holds(MeshBvh::kMaxTriangles + 1));
  EXPECT_FALSE(MeshBvh::holds(std::uint64_t{1} << 31));
  EXPECT_FALSE(MeshBvh::holds(0));
}

}  // namespace
}  // namespace mhd
