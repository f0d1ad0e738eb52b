#include "collision/sweep_candidates.h"

#include <algorithm>

namespace mhd {

SweepCandidates& SweepCandidates::operator=(const SweepCandidates& other) noexcept {
  if (this == &other) return *this;
  const auto n = static_cast<std::ptrdiff_t>(other.count_);
  std::copy_n(other.min_x_.begin(), n, min_x_.begin());
  std::copy_n(other.min_y_.begin(), n, min_y_.begin());
  std::copy_n(other.min_z_.begin(), n, min_z_.begin());
  std::copy_n(other.max_x_.begin(), n, max_x_.begin());
  std::copy_n(other.max_y_.begin(), n, max_y_.begin());
  std::copy_n(other.max_z_.begin(), n, max_z_.begin());
  std::copy_n(other.triangle_.begin(), n, triangle_.begin());
  regions_ = other.regions_;
  world_id_ = other.world_id_;
  region_count_ = other.region_count_;
  count_ = other.count_;
  walks_ = other.walks_;
  gathers_ = other.gathers_;
  return *this;
}

const SweepCandidates::Region* SweepCandidates::gather(const MeshBvh& bvh, int object,
                                                       const MeshBvh::QuantizedBox& box) {
  ++gathers_;
  walks_ = 0;
  // Walks the tree into the arrays from `first`; false if the leaves ran past the capacity.
  auto walk_from = [&](int first, int& end) {
    int n = first;
    bool fits = true;
    bvh.for_each_leaf_overlapping(box, [&](std::uint32_t triangle, const btQuantizedBvhNode& leaf) {
      if (n == kCapacity) {
        fits = false;
        return false;
      }
      const auto k = static_cast<std::size_t>(n++);
      min_x_[k] = leaf.m_quantizedAabbMin[0];
      min_y_[k] = leaf.m_quantizedAabbMin[1];
      min_z_[k] = leaf.m_quantizedAabbMin[2];
      max_x_[k] = leaf.m_quantizedAabbMax[0];
      max_y_[k] = leaf.m_quantizedAabbMax[1];
      max_z_[k] = leaf.m_quantizedAabbMax[2];
      triangle_[k] = triangle;
      return true;
    });
    end = n;
    return fits;
  };
  // After the regions held if there is room, else in place of all of them.
  int end = 0;
  const bool room = region_count_ < kMaxRegions;
  if (!room || !walk_from(count_, end)) {
    const bool walked_from_start = room && count_ == 0;
    region_count_ = 0;
    count_ = 0;
    if (walked_from_start || !walk_from(0, end)) {
      walks_ = -kWalksAfterOverflow;
      return nullptr;
    }
  }
  Region& r = regions_[static_cast<std::size_t>(region_count_++)];
  r.object = object;
  r.box = box;
  r.begin = count_;
  r.end = end;
  count_ = end;
  return &r;
}

}  // namespace mhd
