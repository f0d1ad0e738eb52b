#include "mesh_gen/dolphin_shape.h"

#include "mesh_gen/profile_curve.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace mhd::mesh_gen {
namespace {

// Straight-frame lengths are metres of a dolphin that the final scale makes 2.0 m long.
// x runs from the beak tip (0) to the tail end (kTailEnd), y is up, z lateral.
constexpr double kTailEnd = 1.88;
constexpr double kNoseCap = 0.025;  // length over which the beak tip rounds off
constexpr double kTailCap = 0.035;  // ... and the tail end (the fluke's trailing edge)
constexpr double kUnionPower = 12.0;  // smooth union of body and fins: larger = sharper root

double smoothstep(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// 0 below 0, quadratic onset over `a`, then linear with slope 1 (C1).
double soft_ramp(double t, double a) {
  if (t <= 0.0) return 0.0;
  if (t < a) return 0.5 * t * t / a;
  return t - 0.5 * a;
}

// Elliptic rounding towards a pole: 0 at the end, 1 at `length` from it.
double cap(double distance_from_end, double length) {
  if (distance_from_end >= length) return 1.0;
  if (distance_from_end <= 0.0) return 0.0;
  const double t = 1.0 - distance_from_end / length;
  return std::sqrt(1.0 - t * t);
}

struct Profiles {
  // Silhouette: top and bottom of the body (y) and its half-width, along x.
  ProfileCurve top{{{0.000, -0.030}, {0.040, -0.020}, {0.090, -0.011}, {0.130, 0.000}, {0.160, 0.042},
                    {0.200, 0.085}, {0.260, 0.122}, {0.340, 0.152}, {0.450, 0.178}, {0.600, 0.200},
                    {0.750, 0.212}, {0.900, 0.208}, {1.050, 0.188}, {1.200, 0.158}, {1.350, 0.125},
                    {1.500, 0.094}, {1.620, 0.067}, {1.720, 0.044}, {1.800, 0.027}, {1.880, 0.015}}};
  ProfileCurve bottom{{{0.000, -0.075}, {0.040, -0.082}, {0.090, -0.092}, {0.130, -0.100}, {0.160, -0.108},
                       {0.200, -0.120}, {0.260, -0.138}, {0.340, -0.160}, {0.450, -0.186}, {0.600, -0.208},
                       {0.750, -0.218}, {0.900, -0.213}, {1.050, -0.192}, {1.200, -0.163}, {1.350, -0.130},
                       {1.500, -0.098}, {1.620, -0.070}, {1.720, -0.046}, {1.800, -0.028}, {1.880, -0.016}}};
  ProfileCurve half_width{{{0.000, 0.026}, {0.040, 0.032}, {0.090, 0.040}, {0.130, 0.048}, {0.160, 0.060},
                           {0.200, 0.076}, {0.260, 0.097}, {0.340, 0.120}, {0.450, 0.142}, {0.600, 0.158},
                           {0.750, 0.164}, {0.900, 0.160}, {1.050, 0.140}, {1.200, 0.108}, {1.350, 0.070},
                           {1.500, 0.040}, {1.620, 0.024}, {1.720, 0.017}, {1.800, 0.013}, {1.880, 0.010}}};
  // Height of the section centre (where the body is widest) between bottom (0) and top (1).
  ProfileCurve centre_fraction{{{0.0, 0.50}, {0.20, 0.46}, {0.40, 0.42}, {0.62, 0.42}, {0.90, 0.46},
                                {1.20, 0.50}, {1.88, 0.50}}};
  // Super-ellipse exponents of the upper and lower halves (below 2: keeled).
  ProfileCurve n_top{{{0.0, 2.0}, {0.3, 2.2}, {1.0, 2.2}, {1.30, 1.8}, {1.50, 1.5}, {1.88, 1.6}}};
  ProfileCurve n_bottom{{{0.0, 2.0}, {0.3, 2.1}, {1.0, 2.1}, {1.30, 1.8}, {1.50, 1.5}, {1.88, 1.6}}};
  // Dorsal fin: height above the back (negative where there is no fin) and half-thickness.
  ProfileCurve dorsal_height{{{0.66, -0.06}, {0.72, 0.0}, {0.80, 0.075}, {0.87, 0.145}, {0.93, 0.200},
                              {0.975, 0.222}, {1.005, 0.205}, {1.035, 0.120}, {1.065, 0.0}, {1.12, -0.06}}};
  ProfileCurve dorsal_thickness{{{0.66, 0.010}, {0.76, 0.017}, {0.86, 0.019}, {0.96, 0.015}, {1.03, 0.009},
                                 {1.08, 0.005}}};
  // Pectoral fins: length beyond the body and half-thickness. Fluke: half-span from the
  // centre line and half-thickness.
  ProfileCurve pectoral_span{{{0.38, -0.05}, {0.42, 0.0}, {0.46, 0.09}, {0.50, 0.170}, {0.54, 0.215},
                              {0.565, 0.205}, {0.59, 0.12}, {0.61, 0.0}, {0.65, -0.05}}};
  ProfileCurve pectoral_thickness{{{0.38, 0.008}, {0.45, 0.015}, {0.50, 0.014}, {0.56, 0.009}, {0.61, 0.005}}};
  ProfileCurve fluke_span{{{1.52, 0.0}, {1.60, 0.035}, {1.66, 0.085}, {1.72, 0.150}, {1.78, 0.215},
                           {1.83, 0.260}, {1.86, 0.275}, {1.88, 0.278}}};
  ProfileCurve fluke_thickness{{{1.52, 0.010}, {1.64, 0.013}, {1.74, 0.012}, {1.82, 0.009}, {1.88, 0.006}}};
};

const Profiles& profiles() {
  static const Profiles p;
  return p;
}

// Shears along x of the straight frame. They move points within the fins' planes, so even
// coarse triangles of a thin fin stay apart. Each is one-to-one on the surface: for fixed
// (y, z), x + dx grows with x, because the pectoral term only fades out (front' < 0) far
// behind the pectoral fins, where nothing reaches beyond kLateralClear.
constexpr double kLateralClear = 0.175;  // |z| beyond every body section: only fins reach out there
constexpr double kPectoralSweep = 0.85;  // x shift per metre beyond kLateralClear (soft ramp)
constexpr double kFlukeSweep = 0.125;    // x shift of the fluke tips
constexpr double kFlukeSpan = 0.278;
constexpr double kDorsalClear = 0.225;   // y above every body section: only the dorsal fin
constexpr double kDorsalHook = 0.75;     // x shift per metre above kDorsalClear (soft ramp)

Eigen::Vector3d warp(const Eigen::Vector3d& p) {
  const double x = p.x();
  const double az = std::abs(p.z());
  const double front = 1.0 - smoothstep(0.9, 1.3, x);  // pectoral region
  const double back = smoothstep(1.40, 1.62, x);        // fluke region
  const double lateral = soft_ramp(az - kLateralClear, 0.08);
  const double fluke = kFlukeSweep * std::pow(std::min(az / kFlukeSpan, 1.5), 1.6);
  const double hook = kDorsalHook * soft_ramp(p.y() - kDorsalClear, 0.10);
  return {x + front * kPectoralSweep * lateral + back * fluke + hook, p.y(), p.z()};
}

}  // namespace

struct DolphinShape::Section {
  double x = 0;
  double y_centre = 0;
  double half_width = 0, above = 0, below = 0;  // body extents from the centre
  double n_top = 2, n_bottom = 2;
  double dorsal_reach = 0, dorsal_half_thickness = 0;      // thin half-ellipse along +y
  double pectoral_reach = 0, pectoral_half_thickness = 0;  // thin half-ellipses, down and out
  double fluke_reach = 0, fluke_half_thickness = 0;        // thin ellipse along z
};

double DolphinShape::body_radius(const Section& s, double cz, double sy) {
  const double tiny = 1e-12;
  const double n = sy >= 0.0 ? s.n_top : s.n_bottom;
  const double a = std::max(sy >= 0.0 ? s.above : s.below, tiny);
  const double w = std::max(s.half_width, tiny);
  return 1.0 / std::pow(std::pow(std::abs(cz) / w, n) + std::pow(std::abs(sy) / a, n), 1.0 / n);
}

DolphinShape::Section DolphinShape::section(double u) const {
  const Profiles& P = profiles();
  Section s;
  s.x = u;
  const double top = P.top(u);
  const double bottom = P.bottom(u);
  s.y_centre = bottom + P.centre_fraction(u) * (top - bottom);
  const double c = cap(u, kNoseCap) * cap(kTailEnd - u, kTailCap);
  s.above = (top - s.y_centre) * c;
  s.below = (s.y_centre - bottom) * c;
  s.half_width = P.half_width(u) * c;
  s.n_top = P.n_top(u);
  s.n_bottom = P.n_bottom(u);
  s.dorsal_reach = std::max(s.above + P.dorsal_height(u), 0.0);
  s.dorsal_half_thickness = P.dorsal_thickness(u);
  const double body_along_pectoral = body_radius(s, std::cos(kPectoralDihedral), -std::sin(kPectoralDihedral));
  s.pectoral_reach = std::max(body_along_pectoral + P.pectoral_span(u), 0.0);
  s.pectoral_half_thickness = P.pectoral_thickness(u);
  s.fluke_reach = P.fluke_span(u) * c;
  s.fluke_half_thickness = P.fluke_thickness(u) * std::max(c, 0.05);
  return s;
}

Eigen::Vector3d DolphinShape::straight_point(const Section& s, double theta) const {
  const double cz = std::cos(theta);  // towards +z
  const double sy = std::sin(theta);  // towards +y
  const double body = body_radius(s, cz, sy);
  // A thin ellipse centred on the section centre with semi-axes `reach` along the
  // direction (along, perp) = (1, 0) and `half_thickness` across; half = only along > 0.
  double sum = 1.0;
  auto fin = [&sum, body](double along, double perp, double reach, double half_thickness, bool half) {
    if (reach <= 0.0 || (half && along <= 0.0)) return;
    const double e = 1.0 / std::hypot(along / reach, perp / half_thickness);
    sum += std::pow(e / body, kUnionPower);
  };
  fin(sy, cz, s.dorsal_reach, s.dorsal_half_thickness, true);
  const double cp = std::cos(kPectoralDihedral), sp = std::sin(kPectoralDihedral);
  // Right pectoral points along (z, y) = (cp, -sp), the left one along (-cp, -sp).
  fin(cz * cp - sy * sp, cz * sp + sy * cp, s.pectoral_reach, s.pectoral_half_thickness, true);
  fin(-cz * cp - sy * sp, cz * sp - sy * cp, s.pectoral_reach, s.pectoral_half_thickness, true);
  fin(cz, sy, s.fluke_reach, s.fluke_half_thickness, false);
  const double r = body * std::pow(sum, 1.0 / kUnionPower);
  return {s.x, s.y_centre + r * sy, r * cz};
}

Eigen::Vector3d DolphinShape::to_output(const Eigen::Vector3d& p_straight) const {
  const Eigen::Vector3d q = warp(p_straight);
  // Half-turn about y (nose towards +x, still right-handed), then scale and centre.
  return Eigen::Vector3d(-q.x(), q.y(), -q.z()) * scale_ + offset_;
}

DolphinShape::DolphinShape() {
  // Bounds of the continuous surface on a fixed dense grid: the final scale and offset.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d hi = -lo;
  const int stations = 1500;
  const int around = 720;
  for (int i = 0; i <= stations; ++i) {
    const double u = kTailEnd * i / stations;
    const Section sec = section(u);
    for (int j = 0; j < around; ++j) {
      const Eigen::Vector3d p = to_output(straight_point(sec, 2.0 * std::numbers::pi * j / around));
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  scale_ = kLength_m / (hi.x() - lo.x());
  offset_ = -0.5 * (lo + hi) * scale_;

  const Profiles& P = profiles();
  auto inside_point = [this](double u, double y, double z) { return to_output({u, y, z}); };
  const double u_mid = 0.75;
  const Section mid = section(u_mid);
  landmarks_.p_body_centre_m = inside_point(u_mid, mid.y_centre, 0.0);
  const double u_dorsal = 0.95;
  const Section dorsal = section(u_dorsal);
  landmarks_.p_dorsal_fin_m = inside_point(u_dorsal, dorsal.y_centre + dorsal.above + 0.5 * P.dorsal_height(u_dorsal), 0.0);
  const double u_pectoral = 0.50;
  const Section pectoral = section(u_pectoral);
  const double out = pectoral.pectoral_reach - 0.5 * P.pectoral_span(u_pectoral);
  landmarks_.p_pectoral_fin_m = inside_point(u_pectoral, pectoral.y_centre - out * std::sin(kPectoralDihedral),
                                             out * std::cos(kPectoralDihedral));
  const double u_fluke = 1.80;
  const Section fluke = section(u_fluke);
  landmarks_.p_fluke_lobe_m = inside_point(u_fluke, fluke.y_centre, 0.6 * fluke.fluke_reach);
  const Section tail_end = section(kTailEnd);
  landmarks_.p_fluke_notch_m = inside_point(kTailEnd + 0.5 * kFlukeSweep, tail_end.y_centre, 0.0);
  const double u_back = 0.60;
  const Section back = section(u_back);
  landmarks_.p_above_back_m = inside_point(u_back, back.y_centre + back.above + 0.02, 0.0);
  landmarks_.p_beak_tip_m = nose();
}

std::vector<double> DolphinShape::feature_angles() {
  return {-0.5 * std::numbers::pi, -kPectoralDihedral, 0.0};
}

Eigen::Vector3d DolphinShape::point(double s, double theta) const {
  return to_output(straight_point(section(s * kTailEnd), theta));
}

void DolphinShape::ring(double s, const std::vector<double>& thetas, std::vector<Eigen::Vector3d>& out) const {
  const Section sec = section(s * kTailEnd);
  out.clear();
  out.reserve(thetas.size());
  for (double theta : thetas) out.push_back(to_output(straight_point(sec, theta)));
}

Eigen::Vector3d DolphinShape::nose() const {
  const Section s = section(0.0);
  return to_output({0.0, s.y_centre, 0.0});
}

Eigen::Vector3d DolphinShape::tail() const {
  const Section s = section(kTailEnd);
  return to_output({kTailEnd, s.y_centre, 0.0});
}

}  // namespace mhd::mesh_gen
