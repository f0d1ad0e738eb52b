#include "mesh_gen/range_scan.h"

#include "mesh_gen/depth_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace mhd::mesh_gen {
namespace {

constexpr double kMaxNoise_m = 0.001;
constexpr double kMaxSamples = 1e8;  // keeps sample indices in 32 bits
constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

std::string text(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

// Uniform in [-1, 1), a pure function of (seed, sample) so the scan does not depend on
// the order samples are visited in.
double noise_unit(std::uint64_t seed, std::size_t sample) {
  const std::uint64_t bits = splitmix64(seed ^ splitmix64(static_cast<std::uint64_t>(sample)));
  return 2.0 * static_cast<double>(bits >> 11) * 0x1.0p-53 - 1.0;
}

void validate(const TriangleMesh& source, const RangeScanParams& p) {
  if (source.triangles.empty()) throw std::invalid_argument("range scan: the source mesh has no triangles");
  if (!std::isfinite(p.azimuth_deg) || !std::isfinite(p.elevation_deg) || std::abs(p.elevation_deg) > 90.0) {
    throw std::invalid_argument("range scan: the view needs a finite azimuth and an elevation in [-90, 90] degrees (got " +
                                text(p.azimuth_deg) + ", " + text(p.elevation_deg) + ")");
  }
  if (p.columns < 2 || p.rows < 2) {
    throw std::invalid_argument("range scan: the grid needs at least 2 x 2 samples (got " + std::to_string(p.columns) +
                                " x " + std::to_string(p.rows) + ")");
  }
  if (static_cast<double>(p.columns) * static_cast<double>(p.rows) > kMaxSamples) {
    throw std::invalid_argument("range scan: the grid has more than 100 million samples (" + std::to_string(p.columns) +
                                " x " + std::to_string(p.rows) + ")");
  }
  if (!(p.max_depth_jump_cells >= 0.0) || !std::isfinite(p.max_depth_jump_cells)) {
    throw std::invalid_argument("range scan: the depth-jump threshold must be finite and >= 0 grid cells (got " +
                                text(p.max_depth_jump_cells) + ")");
  }
  if (!(p.noise_m >= 0.0 && p.noise_m < kMaxNoise_m)) {
    throw std::invalid_argument("range scan: the noise must be in [0, 1) mm (got " + text(p.noise_m * 1e3) +
                                " mm)");
  }
}

struct Patches {
  std::vector<std::uint32_t> parent;
  explicit Patches(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t root(std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  }
  void join(std::uint32_t a, std::uint32_t b) { parent[root(a)] = root(b); }
};

}  // namespace

Eigen::Vector3d scan_direction(double azimuth_deg, double elevation_deg) {
  const double az = azimuth_deg * std::numbers::pi / 180.0;
  const double el = elevation_deg * std::numbers::pi / 180.0;
  return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}

RangeScan make_range_scan(const TriangleMesh& source, const RangeScanParams& params) {
  validate(source, params);
  RangeScan scan;
  scan.to_scanner_O = scan_direction(params.azimuth_deg, params.elevation_deg);
  DepthGrid grid = cast_depth_grid(source, scan_axes(scan.to_scanner_O), params.columns, params.rows);
  if (!(grid.spacing_m > 0.0)) throw std::invalid_argument("range scan: the source is a single point in this view");
  scan.stats.spacing_m = grid.spacing_m;

  for (std::size_t k = 0; k < grid.depth_m.size(); ++k) {
    if (!std::isfinite(grid.depth_m[k])) continue;
    ++scan.stats.samples_hit;
    if (params.noise_m > 0.0) grid.depth_m[k] += params.noise_m * noise_unit(params.seed, k);
  }

  // Triangles over grid samples: each cell split along its diagonal of smaller depth
  // change, or the one triangle of three hit corners; then cut at depth jumps.
  const double max_jump_m = params.max_depth_jump_cells * grid.spacing_m;
  std::vector<std::array<std::uint32_t, 3>> kept;
  std::vector<Eigen::Vector3d> point_O(grid.depth_m.size());
  const auto try_triangle = [&](std::array<std::uint32_t, 3> s, const std::array<Eigen::Vector3d, 3>& p,
                                const std::array<double, 3>& d) {
    if (std::max({d[0], d[1], d[2]}) - std::min({d[0], d[1], d[2]}) > max_jump_m) {
      ++scan.stats.dropped_depth_jump;
      return;
    }
    // Never happens for exact samples (a triangle's area is at least its projection's,
    // half a cell); kept as a guard for the output.
    const double area2 = (p[1] - p[0]).cross(p[2] - p[0]).norm();
    if (!(area2 > 0.0) || !std::isfinite(area2)) {
      ++scan.stats.dropped_degenerate;
      return;
    }
    kept.push_back(s);
  };
  for (int j = 0; j + 1 < grid.rows; ++j) {
    for (int i = 0; i + 1 < grid.columns; ++i) {
      // Corners counter-clockwise seen from the scanner: A (i, j), B (i+1, j), C (i+1, j+1), D (i, j+1).
      const std::array<std::uint32_t, 4> s = {
          static_cast<std::uint32_t>(grid.index(i, j)), static_cast<std::uint32_t>(grid.index(i + 1, j)),
          static_cast<std::uint32_t>(grid.index(i + 1, j + 1)), static_cast<std::uint32_t>(grid.index(i, j + 1))};
      const std::array<int, 4> ci = {i, i + 1, i + 1, i};
      const std::array<int, 4> cj = {j, j, j + 1, j + 1};
      std::array<double, 4> d{};
      std::array<Eigen::Vector3d, 4> p;
      int hits = 0;
      int missing = -1;
      for (int k = 0; k < 4; ++k) {
        const auto uk = static_cast<std::size_t>(k);
        d[uk] = grid.depth_m[s[uk]];
        if (std::isfinite(d[uk])) {
          ++hits;
          p[uk] = grid.point_O(ci[uk], cj[uk], d[uk]);
          point_O[s[uk]] = p[uk];
        } else {
          missing = k;
        }
      }
      const auto tri = [&](int a, int b, int c) {
        const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b), uc = static_cast<std::size_t>(c);
        try_triangle({s[ua], s[ub], s[uc]}, {p[ua], p[ub], p[uc]}, {d[ua], d[ub], d[uc]});
      };
      if (hits == 4) {
        if (std::abs(d[0] - d[2]) <= std::abs(d[1] - d[3])) {
          tri(0, 1, 2);
          tri(0, 2, 3);
        } else {
          tri(0, 1, 3);
          tri(1, 2, 3);
        }
      } else if (hits == 3) {
        std::array<int, 3> rest{};
        for (int k = 0, n = 0; k < 4; ++k) {
          if (k != missing) rest[static_cast<std::size_t>(n++)] = k;
        }
        tri(rest[0], rest[1], rest[2]);
      }
    }
  }

  // Vertices: the used samples, renumbered in row-major order.
  std::vector<std::uint32_t> vertex_of(grid.depth_m.size(), kUnused);
  for (const auto& t : kept) {
    for (std::uint32_t s : t) vertex_of[s] = 0;
  }
  Patches patches(grid.depth_m.size());
  for (std::size_t k = 0; k < vertex_of.size(); ++k) {
    if (vertex_of[k] == kUnused) continue;
    vertex_of[k] = static_cast<std::uint32_t>(scan.mesh.vertices_m.size());
    scan.mesh.vertices_m.push_back(point_O[k]);
  }
  scan.mesh.triangles.reserve(kept.size());
  for (const auto& t : kept) {
    scan.mesh.triangles.push_back({vertex_of[t[0]], vertex_of[t[1]], vertex_of[t[2]]});
    patches.join(t[0], t[1]);
    patches.join(t[0], t[2]);
  }
  for (std::size_t k = 0; k < vertex_of.size(); ++k) {
    if (vertex_of[k] != kUnused && patches.root(static_cast<std::uint32_t>(k)) == k) ++scan.stats.patches;
  }
  return scan;
}

}  // namespace mhd::mesh_gen
