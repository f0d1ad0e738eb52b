// Tour strokes (stress_strokes.h, kind Tour): one continuous path per chain, never reset
// between its strokes. Each stroke: a free-space transit from where the last one left
// the HIP (tour_transit.h), an approach along the surface normal, a push 20-50 mm deep,
// a slide while pressed in, and a retract along the normal back out to free space.
// Targets: random surface points, concave creases and corners (the saddle and concave
// places), convex edges (slid across), and open rims (slid over the edge, round it to
// the back, pushed into from behind, retracted on the back side).

#include "stress/stress_strokes.h"

#include "stress/stroke_random.h"
#include "stress/tour_transit.h"
#include "verification/stroke_set.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace mhd::stress {
namespace {

using Eigen::Vector3d;

// Offset of the approach check's end from the target, so a point on the surface is not
// counted as blocking its own approach.
constexpr double kApproachEndOffset_m = 1e-4;

// One drawn tour stroke before sampling: press corners are approach start, push, slide
// waypoints; the retract leaves the last of them along retract_out.
struct TourPlan {
  bool valid = false;
  Vector3d approach_start = Vector3d::Zero();
  Vector3d approach_out = Vector3d::Zero();  ///< unit, from the surface to the approach start
  std::vector<Vector3d> slide;               ///< push point first
  Vector3d retract_end = Vector3d::Zero();
  Vector3d retract_out = Vector3d::Zero();
};

// Tangent direction t rotated about n (unit, perpendicular) by angle a.
Vector3d turn(const Vector3d& t, const Vector3d& n, double a) { return std::cos(a) * t + std::sin(a) * n.cross(t); }

}  // namespace

StressStroke StressStrokeGenerator::make_tour(std::uint64_t seed, std::uint64_t object_key, std::size_t index,
                                              const std::optional<Vector3d>& continue_from) const {
  std::mt19937_64 rng(splitmix64(seed ^ splitmix64(object_key ^ splitmix64(static_cast<std::uint64_t>(index)))));
  const ObjectSurface& s = surface_;
  const TourParams& tp = params_.tour;
  const double clear = tp.clearance_m;
  const double radius = 0.5 * s.bounds_W.diagonal().norm();
  const bool around = radius <= tp.max_around_radius_m;

  // A free approach start at most `h` out along n from q (halved until free), or false.
  auto free_approach = [&](const Vector3d& q, const Vector3d& n, double h, Vector3d& start) {
    for (; h >= 0.002; h *= 0.5) {
      start = q + h * n;
      if (start_is_free(start) && !oracle_.segment_touches_surface(start, q + kApproachEndOffset_m * n)) return true;
    }
    return false;
  };
  // The retract from `from` along n, out past the surface by at least `h` (tried further out).
  auto free_retract = [&](const Vector3d& from, const Vector3d& n, double depth, double h, Vector3d& end) {
    for (int k = 0; k < 3; ++k, h *= 2.0) {
      end = from + (depth + h + clear) * n;
      if (start_is_free(end) && oracle_.distance_to_surface(end) >= clear) return true;
    }
    return false;
  };

  auto draw_plan = [&]() {
    TourPlan plan;
    const double depth = uniform_in(rng, tp.min_depth_m, tp.max_depth_m);
    const double approach = uniform_in(rng, tp.min_approach_m, tp.max_approach_m);
    const double slide = uniform_in(rng, tp.min_slide_m, tp.max_slide_m);
    const double pick = verify::uniform01(rng);
    if (pick < 0.25 && !rims_.empty()) {
      // Open rim: press in from one side, slide out over the edge and round it, come back
      // under the sheet on the far side, push into it from behind, retract there.
      const SurfaceFeature& rim = draw_feature(rims_, rng);
      const Vector3d e = (rim.b_W - rim.a_W).normalized();
      const Vector3d& o = rim.out_W;
      const Vector3d n = (verify::uniform01(rng) < 0.5 ? 1.0 : -1.0) * e.cross(o).normalized();
      const Vector3d q = rim.a_W + verify::uniform01(rng) * (rim.b_W - rim.a_W);
      const double inward = uniform_in(rng, 0.005, 0.04);
      const Vector3d q_in = q - inward * o;
      if (!oracle_.segment_touches_surface(q_in + 1e-3 * n, q_in - 1e-3 * n)) return plan;  // not on the sheet
      if (!free_approach(q_in, n, approach, plan.approach_start)) return plan;
      const double beyond = uniform_in(rng, 0.005, 0.03);
      const double back_in = uniform_in(rng, 0.005, 0.04);
      const double below = uniform_in(rng, 0.003, 0.02);
      const double push_back = uniform_in(rng, tp.min_depth_m, tp.max_depth_m);
      const Vector3d under = q - back_in * o - below * n;
      plan.approach_out = n;
      plan.slide = {q_in - depth * n, q + beyond * o - depth * n, under, under + (below + push_back) * n};
      if (!free_retract(plan.slide.back(), -n, push_back, approach, plan.retract_end)) return plan;
      plan.retract_out = -n;
      plan.valid = true;
      return plan;
    }
    Vector3d q, n, t;
    if (pick < 0.45 && !s.creases.empty()) {
      // Concave edge: press into the fold, slide along it, rolling a little.
      const SurfaceFeature& f = draw_feature(s.creases, rng);
      q = f.a_W + verify::uniform01(rng) * (f.b_W - f.a_W);
      n = f.out_W;
      const Vector3d e = (f.b_W - f.a_W).normalized();
      t = ((verify::uniform01(rng) < 0.5 ? 1.0 : -1.0) * e + uniform_in(rng, -0.3, 0.3) * e.cross(n)).normalized();
    } else if (pick < 0.55 && !s.corners.empty()) {
      const SurfaceFeature& f = draw_feature(s.corners, rng);
      q = f.a_W;
      n = f.out_W;
      t = turn(any_perpendicular(n), n, uniform_in(rng, 0.0, 2.0 * std::numbers::pi));
    } else if (pick < 0.65 && !convex_ridges_.empty()) {
      // Convex edge: slide across it, over to the other face.
      const SurfaceFeature& f = draw_feature(convex_ridges_, rng);
      q = f.a_W + verify::uniform01(rng) * (f.b_W - f.a_W);
      n = f.out_W;
      const Vector3d e = (f.b_W - f.a_W).normalized();
      t = ((verify::uniform01(rng) < 0.5 ? 1.0 : -1.0) * e.cross(n) + uniform_in(rng, -0.5, 0.5) * e).normalized();
    } else {
      draw_surface_point(s, rng, q, n);
      if (!(n.squaredNorm() > 0.0)) return plan;
      t = turn(any_perpendicular(n), n, uniform_in(rng, 0.0, 2.0 * std::numbers::pi));
    }
    if (!free_approach(q, n, approach, plan.approach_start)) return plan;
    const double first = slide * uniform_in(rng, 0.4, 1.0);
    const Vector3d push = q - depth * n;
    const Vector3d bend = push + first * t;
    plan.slide = {push, bend, bend + (slide - first) * turn(t, n, uniform_in(rng, -0.5, 0.5) * std::numbers::pi)};
    plan.approach_out = n;
    if (!free_retract(plan.slide.back(), n, depth, approach, plan.retract_end)) return plan;
    plan.retract_out = n;
    plan.valid = true;
    return plan;
  };

  auto speed = [&](double lo) {
    return verify::uniform01(rng) < params_.full_speed_fraction ? params_.max_speed_m_per_s
                                                                 : uniform_in(rng, lo, 1.0) * params_.max_speed_m_per_s;
  };

  const int candidates = continue_from && !around ? std::max(1, params_.continue_candidates) : 1;
  for (int attempt = 0; attempt < params_.max_attempts; ++attempt) {
    TourPlan plan = draw_plan();
    for (int c = 1; c < candidates; ++c) {
      // Large objects are toured locally: the nearest of a few targets.
      TourPlan other = draw_plan();
      if (other.valid && (!plan.valid || (other.approach_start - *continue_from).squaredNorm() <
                                             (plan.approach_start - *continue_from).squaredNorm())) {
        plan = std::move(other);
      }
    }
    if (!plan.valid) continue;

    StressStroke stroke;
    stroke.kind = StrokeKind::Tour;
    stroke.index = index;
    stroke.start_W = plan.approach_start;
    stroke.direction_W = -plan.approach_out;
    stroke.push_W = plan.slide.front();
    stroke.retract_W = plan.retract_end;
    stroke.attempts = attempt + 1;
    const double press_speed = speed(0.1);
    stroke.speed_m_per_s = press_speed;
    if (continue_from) {
      TransitRequest request;
      request.from.p_W = *continue_from;
      request.to = TransitEnd{plan.approach_start, plan.approach_out};
      request.bounds_W = s.bounds_W;
      request.around = around;
      request.rims = s.closed ? nullptr : &rims_;
      const std::optional<Transit> transit = plan_free_transit(oracle_, request, tp, rng);
      if (transit) {
        const std::vector<Vector3d> samples =
            verify::sample_polyline(transit->corners_W, speed(0.4), params_.rate_Hz);
        stroke.p_W_hip.assign(samples.begin() + 1, samples.end() - 1);  // own samples start at the approach start
        stroke.connector_samples = stroke.p_W_hip.size();
        stroke.continues = true;
        stroke.transit_attempts = transit->attempts;
      } else {
        stroke.transit_attempts = tp.max_transit_attempts;  // no free transit: the proxy is reset
      }
    }
    auto append = [&](std::vector<Vector3d> corners, double v) {
      const std::vector<Vector3d> samples = verify::sample_polyline(corners, v, params_.rate_Hz);
      const bool joined = stroke.p_W_hip.size() > stroke.connector_samples;  // drop the shared first sample
      stroke.p_W_hip.insert(stroke.p_W_hip.end(), samples.begin() + (joined ? 1 : 0), samples.end());
    };
    append({plan.approach_start, plan.slide.front()}, press_speed);
    // At 5-60 % of max speed a slide lasts about a second at most.
    append(plan.slide, uniform_in(rng, 0.05, 0.6) * params_.max_speed_m_per_s);
    append({plan.slide.back(), plan.retract_end}, speed(0.1));
    return stroke;
  }
  throw std::runtime_error("stress strokes: no tour target with a free approach for stroke " + std::to_string(index) +
                           " in " + std::to_string(params_.max_attempts) + " draws");
}

}  // namespace mhd::stress
