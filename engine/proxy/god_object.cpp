#include "proxy/god_object.h"

#include "proxy/constraint_projection.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mhd {
namespace {

// Triangles a pass may set aside (collected planes plus coplanar twins at shared edges).
constexpr int kMaxIgnored = 16;
// Moves shorter than this fraction of the skin are skipped: they cannot matter to force
// and a zero-length sweep has no direction.
constexpr double kMinStepPerSkin = 1e-3;
// A constraint counts as active when the proxy is this close (fraction of the skin) to
// its offset plane, and the projection may violate a plane by this much.
constexpr double kActivePerSkin = 1e-2;
constexpr double kFeasibleTolerancePerSkin = 1e-3;
// A constraint is released once the proxy's projection leaves its triangle by more
// than this (fraction of the skin). It exceeds the sweep's own inflation (one skin),
// so a triangle just hit is never released at once.
constexpr double kReleaseMarginPerSkin = 2.0;

// A triangle set aside by the sweeps of a pass, and the constraint plane it belongs
// to: its own, or that of a coplanar neighbour (a twin) it duplicates.
struct IgnoredTriangle {
  TriangleRef triangle;
  int plane = 0;
};

// One pass of constrained motion: the proxy moving from a start towards a goal.
struct Motion {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  std::array<HalfSpace, kMaxHalfSpaces> planes{};
  std::array<TriangleRef, kMaxHalfSpaces> plane_triangles{};
  int plane_count = 0;
  std::array<IgnoredTriangle, kMaxIgnored> ignored{};
  std::array<TriangleRef, kMaxIgnored> ignored_refs{};  // the same triangles, as sweep() takes them
  int ignored_count = 0;

  void remove_ignored(int index) {
    --ignored_count;
    ignored[static_cast<std::size_t>(index)] = ignored[static_cast<std::size_t>(ignored_count)];
    ignored_refs[static_cast<std::size_t>(index)] = ignored_refs[static_cast<std::size_t>(ignored_count)];
  }
};

void append_path(ProxyState& state, const Eigen::Vector3d& p) {
  // solve_motion appends at most one point per iteration, so this never overflows.
  state.path_W[static_cast<std::size_t>(state.path_points)] = p;
  ++state.path_points;
}

// Drops the constraints whose triangles (own and twins) the proxy has slid off, past
// a convex edge: such a plane no longer bounds free space around the proxy. Their
// triangles stop being ignored, so later sweeps test them again. Returns true if any went.
bool release_passed_constraints(const CollisionWorld& world, Motion& m, double skin_m) {
  bool released = false;
  for (int i = 0; i < m.plane_count;) {
    bool supported = false;
    for (int j = 0; j < m.ignored_count && !supported; ++j) {
      const IgnoredTriangle& t = m.ignored[static_cast<std::size_t>(j)];
      supported = t.plane == i && world.projects_onto_triangle(t.triangle, m.p, kReleaseMarginPerSkin * skin_m);
    }
    if (supported) {
      ++i;
      continue;
    }
    released = true;
    for (int j = 0; j < m.ignored_count;) {
      if (m.ignored[static_cast<std::size_t>(j)].plane == i) {
        m.remove_ignored(j);
      } else {
        ++j;
      }
    }
    // Move the last plane into slot i and renumber its triangles.
    const int last = --m.plane_count;
    m.planes[static_cast<std::size_t>(i)] = m.planes[static_cast<std::size_t>(last)];
    m.plane_triangles[static_cast<std::size_t>(i)] = m.plane_triangles[static_cast<std::size_t>(last)];
    for (int j = 0; j < m.ignored_count; ++j) {
      if (m.ignored[static_cast<std::size_t>(j)].plane == last) m.ignored[static_cast<std::size_t>(j)].plane = i;
    }
  }
  return released;
}

// Records a surface the proxy ran into. Returns false when the pass has no room left,
// which ends the pass with the proxy where it is.
bool add_constraint(Motion& m, const SweepHit& hit, double skin_m) {
  if (m.ignored_count == kMaxIgnored) return false;
  const double offset = hit.plane_offset_m + skin_m;
  int plane = -1;
  for (int i = 0; i < m.plane_count && plane < 0; ++i) {
    const HalfSpace& h = m.planes[static_cast<std::size_t>(i)];
    // A coplanar neighbour (flat region, shared edge) adds no new constraint.
    if (h.normal.dot(hit.normal_W) > 1.0 - 1e-12 && std::abs(h.offset - offset) < kFeasibleTolerancePerSkin * skin_m) {
      plane = i;
    }
  }
  if (plane < 0) {
    if (m.plane_count == kMaxHalfSpaces) return false;
    plane = m.plane_count++;
    m.planes[static_cast<std::size_t>(plane)] = HalfSpace{hit.normal_W, offset};
    m.plane_triangles[static_cast<std::size_t>(plane)] = hit.where;
  }
  m.ignored[static_cast<std::size_t>(m.ignored_count)] = IgnoredTriangle{hit.where, plane};
  m.ignored_refs[static_cast<std::size_t>(m.ignored_count)] = hit.where;
  ++m.ignored_count;
  return true;
}

// Starts a pass with the planes the proxy rested on last tick, so a contact tick does
// not first sweep just to find the same triangle again. Each plane is rebuilt from its
// triangle's current pose (an object may have moved) and kept only while the proxy is
// on its free side; the pass then keeps every move inside it, so the triangle, now
// ignored by the sweeps, still cannot be crossed.
void seed_constraints(const CollisionWorld& world, std::span<const ConstraintPlane> previous,
                      const Eigen::Vector3d& p, double skin_m, Motion& m) {
  for (const ConstraintPlane& plane : previous) {
    const auto v = world.triangle_W(plane.triangle);
    const Eigen::Vector3d area_normal = (v[1] - v[0]).cross(v[2] - v[0]);
    const double twice_area = area_normal.norm();
    if (!(twice_area > 0.0)) continue;
    Eigen::Vector3d n = area_normal / twice_area;
    if (n.dot(plane.normal_W) < 0.0) n = -n;
    const double surface_offset = n.dot(v[0]);
    if (n.dot(p) - (surface_offset + skin_m) < -kActivePerSkin * skin_m) continue;
    SweepHit seed;
    seed.where = plane.triangle;
    seed.normal_W = n;
    seed.plane_offset_m = surface_offset;
    if (!add_constraint(m, seed, skin_m)) return;
  }
}

// Moves the proxy from `start` towards `goal`: project the goal onto the collected
// constraints, sweep there, and on each hit stop short by the skin and add the hit
// plane. A move that carries the proxy off a triangle (past a convex edge) releases
// that triangle's plane. Once a move completes, probe the straight line to the goal for a surface not
// yet collected (a convex edge seen from the far face) and go on until nothing new is
// found. Every leg is swept, and legs inside collected half-spaces cannot cross the
// triangles that made them, so the proxy never crosses the surface.
void solve_motion(const CollisionWorld& world, const ProxySettings& settings, const Eigen::Vector3d& start,
                  const Eigen::Vector3d& goal, std::span<const ConstraintPlane> previous_planes, Motion& m,
                  ProxyState& state) {
  const double skin = settings.skin_m;
  const double min_step_sq = (kMinStepPerSkin * skin) * (kMinStepPerSkin * skin);
  m.p = start;
  seed_constraints(world, previous_planes, start, skin, m);
  state.path_points = 0;
  append_path(state, start);
  for (int iteration = 0; iteration < kMaxProxyIterations; ++iteration) {
    const std::span<const HalfSpace> planes(m.planes.data(), static_cast<std::size_t>(m.plane_count));
    const auto target = project_onto_half_spaces(goal, planes, kFeasibleTolerancePerSkin * skin);
    if (!target) return;
    const std::span<const TriangleRef> ignored(m.ignored_refs.data(), static_cast<std::size_t>(m.ignored_count));
    const Eigen::Vector3d step = *target - m.p;
    if (step.squaredNorm() > min_step_sq) {
      if (const auto hit = world.sweep(m.p, *target, skin, ignored)) {
        if (hit->t_stop > 0.0) {
          m.p += hit->t_stop * step;
          append_path(state, m.p);
        }
        if (!add_constraint(m, *hit, skin)) return;
        continue;
      }
      m.p = *target;
      append_path(state, m.p);
      if (release_passed_constraints(world, m, skin)) continue;
    }
    if (m.plane_count == 0) return;  // free motion reached the goal
    if ((goal - m.p).squaredNorm() <= min_step_sq) return;
    const auto probe = world.sweep(m.p, goal, skin, ignored);
    if (!probe) return;
    if (!add_constraint(m, *probe, skin)) return;
  }
}

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

}  // namespace

void reset_proxy(ProxyState& state, const Eigen::Vector3d& hip_W) {
  state = ProxyState{};
  state.proxy_W = hip_W;
  state.hip_W = hip_W;
  state.initialised = true;
  state.path_W[0] = hip_W;
  state.path_points = 1;
}

ProxyOutput step_proxy(const CollisionWorld& world, std::span<const HapticMaterial> materials,
                       const ProxySettings& settings, ProxyState& state, const Eigen::Vector3d& hip_W,
                       double dt_s) {
  ProxyOutput out;
  if (!hip_W.allFinite() || !std::isfinite(dt_s) || !(dt_s > 0.0)) {
    // Bad input: hold the proxy, command nothing.
    out.proxy_W = state.proxy_W;
    state.path_points = 1;
    state.path_W[0] = state.proxy_W;
    return out;
  }
  if (!state.initialised) reset_proxy(state, hip_W);

  // First-order low-pass of the HIP velocity for damping.
  const double alpha = 1.0 - std::exp(-2.0 * std::numbers::pi * settings.velocity_cutoff_Hz * dt_s);
  state.hip_velocity_W += alpha * ((hip_W - state.hip_W) / dt_s - state.hip_velocity_W);
  state.hip_W = hip_W;

  const Eigen::Vector3d start = state.proxy_W;
  const bool was_in_contact = state.plane_count > 0;
  // Last tick's contact planes seed both passes (store_active_planes overwrites state).
  const std::array<ConstraintPlane, kMaxConstraintPlanes> previous_planes = state.planes;
  const std::span<const ConstraintPlane> previous(previous_planes.data(),
                                                  static_cast<std::size_t>(state.plane_count));

  Motion motion;
  solve_motion(world, settings, start, hip_W, previous, motion, state);
  store_active_planes(motion, settings.skin_m, state);

  bool sticking = false;
  if (state.plane_count > 0 && was_in_contact) {
    const HapticMaterial& mat = material_of(materials, state.planes[0].triangle.object);
    const Eigen::Vector3d to_proxy = motion.p - hip_W;
    const double depth = to_proxy.norm();
    if ((mat.static_friction > 0.0 || mat.dynamic_friction > 0.0) && depth > 0.0) {
      // Friction cone around the frictionless proxy: the previous proxy may stay put
      // while its tangential offset is within mu_s * depth (static), else it slides
      // to the dynamic cone's rim (mu_d * depth behind the frictionless point).
      const Eigen::Vector3d n = to_proxy / depth;
      const Eigen::Vector3d offset = start - motion.p;
      const Eigen::Vector3d tangential = offset - n * n.dot(offset);
      const double slip = tangential.norm();
      if (slip <= mat.static_friction * depth) {
        sticking = true;
        motion.p = start;
        state.path_points = 1;
        state.path_W[0] = start;
      } else if (mat.dynamic_friction > 0.0 && slip > 0.0) {
        const Eigen::Vector3d goal = hip_W + tangential * (mat.dynamic_friction * depth / slip);
        Motion sliding;
        solve_motion(world, settings, start, goal, previous, sliding, state);
        motion = sliding;
        store_active_planes(motion, settings.skin_m, state);
      }
    }
  }

  state.proxy_W = motion.p;
  state.sticking = sticking;
  out.proxy_W = motion.p;
  out.sticking = sticking;
  out.plane_count = state.plane_count;

  const Eigen::Vector3d to_proxy = motion.p - hip_W;
  const double depth = to_proxy.norm();
  if (state.plane_count == 0 || !(depth > 0.0)) return out;  // free space: no force

  const int object = state.planes[0].triangle.object;
  const HapticMaterial& mat = material_of(materials, object);
  out.in_contact = true;
  out.contact_object = object;

  Eigen::Vector3d force = mat.stiffness_N_per_m * to_proxy;
  const Eigen::Vector3d n_contact = to_proxy / depth;
  if (mat.force_shading) {
    // Keep the spring's normal magnitude, turn its direction to the interpolated normal.
    // On an edge or corner the spring's own direction stands in for the face normal.
    const Eigen::Vector3d n_face = state.plane_count == 1 ? state.planes[0].normal_W : n_contact;
    Eigen::Vector3d n_shaded = world.shaded_normal_W(state.planes[0].triangle, motion.p);
    if (n_shaded.dot(n_face) < 0.0) n_shaded = -n_shaded;  // two-sided surfaces
    force += force.dot(n_face) * (n_shaded - n_face);
  }
  if (mat.damping_Ns_per_m > 0.0) {
    force -= mat.damping_Ns_per_m * state.hip_velocity_W.dot(n_contact) * n_contact;
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
