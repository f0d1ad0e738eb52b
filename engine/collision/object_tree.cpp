#include "collision/object_tree.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace mhd {

void ObjectTree::rebuild(std::span<const Eigen::AlignedBox3d> boxes) {
  nodes_.clear();
  leaf_of_.assign(boxes.size(), -1);
  depth_ = 0;
  if (boxes.empty()) return;
  // An unbounded box has no finite centre: it is placed as if centred at the origin, and
  // its box still reaches every node above it.
  std::vector<Eigen::Vector3d> centres(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Eigen::Vector3d c = boxes[i].center();
    centres[i] = c.allFinite() ? c : Eigen::Vector3d::Zero();
  }
  std::vector<int> objects(boxes.size());
  std::iota(objects.begin(), objects.end(), 0);
  nodes_.reserve(2 * boxes.size() - 1);
  (void)build(objects, boxes, centres, -1, 0);
  if (depth_ > kMaxDepth - 1) throw std::length_error("ObjectTree: too deep");  // not for 2^31 boxes
}

int ObjectTree::build(std::span<int> objects, std::span<const Eigen::AlignedBox3d> boxes,
                      std::span<const Eigen::Vector3d> centres, int parent, int level) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back(Node{});
  nodes_.back().parent = parent;
  depth_ = std::max(depth_, level);
  if (objects.size() == 1) {
    nodes_.back().box = boxes[static_cast<std::size_t>(objects[0])];
    nodes_.back().object = objects[0];
    leaf_of_[static_cast<std::size_t>(objects[0])] = index;
    return index;
  }
  Eigen::AlignedBox3d spread;
  for (const int o : objects) spread.extend(centres[static_cast<std::size_t>(o)]);
  Eigen::Index axis = 0;
  (void)spread.sizes().maxCoeff(&axis);
  const auto half = static_cast<std::ptrdiff_t>(objects.size() / 2);
  // Ties broken by the object's number, so a build does not depend on the library's sort.
  std::nth_element(objects.begin(), objects.begin() + half, objects.end(), [&](int a, int b) {
    const double ca = centres[static_cast<std::size_t>(a)][axis];
    const double cb = centres[static_cast<std::size_t>(b)][axis];
    return ca < cb || (ca == cb && a < b);
  });
  const int left = build(objects.first(static_cast<std::size_t>(half)), boxes, centres, index, level + 1);
  const int right = build(objects.subspan(static_cast<std::size_t>(half)), boxes, centres, index, level + 1);
  Node& node = nodes_[static_cast<std::size_t>(index)];
  node.left = left;
  node.right = right;
  node.box = nodes_[static_cast<std::size_t>(left)].box.merged(nodes_[static_cast<std::size_t>(right)].box);
  return index;
}

void ObjectTree::update(int object, const Eigen::AlignedBox3d& box) noexcept {
  if (object < 0 || static_cast<std::size_t>(object) >= leaf_of_.size()) return;
  int n = leaf_of_[static_cast<std::size_t>(object)];
  nodes_[static_cast<std::size_t>(n)].box = box;
  for (n = nodes_[static_cast<std::size_t>(n)].parent; n >= 0; n = nodes_[static_cast<std::size_t>(n)].parent) {
    Node& node = nodes_[static_cast<std::size_t>(n)];
    node.box = nodes_[static_cast<std::size_t>(node.left)].box.merged(nodes_[static_cast<std::size_t>(node.right)].box);
  }
}

}  // namespace mhd
