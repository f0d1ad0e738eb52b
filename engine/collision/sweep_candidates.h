#pragma once
// The triangles near the proxy, gathered from the BVH by one walk of a box round where the
// proxy is and reused by later sweeps, this tick and the next ones, that stay in that box
// (CollisionWorld::sweep, docs/proxy.md "What a tick costs"). A sweep tests exactly the
// triangles the BVH walk of its own box would report, whether they come from here or from
// the tree: only the cost changes, never an answer.

#include "collision/mesh_bvh.h"

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>

namespace mhd {

class SweepCandidates {
 public:
  /// Most triangles held at once; a gather that would exceed it is not kept.
  static constexpr int kCapacity = 256;
  /// Most gathered boxes held at once (an object each, or places of one object).
  static constexpr int kMaxRegions = 4;

  // Only the counts are initialised: the arrays are written before they are read.
  SweepCandidates() noexcept {}  // NOLINT(modernize-use-equals-default): no zeroing of the arrays
  SweepCandidates(const SweepCandidates& other) noexcept { *this = other; }
  /// Copies the regions held and only the part of the arrays in use.
  SweepCandidates& operator=(const SweepCandidates& other) noexcept;

  /// The leaves of one object's tree that overlap `box`, at [begin, end) of the arrays.
  struct Region {
    int object = -1;
    MeshBvh::QuantizedBox box;
    int begin = 0;
    int end = 0;
  };

  /// Forgets everything gathered unless it was gathered from the world named `world_id`
  /// (CollisionWorld::geometry_id()).
  void bind(std::uint64_t world_id) {
    if (world_id == world_id_) return;
    forget();
    world_id_ = world_id;
  }

  /// Forgets everything gathered.
  void forget() {
    region_count_ = 0;
    count_ = 0;
    walks_ = 0;
  }

  /// A gathered region of `object` whose box holds `q`, or null.
  [[nodiscard]] const Region* find(int object, const MeshBvh::QuantizedBox& q) const {
    for (int i = 0; i < region_count_; ++i) {
      const Region& r = regions_[static_cast<std::size_t>(i)];
      if (r.object == object && MeshBvh::contains(r.box, q)) return &r;
    }
    return nullptr;
  }

  /// Whether a sweep that the list did not serve should gather: on every second such
  /// sweep (a single one, as in most free-space ticks, never pays for a list) and not for
  /// a while after a gather that did not fit (the mesh is too fine there for a list).
  [[nodiscard]] bool should_gather() const { return walks_ > 0; }

  /// Counts a walk of the BVH that the list did not serve.
  void count_walk() { ++walks_; }

  /// Walks `bvh` once and keeps every leaf overlapping `box` as a region of `object`,
  /// making room by forgetting older regions. Returns the region, or null (nothing
  /// kept, and no gather for the next kWalksAfterOverflow walks) when its leaves would
  /// not fit in kCapacity.
  const Region* gather(const MeshBvh& bvh, int object, const MeshBvh::QuantizedBox& box);

  /// Calls f(triangle) for every leaf of `r` whose box overlaps `q`. When r's box holds
  /// q these are exactly the triangles MeshBvh::for_each_leaf_overlapping(q) reports.
  template <class F>
  void for_each_overlapping(const Region& r, const MeshBvh::QuantizedBox& q, F&& f) const {
    // Bullet's closed-interval overlap, over plain arrays so the compiler can vectorise it;
    // then the overlapping ones, eight flags at a time (the padding past r.end is cleared).
    std::array<std::uint8_t, kCapacity + 8> overlaps;
    for (int i = r.begin; i < r.end; ++i) {
      const auto k = static_cast<std::size_t>(i);
      // Bitwise & on ints, not && on bools: no branch per comparison (clang warns on bools).
      const int in_x = static_cast<int>(q.min[0] <= max_x_[k]) & static_cast<int>(q.max[0] >= min_x_[k]);
      const int in_y = static_cast<int>(q.min[1] <= max_y_[k]) & static_cast<int>(q.max[1] >= min_y_[k]);
      const int in_z = static_cast<int>(q.min[2] <= max_z_[k]) & static_cast<int>(q.max[2] >= min_z_[k]);
      overlaps[k] = static_cast<std::uint8_t>(in_x & in_y & in_z);
    }
    std::memset(overlaps.data() + r.end, 0, 8);
    for (int i = r.begin; i < r.end; i += 8) {
      std::uint64_t flags = 0;  // one byte per leaf, 0 or 1
      std::memcpy(&flags, overlaps.data() + i, sizeof flags);
      while (flags != 0) {
        // The set flag of the lowest address first: leaves in array order, as one by one.
        constexpr bool kLittle = std::endian::native == std::endian::little;
        const int bit = kLittle ? std::countr_zero(flags) : 63 - std::countl_zero(flags);
        const int byte = kLittle ? bit / 8 : 7 - bit / 8;
        f(triangle_[static_cast<std::size_t>(i + byte)]);
        flags &= ~(std::uint64_t{1} << bit);
      }
    }
  }

  /// Triangles held now, and gathers made since construction (for tests).
  [[nodiscard]] int size() const { return count_; }
  [[nodiscard]] int gathers() const { return gathers_; }

 private:
  // Walks to wait, after a gather that did not fit, before gathering again.
  static constexpr int kWalksAfterOverflow = 32;

  std::array<std::uint16_t, kCapacity> min_x_, min_y_, min_z_, max_x_, max_y_, max_z_;
  std::array<std::uint32_t, kCapacity> triangle_;
  std::array<Region, kMaxRegions> regions_;
  std::uint64_t world_id_ = 0;
  int region_count_ = 0;
  int count_ = 0;
  int walks_ = 0;  // walks since the last gather (negative: waiting after an overflow)
  int gathers_ = 0;
};

}  // namespace mhd
