#include "mesh_gen/dolphin_mesh.h"

#include "mesh_gen/density_sampling.h"
#include "mesh_gen/dolphin_shape.h"
#include "mesh_gen/ring_surface.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mhd::mesh_gen {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<double> uniform(double begin, double end, int intervals) {
  std::vector<double> v(static_cast<std::size_t>(intervals) + 1);
  for (int i = 0; i <= intervals; ++i) v[static_cast<std::size_t>(i)] = begin + (end - begin) * i / intervals;
  return v;
}

// Adds two densities, each normalised to unit mass, plus a uniform floor.
std::vector<double> blend(const std::vector<double>& a, const std::vector<double>& b, double floor) {
  double sa = 0.0, sb = 0.0;
  for (double x : a) sa += x;
  for (double x : b) sb += x;
  std::vector<double> out(a.size());
  const double f = floor / static_cast<double>(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) out[i] = (sa > 0 ? a[i] / sa : 0.0) + (sb > 0 ? b[i] / sb : 0.0) + f;
  return out;
}

// Splits `total` into integers proportional to `weights`, each at least 1 (largest remainder).
std::vector<int> apportion(const std::vector<double>& weights, int total) {
  const int n = static_cast<int>(weights.size());
  double sum = 0.0;
  for (double w : weights) sum += w;
  std::vector<int> out(weights.size(), 1);
  const int spare = total - n;
  std::vector<std::pair<double, std::size_t>> remainders;
  int given = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    const double share = spare * weights[i] / sum;
    const int whole = static_cast<int>(std::floor(share));
    out[i] += whole;
    given += whole;
    remainders.emplace_back(share - whole, i);
  }
  std::stable_sort(remainders.begin(), remainders.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (int k = 0; k < spare - given; ++k) out[remainders[static_cast<std::size_t>(k)].second] += 1;
  return out;
}

// Ring angles: denser where the sections' outlines are long (fins), mirror-symmetric in z,
// with vertices exactly at the belly, the back, the flanks and along the pectoral fins.
std::vector<double> ring_angles(const DolphinShape& shape, int ring_size) {
  const int stations = 320;
  const int bins = 4096;  // over the right half, theta in [-pi/2, pi/2]
  const double bin_width = kPi / bins;
  const std::vector<double> thetas = uniform(-0.5 * kPi, 0.5 * kPi, bins);
  std::vector<double> area(bins, 0.0), sharp(bins, 0.0);
  std::vector<Eigen::Vector3d> pts;
  std::vector<double> len(bins);
  for (int k = 0; k < stations; ++k) {
    shape.ring((k + 0.5) / stations, thetas, pts);
    double perimeter = 0.0;
    for (std::size_t m = 0; m < len.size(); ++m) {
      len[m] = (pts[m + 1] - pts[m]).norm();
      perimeter += len[m];
    }
    for (std::size_t m = 0; m < len.size(); ++m) {
      area[m] += len[m];
      sharp[m] = std::max(sharp[m], len[m] / perimeter);
    }
  }
  const std::vector<double> density = blend(area, sharp, 0.15);

  // Split the right half at the feature angles; each piece gets samples in proportion
  // to its mass (at least one, which sits on the feature angle itself).
  std::vector<double> cuts = DolphinShape::feature_angles();
  cuts.push_back(0.5 * kPi);
  std::vector<std::vector<double>> pieces;
  std::vector<double> mass;
  for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
    const auto from = static_cast<std::ptrdiff_t>(std::lround((cuts[p] + 0.5 * kPi) / bin_width));
    const auto to = static_cast<std::ptrdiff_t>(std::lround((cuts[p + 1] + 0.5 * kPi) / bin_width));
    pieces.emplace_back(density.begin() + from, density.begin() + to);
    double sum = 0.0;
    for (double d : pieces.back()) sum += d;
    mass.push_back(sum);
  }
  const int half = ring_size / 2;
  const std::vector<int> counts = apportion(mass, half);
  std::vector<double> right;
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    const std::vector<double> piece = sample_by_density(pieces[p], cuts[p], cuts[p + 1], counts[p], 0.0);
    right.insert(right.end(), piece.begin(), piece.end());
  }
  // Full ring, counter-clockwise from the belly: the right half, the back, the mirror.
  std::vector<double> out = right;
  out.push_back(0.5 * kPi);
  for (auto it = right.rbegin(); it != right.rend() - 1; ++it) out.push_back(kPi - *it);
  return out;
}

// Ring positions along the body: denser where the surface changes fast (fin edges, tips).
std::vector<double> ring_positions(const DolphinShape& shape, const std::vector<double>& angles, int rings) {
  const int bins = 4096;
  const std::size_t stride = std::max<std::size_t>(1, angles.size() / 256);
  std::vector<double> probe;
  for (std::size_t j = 0; j < angles.size(); j += stride) probe.push_back(angles[j]);
  std::vector<double> area(bins, 0.0), sharp(bins, 0.0);
  std::vector<Eigen::Vector3d> prev, cur;
  shape.ring(0.0, probe, prev);
  for (int k = 1; k <= bins; ++k) {
    shape.ring(static_cast<double>(k) / bins, probe, cur);
    double sum = 0.0, most = 0.0;
    for (std::size_t j = 0; j < probe.size(); ++j) {
      const double d = (cur[j] - prev[j]).norm();
      sum += d;
      most = std::max(most, d);
    }
    area[static_cast<std::size_t>(k - 1)] = sum;
    sharp[static_cast<std::size_t>(k - 1)] = most;
    std::swap(prev, cur);
  }
  std::vector<double> s = sample_by_density(blend(area, sharp, 0.15), 0.0, 1.0, rings + 1, 0.0);
  s.erase(s.begin());  // quantile 0 is the nose pole
  return s;
}

}  // namespace

std::size_t DolphinLayout::triangle_count() const {
  return 2 * static_cast<std::size_t>(rings) * static_cast<std::size_t>(ring_size);
}

DolphinLayout dolphin_layout(std::size_t target_triangles) {
  // Cells about square on average: rings / ring_size = mean length along the body over
  // mean girth (fins included), both measured on the continuous surface.
  const DolphinShape shape;
  const int stations = 200;
  const int around = 256;
  const std::vector<double> thetas = uniform(-0.5 * kPi, 1.5 * kPi, around);
  std::vector<Eigen::Vector3d> prev, cur;
  std::vector<double> meridian(static_cast<std::size_t>(around), 0.0);
  double girth = 0.0;
  for (int k = 0; k <= stations; ++k) {
    shape.ring(std::clamp(static_cast<double>(k) / stations, 1e-6, 1.0 - 1e-6), thetas, cur);
    for (int j = 0; j < around; ++j) {
      const auto uj = static_cast<std::size_t>(j);
      girth += (cur[uj + 1] - cur[uj]).norm() / (stations + 1);
      if (k > 0) meridian[uj] += (cur[uj] - prev[uj]).norm();
    }
    std::swap(prev, cur);
  }
  double length = 0.0;
  for (double m : meridian) length += m / around;
  const double ratio = length / girth;
  const double target = std::max(static_cast<double>(target_triangles), 64.0);
  const int ring_size = 4 * std::max(2, static_cast<int>(std::lround(std::sqrt(target / (2.0 * ratio)) / 4.0)));
  const int rings = std::max(2, static_cast<int>(std::lround(target / (2.0 * ring_size))));
  return {rings, ring_size};
}

TriangleMesh make_dolphin(const DolphinLayout& layout) {
  if (layout.rings < 2 || layout.ring_size < 8 || layout.ring_size % 4 != 0) {
    throw std::invalid_argument("make_dolphin: needs rings >= 2 and a ring size that is a multiple of 4, >= 8");
  }
  const DolphinShape shape;
  const std::vector<double> angles = ring_angles(shape, layout.ring_size);
  const std::vector<double> positions = ring_positions(shape, angles, layout.rings);
  std::vector<Eigen::Vector3d> points;
  points.reserve(static_cast<std::size_t>(layout.rings) * angles.size());
  std::vector<Eigen::Vector3d> ring;
  for (double s : positions) {
    shape.ring(s, angles, ring);
    points.insert(points.end(), ring.begin(), ring.end());
  }
  return make_ring_surface(points, layout.rings, static_cast<int>(angles.size()), shape.nose(), shape.tail());
}

}  // namespace mhd::mesh_gen
