#pragma once
// A tree over the boxes of the world's objects, so that a sweep visits only the objects
// whose boxes it comes near: a scene of thousands of objects then costs a sweep about
// what a scene of a few does. Built top down for a set of boxes, each node split at the
// median of its centres along their longest spread, so its depth stays about log2 of
// the count. A box that changes (an object moved) is refitted up to the root: that
// allocates nothing, so the haptic thread may move objects.

#include <Eigen/Geometry>

#include <array>
#include <cstddef>
#include <span>
#include <type_traits>
#include <vector>

namespace mhd {

class ObjectTree {
 public:
  /// Most levels a tree has: a median split of 2^31 boxes takes 33.
  static constexpr int kMaxDepth = 64;

  /// The tree over boxes[0..n), box i being object i's. Boxes may be unbounded (an
  /// infinite half-space), never empty.
  void rebuild(std::span<const Eigen::AlignedBox3d> boxes);

  /// Object `object`'s box is now `box`: its leaf and every node above it are refitted.
  /// A box that moves far leaves the tree looser, never wrong.
  void update(int object, const Eigen::AlignedBox3d& box) noexcept;

  /// Calls f(object) for every object whose box overlaps `box` (closed boxes), in no
  /// particular order; stops early if f returns false (f may also return void).
  template <class F>
  void for_each_overlapping(const Eigen::AlignedBox3d& box, F&& f) const {
    if (nodes_.empty()) return;
    std::array<int, kMaxDepth + 1> stack;  // not cleared: only what is pushed is read
    int top = 0;
    stack[static_cast<std::size_t>(top++)] = 0;
    while (top > 0) {
      const Node& node = nodes_[static_cast<std::size_t>(stack[static_cast<std::size_t>(--top)])];
      if (!overlaps(node.box, box)) continue;
      if (node.object >= 0) {
        if constexpr (std::is_same_v<decltype(f(node.object)), bool>) {
          if (!f(node.object)) return;
        } else {
          f(node.object);
        }
        continue;
      }
      stack[static_cast<std::size_t>(top++)] = node.right;
      stack[static_cast<std::size_t>(top++)] = node.left;
    }
  }

  [[nodiscard]] std::size_t object_count() const { return leaf_of_.size(); }
  /// Levels below the root of the deepest leaf (0 for one object).
  [[nodiscard]] int depth() const { return depth_; }

  /// Whether two closed boxes overlap, as Eigen's intersects(), written out so that an
  /// unbounded side (infinities) compares as it should.
  [[nodiscard]] static bool overlaps(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b) {
    return (a.min().array() <= b.max().array()).all() && (b.min().array() <= a.max().array()).all();
  }

 private:
  struct Node {
    Eigen::AlignedBox3d box;
    int left = -1;
    int right = -1;
    int parent = -1;
    int object = -1;  ///< a leaf's object, -1 for an inner node
  };
  int build(std::span<int> objects, std::span<const Eigen::AlignedBox3d> boxes,
            std::span<const Eigen::Vector3d> centres, int parent, int level);

  std::vector<Node> nodes_;  ///< the root first
  std::vector<int> leaf_of_;
  int depth_ = 0;
};

}  // namespace mhd
