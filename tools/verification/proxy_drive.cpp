#include "verification/proxy_drive.h"

#include <algorithm>
#include <stdexcept>

namespace mhd::verify {

TickRecord drive_proxy(const CollisionWorld& world, std::span<const HapticMaterial> materials,
                       const ProxySettings& settings, std::span<const Eigen::Vector3d> hip_path_W, double rate_Hz) {
  if (!(rate_Hz > 0.0)) throw std::invalid_argument("drive_proxy: rate_Hz must be > 0");
  TickRecord records;
  if (hip_path_W.empty()) return records;
  records.reserve(hip_path_W.size());
  const double dt_s = 1.0 / rate_Hz;
  ProxyState state;
  reset_proxy(state, hip_path_W.front());
  for (const Eigen::Vector3d& p_W_hip : hip_path_W) {
    const ProxyOutput out = step_proxy(world, materials, settings, state, p_W_hip, dt_s);
    records.push_back(make_tick_sample(p_W_hip, out, state));
  }
  return records;
}

TickSample make_tick_sample(const Eigen::Vector3d& p_W_hip, const ProxyOutput& out, const ProxyState& state) {
  TickSample s;
  s.p_W_hip = p_W_hip;
  s.proxy_W = out.proxy_W;
  s.force_W = out.force_W;
  s.in_contact = out.in_contact;
  s.force_clamped = out.force_clamped;
  s.plane_count = out.plane_count;
  s.path_points = state.path_points;
  s.path_W = state.path_W;
  return s;
}

TickRecord drive_proxy(const CompiledScene& scene, std::span<const Eigen::Vector3d> hip_path_W, double rate_Hz) {
  return drive_proxy(scene.world, scene.materials, scene.proxy, hip_path_W, rate_Hz);
}

std::vector<Crossing> find_crossings(const SurfaceCrossingOracle& oracle, const TickRecord& records) {
  std::vector<Crossing> crossings;
  auto check = [&](std::size_t tick, int leg, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    if (!oracle.segment_touches_surface(a, b)) return;
    Crossing c;
    c.tick = tick;
    c.leg = leg;
    c.from_W = a;
    c.to_W = b;
    if (const std::optional<OracleHit> hit = oracle.first_touched_triangle(a, b)) c.first_hit = *hit;
    crossings.push_back(c);
  };
  for (std::size_t k = 0; k < records.size(); ++k) {
    const TickSample& s = records[k];
    const int n = std::clamp(s.path_points, 0, kMaxProxyPath);
    // Where this tick's motion started: the previous proxy, or for the first tick the
    // start of its own path (the reset point).
    Eigen::Vector3d at = k > 0 ? records[k - 1].proxy_W : (n > 0 ? s.path_W[0] : s.proxy_W);
    if (k == 0) check(k, -1, at, at);  // the reset point itself must be free
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d& next = s.path_W[static_cast<std::size_t>(i)];
      if (next != at) check(k, i - 1, at, next);
      at = next;
    }
    if (s.proxy_W != at) check(k, n - 1, at, s.proxy_W);
  }
  return crossings;
}

std::size_t count_crossings(const SurfaceCrossingOracle& oracle, const TickRecord& records) {
  return find_crossings(oracle, records).size();
}

FollowCheck find_follow_failures(const SurfaceCrossingOracle& oracle, const TickRecord& records,
                                 const FollowTolerance& tolerance) {
  FollowCheck check;
  for (std::size_t k = 0; k < records.size(); ++k) {
    const TickSample& s = records[k];
    const Eigen::Vector3d previous = k > 0 ? records[k - 1].proxy_W : (s.path_points > 0 ? s.path_W[0] : s.proxy_W);
    const FollowVerdict v = check_follow(oracle, previous, s.p_W_hip, s.proxy_W, s.force_W, tolerance);
    if (v.hip_in_free_view && v.gap_m > check.max_free_gap_m) {
      check.max_free_gap_m = v.gap_m;
      check.force_at_max_free_gap_N = v.force_N;
    }
    if (v.failed()) check.failures.push_back(FollowFailure{k, v, previous, s.p_W_hip, s.proxy_W});
  }
  return check;
}

std::size_t count_ticks_inside(const SurfaceCrossingOracle& oracle, const TickRecord& records) {
  std::size_t inside = 0;
  for (const TickSample& s : records) {
    if (oracle.point_inside_closed_mesh(s.proxy_W)) ++inside;
  }
  return inside;
}

namespace {

bool is_held(const SurfaceCrossingOracle& oracle, const TickSample& s) {
  return (s.proxy_W - s.p_W_hip).norm() > kHeldGap_m && oracle.segment_meets_a_front(s.p_W_hip, s.proxy_W);
}

}  // namespace

std::size_t count_held_ticks(const SurfaceCrossingOracle& oracle, const TickRecord& records) {
  std::size_t held = 0;
  for (const TickSample& s : records) held += is_held(oracle, s) ? 1 : 0;
  return held;
}

std::size_t count_strokes_starting_behind(const SurfaceCrossingOracle& oracle, const TickRecord& records,
                                          std::span<const std::size_t> starts) {
  std::size_t behind = 0;
  for (const std::size_t tick : starts) behind += tick < records.size() && is_held(oracle, records[tick]) ? 1 : 0;
  return behind;
}

}  // namespace mhd::verify
