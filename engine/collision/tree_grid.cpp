#include "collision/tree_grid.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mhd {
namespace {

constexpr std::size_t kMostSamples = std::size_t{1} << 16;
// Cells along an axis of Bullet's 16-bit grid.
constexpr double kGridCells = 65535.0;
// Share of the sampled vertices left out at each end of an axis as strays.
constexpr double kStrayShare = 0.01;
// The bulk's box grows by this much of its largest side each way, so that a hand near the
// mesh's edge stays on the fine grid.
constexpr double kGrowthPerSide = 0.5;
// Bounds this many times the bulk's size, or less, leave the grid as it is, whatever else.
constexpr double kMostBoundsPerBulk = 4.0;

using Samples = std::array<std::vector<double>, 3>;

double nth(std::vector<double>& v, double share) {
  const auto k = static_cast<std::ptrdiff_t>(share * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[static_cast<std::size_t>(k)];
}

void add(Samples& s, const Eigen::Vector3d& p) {
  for (std::size_t k = 0; k < 3; ++k) s[k].push_back(p[static_cast<Eigen::Index>(k)]);
}

// The box of the middle 98 % of the samples along each axis (empty without samples).
Eigen::AlignedBox3d bulk_of(Samples& s) {
  if (s[0].empty()) return {};
  Eigen::Vector3d lo, hi;
  for (std::size_t k = 0; k < 3; ++k) {
    lo[static_cast<Eigen::Index>(k)] = nth(s[k], kStrayShare);
    hi[static_cast<Eigen::Index>(k)] = nth(s[k], 1.0 - kStrayShare);
  }
  return {lo, hi};
}

// Whether a vertex is in the even sample that keeps one vertex in `stride` (a power of
// two), chosen by its coordinates' bits: the same vertices whatever their order, so a
// mesh renumbered (a large one in its tree's leaf order, as cached) gets the same grid.
bool sampled(const Eigen::Vector3d& p, std::uint64_t stride) {
  std::uint64_t h = std::bit_cast<std::uint64_t>(p.x()) * 0x9E3779B97F4A7C15ULL;
  h ^= std::bit_cast<std::uint64_t>(p.y()) * 0xC2B2AE3D27D4EB4FULL;
  h ^= std::bit_cast<std::uint64_t>(p.z()) * 0x165667B19E3779F9ULL;
  h ^= h >> 31;
  h *= 0xBF58476D1CE4E5B9ULL;
  h ^= h >> 29;
  return (h & (stride - 1)) == 0;
}

}  // namespace

Eigen::AlignedBox3d tree_grid_box(const TriangleMesh& mesh, const Eigen::AlignedBox3d& bounds) {
  const std::size_t n = mesh.vertices_m.size();
  const double extent = bounds.isEmpty() ? 0.0 : bounds.sizes().maxCoeff();
  if (n == 0 || !(extent > 0.0)) return bounds;
  // A quick look at every k-th vertex: most meshes have no strays and stop here.
  const std::size_t step = (n + kMostSamples - 1) / kMostSamples;
  Samples quick;
  for (std::size_t v = 0; v < n; v += step) add(quick, mesh.vertices_m[v]);
  const Eigen::AlignedBox3d quick_bulk = bulk_of(quick);
  if (!(extent > kMostBoundsPerBulk * quick_bulk.sizes().maxCoeff())) return bounds;
  // Strays, perhaps: the same again over a sample that does not depend on the order.
  Samples even;
  const std::uint64_t stride = std::bit_ceil(static_cast<std::uint64_t>(step));
  for (std::size_t v = 0; v < n; ++v) {
    if (stride == 1 || sampled(mesh.vertices_m[v], stride)) add(even, mesh.vertices_m[v]);
  }
  const Eigen::AlignedBox3d bulk = bulk_of(even);
  const double bulk_size = bulk.isEmpty() ? 0.0 : bulk.sizes().maxCoeff();
  if (!(bulk_size > 0.0)) return bounds;
  // The vertices of a surface that size lie about this far apart.
  const double spacing = bulk_size / std::sqrt(static_cast<double>(n));
  if (!(extent / kGridCells > kMaxGridCellPerSpacing * spacing)) return bounds;
  const Eigen::Vector3d grow = Eigen::Vector3d::Constant(kGrowthPerSide * bulk_size);
  const Eigen::AlignedBox3d grid = Eigen::AlignedBox3d(bulk.min() - grow, bulk.max() + grow).intersection(bounds);
  // Not worth clamping anything for less than a halving of the cells.
  if (grid.isEmpty() || 2.0 * grid.sizes().maxCoeff() > extent) return bounds;
  return grid;
}

}  // namespace mhd
