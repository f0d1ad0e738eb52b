#include "stress/moving_stress_run.h"

#include "stress/stress_mover.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>

namespace mhd::stress {
namespace {

// The one place where the stress chooses what moves the objects (stress_mover.h).
std::unique_ptr<StressMover> make_mover(const CompiledScene& scene, int object, const StressMotion& m,
                                        const MovingStressSettings& settings) {
  if (settings.mover == MoverKind::Pushed) {
    const ObjectTwist throw_W{m.motion.v_W_origin_at(0.0), m.motion.omega_W_at(0.0)};
    PushedBodyParams body = settings.pushed;
    body.hand_speed_mps = settings.stroke.max_speed_m_per_s;
    body.hand_rate_radps = settings.motion.max_rate_radps;
    return std::make_unique<PushedMover>(scene, object, throw_W, body, 1.0 / settings.stroke.rate_Hz);
  }
  std::vector<std::optional<ObjectMotion>> motions(static_cast<std::size_t>(scene.world.object_count()));
  motions[static_cast<std::size_t>(object)] = m.motion;
  return std::make_unique<ScriptedMover>(scene.world, std::move(motions), object);
}

void print_vector(std::FILE* out, const Eigen::Vector3d& v) { fmt::print(out, "{:.9f} {:.9f} {:.9f}", v.x(), v.y(), v.z()); }

MovingStressReport run_range(const CompiledScene& scene, int object, std::uint64_t object_key,
                             const MovingStressSettings& settings, std::size_t first, std::size_t last,
                             std::FILE* trace, std::size_t traced_stroke) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const auto o = static_cast<std::size_t>(object);
  MovingStressReport r;
  r.object_name = o < scene.object_names.size() ? scene.object_names[o] : std::to_string(object);
  const verify::SurfaceCrossingOracle oracle(scene.world);  // the strokes' starts, at t = 0
  r.closed = oracle.is_closed(object);
  const ObjectSurface surface = make_object_surface(scene.world, object, r.closed);
  r.triangles = surface.triangles_W.size();
  const StressStrokeGenerator generator(scene.world, oracle, surface, settings.stroke);
  verify::MovingTickCheck check(scene.world);

  const Pose X_WO_start = scene.world.pose(object);
  const Pose X_OW_start = X_WO_start.inverse(Eigen::Isometry);
  const Eigen::Vector3d p_W_centre = surface.bounds_W.center();
  double reach_m = 0.0;  // farthest vertex from the object's origin
  for (const auto& tri : surface.triangles_W) {
    for (const auto& v : tri) reach_m = std::max(reach_m, (v - X_WO_start.translation()).norm());
  }
  const double dt_s = 1.0 / settings.stroke.rate_Hz;
  const std::size_t chain = std::max<std::size_t>(settings.chain_length, 1);
  const double skin_m = scene.proxy.skin_m;

  ProxyState state;
  ProxyOutput last_out;
  std::optional<Eigen::Vector3d> last_hip;  // in the strokes' frame (the object at its start)
  StressMotion motion;
  std::unique_ptr<StressMover> mover;
  double t_s = 0.0;  // the motion's clock, restarted at each proxy reset
  // Squeezed against a still surface, the proxy may be overlapped by the moving object
  // (docs/proxy.md): from the squeeze until it is clear of that object again.
  bool overlapping = false;
  // A pushed body is thrown with a twist's starting velocity (keyframed motions start slow).
  MotionDrawParams motion_params = settings.motion;
  if (settings.mover == MoverKind::Pushed) motion_params.weight_loop = motion_params.weight_pingpong = 0.0;
  for (std::size_t i = first; i < last; ++i) {
    const std::size_t chain_first = i - i % chain;
    const bool traced = trace != nullptr && i == traced_stroke;
    if (i == chain_first || i == first) {
      last_hip.reset();
      motion = draw_stress_motion(settings.seed, object_key, chain_first, X_WO_start, p_W_centre, motion_params);
      mover = make_mover(scene, object, motion, settings);
      ++r.chains;
      ++r.chains_by_motion[static_cast<std::size_t>(motion.kind)];
      ++r.chains_by_anchor[static_cast<std::size_t>(motion.anchor)];
      r.max_object_speed_mps = std::max(r.max_object_speed_mps, motion.motion.max_speed_mps());
      r.max_object_rate_radps = std::max(r.max_object_rate_radps, motion.motion.max_rate_radps());
      r.max_surface_speed_mps = std::max(r.max_surface_speed_mps,
                                         motion.motion.max_speed_mps() + motion.motion.max_rate_radps() * reach_m);
    }
    const bool tour = generator.is_tour_chain(settings.seed, object_key, chain_first);
    const StressStroke stroke = tour ? generator.make_tour(settings.seed, object_key, i, last_hip)
                                     : generator.make(settings.seed, object_key, i, last_hip);
    ++r.strokes;
    ++r.strokes_by_kind[static_cast<std::size_t>(stroke.kind)];
    // The stroke's sample at chain time t, carried by the object as it moved (the anchor).
    const auto hip_at = [&](const Eigen::Vector3d& p_W_stroke, double at_s) {
      return Eigen::Vector3d(mover->X_WO_at(motion.anchor_time_s(at_s)) * (X_OW_start * p_W_stroke));
    };
    if (!stroke.continues) {
      ++r.resets;
      t_s = 0.0;
      mover->restart(t_s);
      reset_proxy(state, hip_at(stroke.p_W_hip.front(), t_s));
      last_out = ProxyOutput{};
      last_out.proxy_W = state.proxy_W;
    }
    if (traced) {
      fmt::print(trace, "stroke {}: {} at {:.3f} m/s, {} ticks ({} connector), {}\n", i, to_string(stroke.kind),
                 stroke.speed_m_per_s, stroke.p_W_hip.size(), stroke.connector_samples,
                 stroke.continues ? "continuing the previous stroke" : "proxy reset at the start");
      fmt::print(trace, "  chain {}: {} motion (origin up to {:.3f} m/s, up to {:.1f} deg/s), strokes {}", chain_first,
                 to_string(motion.kind), motion.motion.max_speed_mps(),
                 motion.motion.max_rate_radps() * 180.0 / std::numbers::pi, to_string(motion.anchor));
      if (motion.anchor == StrokeAnchor::Lagging) fmt::print(trace, " {:.3f} s behind", motion.lag_s);
      fmt::print(trace, "\n  tick t_s p_W_hip proxy_W contact carry(ride/push/squeeze) crossed inside not_followed "
                        "free_force overlap gap_mm\n");
    }
    if (!stroke.continues) overlapping = false;
    std::optional<MovingStrokeFailure> failure;
    std::size_t pushes = 0;
    for (std::size_t k = 0; k < stroke.p_W_hip.size(); ++k) {
      t_s += dt_s;
      check.before_move(mover->world());
      const Eigen::Vector3d p_before_W = state.proxy_W;
      CarryOutput carry;
      if (settings.fault_skip_carry) {
        const ProxyState uncarried = state;
        (void)mover->advance(t_s, state, skin_m, last_out);
        state = uncarried;
      } else {
        carry = mover->advance(t_s, state, skin_m, last_out);
      }
      // After the move: a riding hand follows a pushed body's pose at t_s.
      const Eigen::Vector3d p_W_hip = hip_at(stroke.p_W_hip[k], t_s);
      const Eigen::Vector3d p_carried_W = state.proxy_W;
      const ProxyOutput out =
          step_proxy(mover->world(), scene.materials, scene.proxy, state, p_W_hip, dt_s, mover->twists());
      const auto path_points = static_cast<std::size_t>(std::clamp(state.path_points, 0, kMaxProxyPath));
      overlapping = overlapping || carry.squeezed;
      const verify::MovingTickVerdict v =
          check.judge(mover->world(), p_before_W, p_carried_W,
                      std::span<const Eigen::Vector3d>(state.path_W.data(), path_points), out, p_W_hip,
                      overlapping ? object : -1);
      r.overlap_ticks += v.overlap ? 1 : 0;
      overlapping = v.overlap;
      last_out = out;
      ++r.ticks;
      if (!mover->twists().empty()) {
        const ObjectTwist& twist = mover->twists()[o];
        const double speed_mps = twist.v_W_origin_mps.norm();
        const double rate_radps = twist.omega_W_radps.norm();
        r.max_reached_speed_mps = std::max(r.max_reached_speed_mps, speed_mps);
        r.max_reached_rate_radps = std::max(r.max_reached_rate_radps, rate_radps);
        r.max_reached_surface_speed_mps = std::max(r.max_reached_surface_speed_mps, speed_mps + rate_radps * reach_m);
      }
      r.max_travel_m = std::max(
          r.max_travel_m, (mover->world().pose(object).translation() - X_WO_start.translation()).norm());
      r.object_force_ticks += out.in_contact && out.contact_object == object && out.force_W.squaredNorm() > 0.0 ? 1 : 0;
      if (out.in_contact) {
        ++r.contact_ticks;
        r.max_hip_depth_m = std::max(r.max_hip_depth_m, (out.proxy_W - p_W_hip).norm());
      }
      pushes += carry.pushed > 0 ? 1 : 0;
      r.squeeze_ticks += carry.squeezed ? 1 : 0;
      r.ride_ticks += carry.rode > 0 ? 1 : 0;
      r.crossing_ticks += v.crossed ? 1 : 0;
      r.inside_ticks += v.inside ? 1 : 0;
      r.not_followed_ticks += v.not_followed ? 1 : 0;
      r.free_force_ticks += v.free_force ? 1 : 0;
      if (v.failed() && !failure) failure = MovingStrokeFailure{i, stroke.kind, motion.kind, k, p_W_hip, out.proxy_W, v};
      if (traced) {
        fmt::print(trace, "  {:4d} {:.3f} ", k, t_s);
        print_vector(trace, p_W_hip);
        fmt::print(trace, "  ");
        print_vector(trace, out.proxy_W);
        fmt::print(trace, "  {} {}{}{} {} {} {} {} {} {:.4f}\n", out.in_contact ? "yes" : "no",
                   carry.rode > 0 ? "R" : "-", carry.pushed > 0 ? "P" : "-", carry.squeezed ? "S" : "-",
                   v.crossed ? "YES" : "no", v.inside ? "YES" : "no", v.not_followed ? "YES" : "no",
                   v.free_force ? "YES" : "no", v.overlap ? "yes" : "no", 1e3 * (out.proxy_W - p_W_hip).norm());
      }
    }
    r.push_ticks += pushes;
    r.strokes_with_push += pushes > 0 ? 1 : 0;
    if (pushes > r.busiest_stroke_pushes) {
      r.busiest_stroke_pushes = pushes;
      r.busiest_stroke = i;
    }
    last_hip = stroke.p_W_hip.back();
    if (failure) {
      ++r.failing_strokes;
      if (r.failures.size() < settings.max_failures_kept) r.failures.push_back(*failure);
    }
  }
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return r;
}

}  // namespace

MovingStressReport stress_moving_object(const CompiledScene& scene, int object, std::uint64_t object_key,
                                        const MovingStressSettings& settings) {
  return run_range(scene, object, object_key, settings, 0, settings.strokes, nullptr, 0);
}

MovingStressReport replay_moving_stroke(const CompiledScene& scene, int object, std::uint64_t object_key,
                                        const MovingStressSettings& settings, std::size_t stroke, std::FILE* out) {
  const std::size_t chain = std::max<std::size_t>(settings.chain_length, 1);
  return run_range(scene, object, object_key, settings, stroke - stroke % chain, stroke + 1, out, stroke);
}

}  // namespace mhd::stress
