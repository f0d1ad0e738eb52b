#include "stress/stress_run.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

namespace mhd::stress {
namespace {

// Log-spaced histogram of per-tick times: bin b holds [0.01 us * 10^(b/20), ... * 10^((b+1)/20)).
class TimeHistogram {
 public:
  void add(double us) {
    max_us_ = std::max(max_us_, us);
    const double b = us > kLow_us ? std::floor(kBinsPerDecade * std::log10(us / kLow_us)) : 0.0;
    ++bins_[static_cast<std::size_t>(std::clamp(b, 0.0, static_cast<double>(kBins - 1)))];
    ++count_;
  }
  // Upper edge of the bin holding quantile q (capped by the exact maximum).
  [[nodiscard]] double quantile_us(double q) const {
    if (count_ == 0) return 0.0;
    const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(count_)));
    std::size_t seen = 0;
    for (std::size_t b = 0; b < kBins; ++b) {
      seen += bins_[b];
      if (seen >= rank) return std::min(max_us_, kLow_us * std::pow(10.0, static_cast<double>(b + 1) / kBinsPerDecade));
    }
    return max_us_;
  }
  [[nodiscard]] double max_us() const { return max_us_; }

 private:
  static constexpr double kLow_us = 0.01;
  static constexpr double kBinsPerDecade = 20.0;
  static constexpr std::size_t kBins = 200;  // up to 10^8 us
  std::array<std::size_t, kBins> bins_{};
  std::size_t count_ = 0;
  double max_us_ = 0.0;
};

void print_vec(std::FILE* out, const Eigen::Vector3d& v) { fmt::print(out, "{:.17g} {:.17g} {:.17g}", v.x(), v.y(), v.z()); }

// Runs strokes [first, last) of the object's stream; chains start at multiples of the
// chain length. With a trace, prints every tick of the traced stroke.
ObjectStressReport run_range(const CompiledScene& scene, const verify::SurfaceCrossingOracle& oracle, int object,
                             std::uint64_t object_key, const StressSettings& settings, std::size_t first,
                             std::size_t last, const StressTrace& trace) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  ObjectStressReport r;
  r.object_name = static_cast<std::size_t>(object) < scene.object_names.size()
                      ? scene.object_names[static_cast<std::size_t>(object)]
                      : std::to_string(object);
  r.closed = oracle.is_closed(object);
  const ObjectSurface surface = make_object_surface(scene.world, object, r.closed);
  r.triangles = surface.triangles_W.size();
  r.ridges = surface.ridges.size();
  r.creases = surface.creases.size();
  r.corners = surface.corners.size();
  const StressStrokeGenerator generator(scene.world, oracle, surface, settings.stroke);
  PopThroughChecker checker(scene.world, oracle, settings.engine, settings.engine_stride,
                            verify::follow_tolerance(scene.materials, settings.follow_tolerance_m));
  const double dt_s = 1.0 / settings.stroke.rate_Hz;
  const std::size_t chain = std::max<std::size_t>(settings.chain_length, 1);

  ProxyState state;
  TimeHistogram step_times;
  std::optional<Eigen::Vector3d> last_hip;
  std::size_t follow_run = 0;  // consecutive follow-failure ticks so far
  for (std::size_t i = first; i < last; ++i) {
    if (i % chain == 0 || i == first) last_hip.reset();
    const bool tour = generator.is_tour_chain(settings.seed, object_key, i - i % chain);
    const StressStroke stroke = tour ? generator.make_tour(settings.seed, object_key, i, last_hip)
                                     : generator.make(settings.seed, object_key, i, last_hip);
    const bool reset = !stroke.continues;
    if (reset) ++r.resets;
    ++r.strokes;
    ++r.strokes_by_kind[static_cast<std::size_t>(stroke.kind)];
    r.start_redraws += static_cast<std::size_t>(stroke.attempts - 1);
    const bool traced = trace.out != nullptr && trace.stroke == i;
    if (traced) {
      fmt::print(trace.out, "stroke {}: {} at {:.3f} m/s, {} ticks ({} connector), {}\n", i, to_string(stroke.kind),
                 stroke.speed_m_per_s, stroke.p_W_hip.size(), stroke.connector_samples,
                 reset ? "proxy reset at the start" : "continuing the previous stroke");
      fmt::print(trace.out, "  start ");
      print_vec(trace.out, stroke.start_W);
      fmt::print(trace.out, "  direction ");
      print_vec(trace.out, stroke.direction_W);
      if (stroke.kind == StrokeKind::Tour) {
        fmt::print(trace.out, "\n  push ");
        print_vec(trace.out, stroke.push_W);
        fmt::print(trace.out, "  retract ");
        print_vec(trace.out, stroke.retract_W);
        fmt::print(trace.out, "  transit drawn {} times", stroke.transit_attempts);
      }
      fmt::print(trace.out, "\n  tick  p_W_hip                                    proxy_W                                  "
                            "contact planes path  crossed inside engine depth_m   follow gap_mm free force_N\n");
    }
    std::optional<StrokeFailure> failure;
    auto note = [&](std::size_t tick, const Eigen::Vector3d& hip, const Eigen::Vector3d& proxy, const TickVerdict& v) {
      if (v.inside) ++r.inside_ticks;
      if (v.crossed) ++r.crossing_ticks;
      if (v.engine_checked) ++r.engine_checks;
      if (v.inside_engine) ++r.inside_engine_ticks;
      r.worst_penetration_m = std::max(r.worst_penetration_m, v.penetration_m);
      follow_run = v.follow_failed ? follow_run + 1 : 0;
      if (v.follow_failed) ++r.follow_failure_ticks;
      if (v.follow_kind == verify::FollowFailureKind::Stuck) ++r.stuck_ticks;
      if (v.follow_brushed) ++r.brushed_ticks;
      r.longest_follow_failure_ticks = std::max(r.longest_follow_failure_ticks, follow_run);
      if (v.hip_in_free_view && v.follow_gap_m > r.max_free_gap_m) {
        r.max_free_gap_m = v.follow_gap_m;
        r.force_at_max_free_gap_N = v.force_N;
      }
      if (v.failed() && !failure) failure = StrokeFailure{i, stroke.kind, tick, hip, proxy, v};
    };
    if (reset) {
      follow_run = 0;
      reset_proxy(state, stroke.p_W_hip.front());
      note(0, stroke.p_W_hip.front(), state.proxy_W, checker.check_reset(state.proxy_W));
    }
    for (std::size_t k = 0; k < stroke.p_W_hip.size(); ++k) {
      const Eigen::Vector3d& hip = stroke.p_W_hip[k];
      const auto t_step = Clock::now();
      ProxyOutput out = step_proxy(scene.world, scene.materials, scene.proxy, state, hip, dt_s);
      step_times.add(std::chrono::duration<double, std::micro>(Clock::now() - t_step).count());
      if (settings.tamper) settings.tamper(hip, state, out);
      const std::span<const Eigen::Vector3d> path(state.path_W.data(),
                                                  static_cast<std::size_t>(std::clamp(state.path_points, 0, kMaxProxyPath)));
      const TickVerdict v = checker.check_tick(hip, path, out.proxy_W, out.force_W, out.in_contact);
      ++r.ticks;
      if (out.in_contact) {
        ++r.contact_ticks;
        r.max_hip_depth_m = std::max(r.max_hip_depth_m, (out.proxy_W - hip).norm());
      }
      r.max_plane_count = std::max(r.max_plane_count, out.plane_count);
      note(k, hip, out.proxy_W, v);
      if (traced) {
        fmt::print(trace.out, "  {:4d}  ", k);
        print_vec(trace.out, hip);
        fmt::print(trace.out, "  ");
        print_vec(trace.out, out.proxy_W);
        fmt::print(trace.out, "  {:7} {:6} {:4}  {:7} {:6} {:6} {:.3e} {:>6} {:9.4f} {:4} {:7.3f}\n",
                   out.in_contact ? "yes" : "no", out.plane_count, state.path_points, v.crossed ? "YES" : "no",
                   v.inside ? "YES" : "no", !v.engine_checked ? "-" : (v.inside_engine ? "YES" : "no"),
                   v.penetration_m,
                   !v.follow_failed                                     ? "ok"
                   : v.follow_kind == verify::FollowFailureKind::Stuck ? "STUCK"
                                                                        : "FORCE",
                   1e3 * v.follow_gap_m, v.hip_in_free_view ? "yes" : "no", v.force_N);
        if (v.crossed) {
          fmt::print(trace.out, "        leg {} from ", v.leg);
          print_vec(trace.out, v.leg_from_W);
          fmt::print(trace.out, " to ");
          print_vec(trace.out, v.leg_to_W);
          if (v.hit) fmt::print(trace.out, " touches object {} triangle {} at t = {:.6f}", v.hit->where.object,
                                v.hit->where.triangle, v.hit->t);
          fmt::print(trace.out, "\n");
        }
      }
    }
    last_hip = stroke.p_W_hip.back();
    if (failure) {
      ++r.failing_strokes;
      ++r.failing_strokes_by_kind[static_cast<std::size_t>(failure->kind)];
      if (r.failures.size() < settings.max_failures_kept) r.failures.push_back(*failure);
    }
  }
  r.step_median_us = step_times.quantile_us(0.5);
  r.step_p99_us = step_times.quantile_us(0.99);
  r.step_p999_us = step_times.quantile_us(0.999);
  r.step_max_us = step_times.max_us();
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return r;
}

}  // namespace

ObjectStressReport stress_object(const CompiledScene& scene, const verify::SurfaceCrossingOracle& oracle, int object,
                                 std::uint64_t object_key, const StressSettings& settings) {
  return run_range(scene, oracle, object, object_key, settings, 0, settings.strokes, StressTrace{});
}

ObjectStressReport replay_stroke(const CompiledScene& scene, const verify::SurfaceCrossingOracle& oracle, int object,
                                 std::uint64_t object_key, const StressSettings& settings, std::size_t stroke,
                                 std::FILE* out) {
  const std::size_t chain = std::max<std::size_t>(settings.chain_length, 1);
  const std::size_t first = stroke - stroke % chain;
  return run_range(scene, oracle, object, object_key, settings, first, stroke + 1, StressTrace{out, stroke});
}

}  // namespace mhd::stress
