// The tree over the objects' boxes: a query finds exactly the boxes that overlap it (the
// brute-force answer), before and after boxes move, unbounded ones too; it stays about
// log2 of the count deep; and a visit may stop it.
#include "collision/object_tree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <vector>

namespace mhd {
namespace {

Eigen::AlignedBox3d random_box(std::mt19937_64& rng, double spread_m, double size_m) {
  std::uniform_real_distribution<double> at(-spread_m, spread_m);
  std::uniform_real_distribution<double> side(0.0, size_m);
  const Eigen::Vector3d lo(at(rng), at(rng), at(rng));
  return {lo, lo + Eigen::Vector3d(side(rng), side(rng), side(rng))};
}

std::set<int> overlapping(const ObjectTree& tree, const Eigen::AlignedBox3d& box) {
  std::set<int> found;
  tree.for_each_overlapping(box, [&](int object) { EXPECT_TRUE(found.insert(object).second) << object; });
  return found;
}

std::set<int> brute_force(const std::vector<Eigen::AlignedBox3d>& boxes, const Eigen::AlignedBox3d& box) {
  std::set<int> found;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (ObjectTree::overlaps(boxes[i], box)) found.insert(static_cast<int>(i));
  }
  return found;
}

TEST(ObjectTree, AQueryFindsExactlyTheOverlappingBoxesBeforeAndAfterTheyMove) {
  std::mt19937_64 rng(20261205);
  for (const std::size_t n : {std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{17}, std::size_t{1000}}) {
    std::vector<Eigen::AlignedBox3d> boxes;
    for (std::size_t i = 0; i < n; ++i) boxes.push_back(random_box(rng, 10.0, 1.0));
    constexpr double kInf = std::numeric_limits<double>::infinity();
    if (n > 2) {
      // A half-space's box, unbounded on every side, and one unbounded below only.
      boxes[1] = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-kInf), Eigen::Vector3d::Constant(kInf));
      boxes[2].min().z() = -kInf;
    }
    ObjectTree tree;
    tree.rebuild(boxes);
    ASSERT_EQ(tree.object_count(), n);
    EXPECT_LE(tree.depth(), static_cast<int>(std::ceil(std::log2(static_cast<double>(n)))));
    std::size_t hits = 0;
    for (int q = 0; q < 300; ++q) {
      const Eigen::AlignedBox3d query = random_box(rng, 11.0, q % 3 == 0 ? 5.0 : 0.5);
      const std::set<int> found = overlapping(tree, query);
      EXPECT_EQ(found, brute_force(boxes, query)) << "n " << n << " query " << q;
      hits += found.size();
    }
    if (n >= 17) {
      EXPECT_GT(hits, 300U);  // the queries met boxes, not only empty space
    }
    // Moves, far and near: refitted, the tree still answers exactly.
    for (int m = 0; m < 200; ++m) {
      const auto object = static_cast<int>(rng() % n);
      boxes[static_cast<std::size_t>(object)] = random_box(rng, m % 2 == 0 ? 30.0 : 10.0, 1.0);
      tree.update(object, boxes[static_cast<std::size_t>(object)]);
      const Eigen::AlignedBox3d query = random_box(rng, 11.0, 3.0);
      EXPECT_EQ(overlapping(tree, query), brute_force(boxes, query)) << "n " << n << " move " << m;
    }
  }
}

TEST(ObjectTree, BoxesTouchingTheQueryCountAndAVisitMayStopTheWalk) {
  std::vector<Eigen::AlignedBox3d> boxes;
  for (int i = 0; i < 64; ++i) {
    boxes.emplace_back(Eigen::Vector3d(i, 0, 0), Eigen::Vector3d(i + 1.0, 1, 1));  // a row, each touching the next
  }
  ObjectTree tree;
  tree.rebuild(boxes);
  EXPECT_EQ(tree.depth(), 6);
  // A face shared with the query is an overlap (closed boxes).
  EXPECT_EQ(overlapping(tree, Eigen::AlignedBox3d(Eigen::Vector3d(10, 1, 1), Eigen::Vector3d(10, 2, 2))),
            (std::set<int>{9, 10}));
  EXPECT_TRUE(overlapping(tree, Eigen::AlignedBox3d(Eigen::Vector3d(10, 1.5, 0), Eigen::Vector3d(12, 2, 1))).empty());
  int visited = 0;
  tree.for_each_overlapping(Eigen::AlignedBox3d(Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(65, 1, 1)), [&](int) {
    ++visited;
    return visited < 5;
  });
  EXPECT_EQ(visited, 5);
  ObjectTree empty;
  empty.rebuild({});
  EXPECT_TRUE(overlapping(empty, boxes[0]).empty());
}

}  // namespace
}  // namespace mhd
