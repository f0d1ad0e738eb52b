#include "stress/tour_transit.h"

#include "stress/stroke_random.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mhd::stress {
namespace {

using Eigen::Vector3d;

constexpr double kMaxArcStep_rad = 20.0 * std::numbers::pi / 180.0;

// Points on the great circle from direction d1 to d2 (both unit), d1 excluded, d2
// included, at most kMaxArcStep_rad apart, at radius rho about c.
void append_arc(const Vector3d& c, double rho, const Vector3d& d1, const Vector3d& d2, std::vector<Vector3d>& out) {
  const double angle = std::acos(std::clamp(d1.dot(d2), -1.0, 1.0));
  Vector3d axis = d1.cross(d2);
  if (axis.norm() < 1e-9) axis = any_perpendicular(d1);
  axis.normalize();
  const int steps = std::max(1, static_cast<int>(std::ceil(angle / kMaxArcStep_rad)));
  for (int i = 1; i <= steps; ++i) {
    const double a = angle * static_cast<double>(i) / static_cast<double>(steps);
    out.push_back(c + rho * (Eigen::AngleAxisd(a, axis) * d1));
  }
}

Vector3d unit_or(const Vector3d& v, const Vector3d& fallback) {
  const double n = v.norm();
  return n > 1e-12 ? Vector3d(v / n) : fallback;
}

}  // namespace

bool leg_is_clear(const verify::SurfaceCrossingOracle& oracle, const Vector3d& a_W, const Vector3d& b_W,
                  double clearance_m) {
  if (oracle.segment_touches_surface(a_W, b_W)) return false;
  const double length = (b_W - a_W).norm();
  const int pieces = std::max(1, static_cast<int>(std::ceil(length / std::max(clearance_m, length / 8.0))));
  for (int i = 1; i < pieces; ++i) {
    const double f = static_cast<double>(i) / static_cast<double>(pieces);
    if (oracle.distance_to_surface(a_W + f * (b_W - a_W)) < 0.5 * clearance_m) return false;
  }
  return true;
}

std::optional<Transit> plan_free_transit(const verify::SurfaceCrossingOracle& oracle, const TransitRequest& request,
                                         const TourParams& params, std::mt19937_64& rng) {
  const Vector3d c = request.bounds_W.center();
  const double radius = 0.5 * request.bounds_W.diagonal().norm();
  const double clear = params.clearance_m;
  const Vector3d& p0 = request.from.p_W;
  const Vector3d& p1 = request.to.p_W;
  const double span = (p1 - p0).norm();
  for (int attempt = 0; attempt < params.max_transit_attempts; ++attempt) {
    // Later attempts lift further off the ends and draw directions more freely.
    const double grow = static_cast<double>(attempt + 1) / static_cast<double>(params.max_transit_attempts);
    auto end_direction = [&](const TransitEnd& end) {
      if (end.out_W.squaredNorm() > 0.0 && attempt % 4 != 3) return Vector3d(end.out_W);
      if (attempt == 0) return unit_or(end.p_W - c, Vector3d::UnitY());
      return random_unit(rng);
    };
    const double lift_scale = request.around ? radius : std::max(0.05, 0.5 * span);
    const Vector3d lift0 = p0 + uniform_in(rng, clear, clear + grow * lift_scale) * end_direction(request.from);
    const Vector3d lift1 = p1 + uniform_in(rng, clear, clear + grow * lift_scale) * end_direction(request.to);

    std::vector<Vector3d> corners{p0, lift0};
    if (request.around) {
      const double rho = radius + uniform_in(rng, 2.0 * clear, 2.0 * clear + 0.25 * radius);
      Vector3d d = unit_or(lift0 - c, Vector3d::UnitY());
      const Vector3d d_end = unit_or(lift1 - c, Vector3d::UnitY());
      corners.push_back(c + rho * d);
      std::vector<Vector3d> via;  // directions to pass on the way
      if (verify::uniform01(rng) < 0.5 || d.dot(d_end) < -0.9) via.push_back(random_unit(rng));  // behind, often
      const bool rim_pass = request.rims != nullptr && !request.rims->empty() && verify::uniform01(rng) < 0.35;
      Vector3d rim_point = Vector3d::Zero();
      if (rim_pass) {
        // Just past an open boundary, a little to either side of the sheet's plane.
        const SurfaceFeature& rim = draw_feature(*request.rims, rng);
        const Vector3d e = unit_or(rim.b_W - rim.a_W, any_perpendicular(rim.out_W));
        const Vector3d side = unit_or(e.cross(rim.out_W), any_perpendicular(rim.out_W));
        rim_point = rim.a_W + verify::uniform01(rng) * (rim.b_W - rim.a_W) +
                    uniform_in(rng, 2.0 * clear, 5.0 * clear) * rim.out_W +
                    uniform_in(rng, -2.0 * clear, 2.0 * clear) * side;
        via.push_back(unit_or(rim_point - c, Vector3d::UnitY()));
      }
      for (std::size_t i = 0; i < via.size(); ++i) {
        append_arc(c, rho, d, via[i], corners);
        d = via[i];
        if (rim_pass && i + 1 == via.size()) {
          corners.push_back(rim_point);
          corners.push_back(c + rho * d);
        }
      }
      append_arc(c, rho, d, d_end, corners);
    } else {
      // A lifted arc: up from both ends' mean direction, at most half the distance between them.
      const Vector3d up = unit_or(request.from.out_W + request.to.out_W, unit_or(lift0 - c, Vector3d::UnitY()));
      corners.push_back(0.5 * (lift0 + lift1) + uniform_in(rng, 0.0, grow * 0.5 * span + clear) * up);
    }
    corners.push_back(lift1);
    corners.push_back(p1);
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());

    bool ok = true;
    for (std::size_t i = 1; ok && i < corners.size(); ++i) {
      const bool end_leg = i == 1 || i + 1 == corners.size();  // along the ends' own directions
      ok = end_leg ? !oracle.segment_touches_surface(corners[i - 1], corners[i])
                   : leg_is_clear(oracle, corners[i - 1], corners[i], clear);
      if (ok && !end_leg && oracle.distance_to_surface(corners[i]) < clear) ok = false;
    }
    if (ok) return Transit{std::move(corners), attempt + 1};
  }
  return std::nullopt;
}

}  // namespace mhd::stress
