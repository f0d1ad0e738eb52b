#include "proxy/god_object.h"

#include "proxy/force_shading.h"
#include "proxy/proxy_motion.h"
#include "proxy/texture_force.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mhd {
namespace {

using proxy_detail::Motion;
using proxy_detail::TickWork;

// A constraint counts as active when the proxy is this close (fraction of the skin) to
// its offset plane.
constexpr double kActivePerSkin = 1e-2;
// Depth behind the surface, in skins, over which damping fades in (10 um at the default skin).
constexpr double kDampingOnsetPerSkin = 10.0;

// Copies the constraints the proxy rests on (up to three, nearest first) into state.
void store_active_planes(const Motion& m, double skin_m, ProxyState& state) {
  struct Candidate {
    double gap;
    int index;
  };
  std::array<Candidate, kMaxHalfSpaces> active{};
  int count = 0;
  for (int i = 0; i < m.plane_count; ++i) {
    const HalfSpace& h = m.planes[static_cast<std::size_t>(i)];
    const double gap = h.normal.dot(m.p) - h.offset;
    if (gap <= kActivePerSkin * skin_m) active[static_cast<std::size_t>(count++)] = Candidate{gap, i};
  }
  // Insertion sort by gap (at most six entries; stable, so ties keep discovery order).
  for (int i = 1; i < count; ++i) {
    const Candidate c = active[static_cast<std::size_t>(i)];
    int j = i - 1;
    for (; j >= 0 && active[static_cast<std::size_t>(j)].gap > c.gap; --j) {
      active[static_cast<std::size_t>(j + 1)] = active[static_cast<std::size_t>(j)];
    }
    active[static_cast<std::size_t>(j + 1)] = c;
  }
  state.plane_count = std::min(count, kMaxConstraintPlanes);
  for (int i = 0; i < state.plane_count; ++i) {
    const int src = active[static_cast<std::size_t>(i)].index;
    auto& dst = state.planes[static_cast<std::size_t>(i)];
    dst.normal_W = m.planes[static_cast<std::size_t>(src)].normal;
    dst.offset_m = m.planes[static_cast<std::size_t>(src)].offset;
    dst.triangle = m.plane_triangles[static_cast<std::size_t>(src)];
  }
}

const HapticMaterial& material_of(std::span<const HapticMaterial> materials, int object) {
  static const HapticMaterial kDefault{};
  if (object < 0 || static_cast<std::size_t>(object) >= materials.size()) return kDefault;
  return materials[static_cast<std::size_t>(object)];
}

// Force shading's second pass (proxy/force_shading.h): from the tick's start towards the
// shaded goal, held by the real surface. Kept when it ends in contact with the HIP out of
// the proxy's sight; otherwise (off an open boundary, out of work) the first pass stands.
// Returns the goal the proxy went for.
Eigen::Vector3d shade_motion(const CollisionWorld& world, double skin_m, const Eigen::Vector3d& start,
                             const Eigen::Vector3d& p_W_hip, const TriangleRef* resting_on, Motion& motion,
                             ProxyState& state, TickWork& work) {
  const auto goal = proxy_detail::shaded_goal_W(world, state, motion.p, p_W_hip, skin_m);
  if (!goal) return p_W_hip;
  const Motion unshaded = motion;
  const ProxyState unshaded_state = state;
  proxy_detail::solve_motion(world, skin_m, start, *goal, motion, state, work, resting_on);
  store_active_planes(motion, skin_m, state);
  bool keep = state.plane_count > 0 && !work.exhausted;
  if (keep && !proxy_detail::hip_hidden_by_contact(world, state, motion.p, p_W_hip)) {
    Motion probe = motion;
    ProxyState probe_state = state;
    keep = !proxy_detail::go_if_visible(world, skin_m, p_W_hip, probe, probe_state, work) && !work.exhausted;
  }
  if (keep) return *goal;
  motion = unshaded;
  state = unshaded_state;
  // The first pass was complete: running out in the optional second one is no shortfall.
  work.exhausted = false;
  work.sweep.exhausted = false;
  return p_W_hip;
}

}  // namespace

void reset_proxy(ProxyState& state, const Eigen::Vector3d& p_W_hip) {
  state = ProxyState{};
  state.proxy_W = p_W_hip;
  state.p_W_hip = p_W_hip;
  state.initialised = true;
  state.path_W[0] = p_W_hip;
  state.path_points = 1;
}

ProxyOutput step_proxy(const CollisionWorld& world, std::span<const HapticMaterial> materials,
                       const ProxySettings& settings, ProxyState& state, const Eigen::Vector3d& p_W_hip,
                       double dt_s, std::span<const ObjectTwist> twists) {
  ProxyOutput out;
  if (!p_W_hip.allFinite() || !std::isfinite(dt_s) || !(dt_s > 0.0)) {
    // Bad input: hold the proxy, command nothing.
    out.proxy_W = state.proxy_W;
    state.path_points = 1;
    state.path_W[0] = state.proxy_W;
    return out;
  }
  if (!state.initialised) reset_proxy(state, p_W_hip);

  // First-order low-pass of the HIP velocity for damping.
  const double alpha = 1.0 - std::exp(-2.0 * std::numbers::pi * settings.velocity_cutoff_Hz * dt_s);
  state.hip_velocity_W += alpha * ((p_W_hip - state.p_W_hip) / dt_s - state.hip_velocity_W);
  state.p_W_hip = p_W_hip;

  const Eigen::Vector3d start = state.proxy_W;
  const bool was_in_contact = state.plane_count > 0;
  // Kept for a tick that runs out of work before it moves (its contact goes on).
  const std::array<ConstraintPlane, kMaxConstraintPlanes> previous_planes = state.planes;
  const int previous_plane_count = state.plane_count;

  // Part of the budget is kept back for a last look at the HIP should the motion run out
  // of work: a proxy that has slid a long way round a rim into the open must not end the
  // tick short of a HIP it can see.
  const int max_sweeps = std::clamp(settings.max_sweeps_per_tick, 1, kMaxProxySweeps);
  const int max_triangle_tests = std::max(settings.max_triangle_tests_per_tick, 1);
  TickWork work;
  work.near = &state.near;
  work.max_sweeps = max_sweeps - std::clamp(max_sweeps / 16, max_sweeps >= 2 ? 1 : 0, 4);
  work.sweep.max_triangle_tests = max_triangle_tests - max_triangle_tests / 8;
  work.sweep.fine_pieces = state.ran_out;
  Motion motion;
  const TriangleRef resting_on = previous_planes[0].triangle;
  proxy_detail::solve_motion(world, settings.skin_m, start, p_W_hip, motion, state, work,
                             previous_plane_count > 0 ? &resting_on : nullptr);
  store_active_planes(motion, settings.skin_m, state);

  // What the proxy is drawn to: the HIP, or with force shading its foot on the shaded planes.
  Eigen::Vector3d goal_W = p_W_hip;
  if (state.plane_count > 0 && !work.exhausted &&
      material_of(materials, state.planes[0].triangle.object).force_shading) {
    goal_W = shade_motion(world, settings.skin_m, start, p_W_hip, previous_plane_count > 0 ? &resting_on : nullptr,
                          motion, state, work);
  }

  bool sticking = false;
  if (state.plane_count > 0 && was_in_contact) {
    const HapticMaterial& mat = material_of(materials, state.planes[0].triangle.object);
    const Eigen::Vector3d to_proxy = motion.p - p_W_hip;
    const double depth = to_proxy.norm();
    // A friction map scales both coefficients where the proxy rests (docs/textures.md).
    const double mu_scale = texture_friction_scale(world, mat, state.planes[0].triangle.object, start);
    const double static_friction = mu_scale * mat.static_friction;
    const double dynamic_friction = mu_scale * mat.dynamic_friction;
    if ((static_friction > 0.0 || dynamic_friction > 0.0) && depth > 0.0) {
      // Friction cone around the frictionless proxy: the previous proxy may stay put
      // while its tangential offset is within mu_s * depth (static), else it slides
      // to the dynamic cone's rim (mu_d * depth behind the frictionless point).
      const Eigen::Vector3d n = to_proxy / depth;
      const Eigen::Vector3d offset = start - motion.p;
      const Eigen::Vector3d tangential = offset - n * n.dot(offset);
      const double slip = tangential.norm();
      if (slip <= static_friction * depth) {
        sticking = true;
        motion.p = start;
        state.path_points = 1;
        state.path_W[0] = start;
      } else if (dynamic_friction > 0.0 && slip > 0.0) {
        const Eigen::Vector3d goal = goal_W + tangential * (dynamic_friction * depth / slip);
        // The frictionless motion and its path, kept in case the slide ends off the surface.
        const ProxyState frictionless = state;
        Motion sliding;
        proxy_detail::solve_motion(world, settings.skin_m, start, goal, sliding, state, work);
        store_active_planes(sliding, settings.skin_m, state);
        if (state.plane_count > 0) {
          motion = sliding;
          // The cone's rim is not the hand: slid to where the rim is blocked, the proxy
          // may see the HIP itself (round an edge), and then it goes there, free.
          if (proxy_detail::go_if_visible(world, settings.skin_m, p_W_hip, motion, state, work)) state.plane_count = 0;
        } else {
          // The rim of the cone lies in free space (the surface turned away): friction has
          // nothing to act on, and the proxy must not stop short of the hand there.
          state = frictionless;
        }
      }
    }
  }

  if (work.exhausted && motion.p != p_W_hip) {
    work.max_sweeps = max_sweeps;
    work.sweep.max_triangle_tests = max_triangle_tests;
    work.sweep.exhausted = false;
    work.sweep.fine_pieces = true;
    if (proxy_detail::go_if_visible(world, settings.skin_m, p_W_hip, motion, state, work)) {
      state.plane_count = 0;
      sticking = false;
    }
  }
  if (work.exhausted && (motion.p == start || work.went_partway) && state.plane_count == 0) {
    // Out of work before the proxy moved, or with it part of the way along a leg: last
    // tick's contact goes on, so the force goes on as a spring to the HIP instead of
    // dropping to zero.
    state.planes = previous_planes;
    state.plane_count = previous_plane_count;
  }
  out.sweeps = work.sweeps;
  out.sweeps_at_once = work.sweeps_at_once;
  out.triangle_tests = work.sweep.triangle_tests;
  out.budget_exhausted = work.exhausted;
  state.ran_out = work.exhausted;
  state.proxy_W = motion.p;
  state.sticking = sticking;
  out.proxy_W = motion.p;
  out.sticking = sticking;
  out.plane_count = state.plane_count;

  const Eigen::Vector3d to_proxy = motion.p - p_W_hip;
  const double depth = to_proxy.norm();
  // Contact starts when the HIP is behind the surface of a plane the proxy rests on;
  // a HIP inside the proxy's skin, or beside it, touches nothing (no spring, no damping).
  double behind_m = 0.0;  // how far the HIP is behind the surface of a plane it rests on
  for (int i = 0; i < state.plane_count; ++i) {
    const ConstraintPlane& plane = state.planes[static_cast<std::size_t>(i)];
    behind_m = std::max(behind_m, plane.offset_m - settings.skin_m - plane.normal_W.dot(p_W_hip));
  }
  if (!(behind_m > 0.0) || !(depth > 0.0)) return out;

  const int object = state.planes[0].triangle.object;
  const HapticMaterial& mat = material_of(materials, object);
  out.in_contact = true;
  out.contact_object = object;

  Eigen::Vector3d force = mat.stiffness_N_per_m * to_proxy;
  const Eigen::Vector3d n_contact = to_proxy / depth;
  if (mat.texture) {
    // The texture shapes the force on top of the smooth surface's; the proxy stays on the
    // real surface. On an edge or corner the spring's direction stands in for the normal.
    const Eigen::Vector3d n_surface = state.plane_count == 1 ? state.planes[0].normal_W : n_contact;
    force = textured_force(world, mat, object, motion.p, n_surface, force);
  }
  if (mat.damping_Ns_per_m > 0.0) {
    // Damping fades in over the first kDampingOnsetPerSkin skins of depth: a HIP grazing a
    // surface within micrometres gets no kick of b * v from a contact it barely makes.
    const double onset = std::min(1.0, behind_m / (kDampingOnsetPerSkin * settings.skin_m));
    // Against a moving surface the damper acts on the velocity relative to it.
    Eigen::Vector3d v_W_relative = state.hip_velocity_W;
    if (static_cast<std::size_t>(object) < twists.size()) {
      v_W_relative -= point_velocity_W(twists[static_cast<std::size_t>(object)], world.pose(object).translation(),
                                       motion.p);
    }
    force -= onset * mat.damping_Ns_per_m * v_W_relative.dot(n_contact) * n_contact;
    // Damping may slow the push-back but never pull the hand into the surface.
    const double normal = force.dot(n_contact);
    if (normal < 0.0) force -= normal * n_contact;
  }
  const double magnitude = force.norm();
  if (magnitude > settings.max_force_N) {
    force *= settings.max_force_N / magnitude;
    out.force_clamped = true;
  }
  out.force_W = force.allFinite() ? force : Eigen::Vector3d::Zero();
  return out;
}

}  // namespace mhd
