#include "proxy/proxy_motion.h"

#include <cmath>
#include <optional>
#include <span>

namespace mhd::proxy_detail {
namespace {

// Moves shorter than this fraction of the skin are skipped: they cannot matter to force
// and a zero-length sweep has no direction.
constexpr double kMinStepPerSkin = 1e-3;
// The projection may violate a plane by this much (fraction of the skin), and a proxy
// further than this on a plane's wrong side has left it (the plane goes).
constexpr double kFeasibleTolerancePerSkin = 1e-3;
// A constraint is released once the proxy's projection leaves its triangle by more
// than this (fraction of the skin). It exceeds the sweep's own inflation of triangles,
// so a triangle just hit is never released at once.
constexpr double kReleaseMarginPerSkin = 2.0;

std::size_t at(int i) { return static_cast<std::size_t>(i); }

void append_path(ProxyState& state, const Eigen::Vector3d& p) {
  // At most one point per sweep after the start, and sweeps are capped below the size.
  if (state.path_points < kMaxProxyPath) state.path_W[at(state.path_points++)] = p;
}

// One sweep within the tick's budget. False when the budget is spent (before or during
// the sweep): `hit` is then meaningless and the motion must stop where it is.
bool budgeted_sweep(const CollisionWorld& world, TickWork& work, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                    double skin_m, std::span<const TriangleRef> ignore, std::optional<SweepHit>& hit) {
  if (work.sweeps >= work.max_sweeps) {
    work.exhausted = true;
    return false;
  }
  ++work.sweeps;
  hit = world.sweep(a, b, skin_m, ignore, &work.sweep, work.near);
  if (work.sweep.exhausted) {
    work.exhausted = true;
    work.has_partway = work.sweep.clear_fraction > 0.0;
    if (work.has_partway) {
      work.partway_from = a;
      work.partway = a + work.sweep.clear_fraction * (b - a);
    }
    return false;
  }
  return true;
}

// Triangles one sweep may find touched only within its inflation.
constexpr int kMaxGrazed = 8;
// A graze must miss the triangle itself by this much (fraction of the skin): far above
// double rounding, so a segment through a shared edge is never taken for a graze of both
// neighbours, and far below the sweep's inflation.
constexpr double kGrazeMarginPerSkin = 1e-6;

// True when the leg a -> b reaches `t` only in the band the sweep adds round every
// triangle (nanometres past an edge): it misses the triangle itself. Next to an open
// boundary such grazes are all a sweep finds, and a plane built from one would hold the
// proxy against nothing.
bool only_grazes(const CollisionWorld& world, const TriangleRef& t, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                 double skin_m) {
  if (t.triangle == kExactSurface) return false;  // an exact shape has no inflated band
  return !world.meets_triangle_grown_by(t, a, b, skin_m, kGrazeMarginPerSkin * skin_m);
}

// budgeted_sweep that sweeps again past triangles the leg only grazes (a proxy resting
// beside an open edge, a hand passing one), so they stop nothing.
bool sweep_past_grazes(const CollisionWorld& world, TickWork& work, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                       double skin_m, std::span<const TriangleRef> ignore, std::optional<SweepHit>& hit) {
  // Most sweeps find no graze: the list of triangles to skip is only built for one that does.
  if (!budgeted_sweep(world, work, a, b, skin_m, ignore, hit)) return false;
  if (!hit || !only_grazes(world, hit->where, a, b, skin_m)) return true;
  std::array<TriangleRef, kMaxIgnored + kMaxGrazed> skip{};
  std::size_t k = 0;
  for (const TriangleRef& t : ignore) skip[k++] = t;
  const std::size_t first_grazed = k;
  skip[k++] = hit->where;
  for (;;) {
    if (!budgeted_sweep(world, work, a, b, skin_m, std::span<const TriangleRef>(skip.data(), k), hit)) return false;
    if (!hit || k - first_grazed == kMaxGrazed || !only_grazes(world, hit->where, a, b, skin_m)) {
      return true;
    }
    skip[k++] = hit->where;
  }
}

std::span<const TriangleRef> ignored_of(const Motion& m) {
  return {m.ignored_refs.data(), at(m.ignored_count)};
}

bool is_collected(const Motion& m, const TriangleRef& t) {
  for (int j = 0; j < m.ignored_count; ++j) {
    if (m.ignored[at(j)].triangle == t) return true;
  }
  return false;
}

void remove_ignored(Motion& m, int index) {
  --m.ignored_count;
  m.ignored[at(index)] = m.ignored[at(m.ignored_count)];
  m.ignored_refs[at(index)] = m.ignored_refs[at(m.ignored_count)];
}

// Drops plane i and its triangles (they are swept again from now on).
void drop_plane(Motion& m, int i) {
  for (int j = 0; j < m.ignored_count;) {
    if (m.ignored[at(j)].plane == i) {
      remove_ignored(m, j);
    } else {
      ++j;
    }
  }
  // Move the last plane into slot i and renumber its triangles.
  const int last = --m.plane_count;
  m.planes[at(i)] = m.planes[at(last)];
  m.plane_triangles[at(i)] = m.plane_triangles[at(last)];
  for (int j = 0; j < m.ignored_count; ++j) {
    if (m.ignored[at(j)].plane == last) m.ignored[at(j)].plane = i;
  }
}

// Drops the constraints whose triangles (own and twins) the proxy has slid off, past a
// convex edge: such a plane no longer bounds free space around the proxy. Returns true
// if any went.
bool release_passed_constraints(const CollisionWorld& world, Motion& m, double skin_m) {
  bool released = false;
  for (int i = 0; i < m.plane_count;) {
    bool supported = false;
    for (int j = 0; j < m.ignored_count && !supported; ++j) {
      const IgnoredTriangle& t = m.ignored[at(j)];
      supported = t.plane == i && world.projects_onto_triangle(t.triangle, m.p, kReleaseMarginPerSkin * skin_m);
    }
    if (supported) {
      ++i;
    } else {
      drop_plane(m, i);
      released = true;
    }
  }
  return released;
}

// After a move that the planes did not constrain (towards the goal itself, or with a
// plane set aside), drops the planes the proxy is now on the wrong side of: the move was
// swept against their triangles, so they do not bound the free space around it, and
// keeping them would let later moves ignore triangles they could cross.
void drop_violated_planes(Motion& m, double skin_m) {
  for (int i = 0; i < m.plane_count;) {
    const HalfSpace& h = m.planes[at(i)];
    if (h.normal.dot(m.p) < h.offset - kFeasibleTolerancePerSkin * skin_m) {
      drop_plane(m, i);
    } else {
      ++i;
    }
  }
}

// A plane the proxy is further from than this (fraction of the skin) does not hold it now.
constexpr double kInactivePerSkin = 1e-2;

// Makes room in a full store by dropping the plane the proxy is furthest from, if that
// plane does not hold it now. Its triangles are swept again from then on, so no later
// leg can cross them; what is lost is only the memory that they were met. Returns
// false when every plane holds the proxy.
bool drop_farthest_inactive_plane(Motion& m, double skin_m) {
  int farthest = -1;
  double farthest_gap = kInactivePerSkin * skin_m;
  for (int i = 0; i < m.plane_count; ++i) {
    const HalfSpace& h = m.planes[at(i)];
    const double gap = h.normal.dot(m.p) - h.offset;
    if (gap > farthest_gap) {
      farthest_gap = gap;
      farthest = i;
    }
  }
  if (farthest < 0) return false;
  drop_plane(m, farthest);
  return true;
}

// Records a surface the proxy ran into. Returns false when the store is full of planes
// that all hold the proxy, which ends the motion with the proxy where it is.
bool add_constraint(Motion& m, const SweepHit& hit, double skin_m) {
  if (hit.where.triangle == kExactSurface) {
    // One plane per exact shape: met again, its tangent plane is the newer one.
    for (int i = 0; i < m.plane_count; ++i) {
      if (m.plane_triangles[at(i)] == hit.where) {
        m.planes[at(i)] = HalfSpace{hit.normal_W, hit.plane_offset_m + skin_m};
        return true;
      }
    }
  }
  if (m.ignored_count == kMaxIgnored && !drop_farthest_inactive_plane(m, skin_m)) return false;
  const double offset = hit.plane_offset_m + skin_m;
  int plane = -1;
  for (int i = 0; i < m.plane_count && plane < 0; ++i) {
    const HalfSpace& h = m.planes[at(i)];
    // A coplanar neighbour (flat region, shared edge) adds no new constraint.
    if (h.normal.dot(hit.normal_W) > 1.0 - 1e-12 && std::abs(h.offset - offset) < kFeasibleTolerancePerSkin * skin_m) {
      plane = i;
    }
  }
  if (plane < 0) {
    if (m.plane_count == kMaxHalfSpaces && !drop_farthest_inactive_plane(m, skin_m)) return false;
    plane = m.plane_count++;
    m.planes[at(plane)] = HalfSpace{hit.normal_W, offset};
  }
  // A plane is named by the last of its triangles met: the one the proxy has come to (past
  // a diagonal, on a coplanar twin), where the next tick looks first.
  m.plane_triangles[at(plane)] = hit.where;
  m.ignored[at(m.ignored_count)] = IgnoredTriangle{hit.where, plane};
  m.ignored_refs[at(m.ignored_count)] = hit.where;
  ++m.ignored_count;
  return true;
}

// Turns each exact shape's plane to the shape's tangent plane at the surface point
// nearest the proxy (Salisbury-Tarr): a convex shape lies wholly behind every tangent
// plane, so the new plane keeps every move inside it off the shape as the old one did,
// and projecting the goal onto it walks the proxy round the curved surface. A proxy
// inside a shape (a moving one has engulfed it) loses the plane: a solid lets it out.
// Returns true if the set has an exact shape's plane.
bool turn_exact_planes(const CollisionWorld& world, Motion& m, double skin_m) {
  bool any = false;
  for (int i = 0; i < m.plane_count;) {
    const TriangleRef& t = m.plane_triangles[at(i)];
    if (t.triangle != kExactSurface) {
      ++i;
      continue;
    }
    if (const auto tangent = world.support_plane(t.object, m.p)) {
      m.planes[at(i)] = HalfSpace{tangent->normal_W, tangent->plane_offset_m + skin_m};
      any = true;
      ++i;
    } else {
      drop_plane(m, i);
    }
  }
  return any;
}

// True when the only plane's triangle (or a twin) lies straight under the proxy: the
// proxy is then the foot of the goal on that plane, so the segment to the goal crosses
// the triangle and no move brings it nearer.
bool single_face_under(const CollisionWorld& world, const Motion& m) {
  if (m.plane_count != 1) return false;
  for (int j = 0; j < m.ignored_count; ++j) {
    if (world.projects_onto_triangle(m.ignored[at(j)].triangle, m.p, 0.0)) return true;
  }
  return false;
}

// Moves the proxy along a swept leg that stopped at `hit` (or reached `to`).
void advance(Motion& m, const Eigen::Vector3d& to, const std::optional<SweepHit>& hit, ProxyState& state) {
  const Eigen::Vector3d next = hit ? Eigen::Vector3d(m.p + hit->t_stop * (to - m.p)) : to;
  if (next != m.p) {
    m.p = next;
    append_path(state, m.p);
  }
}

// The face the proxy is over after sliding off every face it held, past a convex edge:
// of the triangles the last sweep tested (the slide's, which passed along that edge), the
// first the segment to the goal meets, if it meets one for real (not a graze).
std::optional<SweepHit> face_beyond_edge(const CollisionWorld& world, SweepWork& last, double skin_m,
                                         const Eigen::Vector3d& p, const Eigen::Vector3d& goal) {
  return world.first_met(std::span<const TriangleRef>(last.tested.data(), at(last.tested_count)), p, goal, skin_m,
                         kGrazeMarginPerSkin * skin_m, last.triangle_tests);
}

// `t`'s hit on the leg from p to `to` when it stops the leg at once (within the least step)
// and for real, not as a graze; else nothing. No hit comes before one at once, so a sweep
// of the whole world would stop the proxy where it is too: the hit answers that sweep and
// is counted as one (and apart, as at once), so what a tick may do stays the same.
std::optional<SweepHit> hit_at_once(const CollisionWorld& world, const TriangleRef& t, const Eigen::Vector3d& p,
                                    const Eigen::Vector3d& to, double skin_m, TickWork& work) {
  if (work.sweeps >= work.max_sweeps) return std::nullopt;
  ++work.sweep.triangle_tests;
  auto hit = world.sweep_triangle(t, p, to, skin_m);
  if (!hit || hit->t_stop * (to - p).norm() > kMinStepPerSkin * skin_m || only_grazes(world, t, p, to, skin_m)) {
    return std::nullopt;
  }
  hit->t_stop = 0.0;
  ++work.sweeps;
  ++work.sweeps_at_once;
  return hit;
}

// Whether a collected triangle (of plane `plane`, or of any plane when it is negative)
// stops the leg from m.p to `to` at once (hit_at_once).
bool collected_blocks_at_once(const CollisionWorld& world, double skin_m, const Motion& m, const Eigen::Vector3d& to,
                              int plane, TickWork& work) {
  for (int j = 0; j < m.ignored_count; ++j) {
    const IgnoredTriangle& t = m.ignored[at(j)];
    if ((plane < 0 || t.plane == plane) && hit_at_once(world, t.triangle, m.p, to, skin_m, work)) return true;
  }
  return false;
}

// A triangle not collected that the last sweep tested (work.sweep.tested) and that stops
// the leg from m.p to `to` at once (hit_at_once): a face holding the proxy, such as a
// coplanar twin past a diagonal it stopped beside.
std::optional<SweepHit> tested_blocks_at_once(const CollisionWorld& world, double skin_m, const Motion& m,
                                              const Eigen::Vector3d& to, TickWork& work) {
  for (int i = 0; i < work.sweep.tested_count; ++i) {
    const TriangleRef& t = work.sweep.tested[at(i)];
    if (is_collected(m, t)) continue;
    if (auto hit = hit_at_once(world, t, m.p, to, skin_m, work)) return hit;
  }
  return std::nullopt;
}

enum class Step { Stay, Moved, OutOfWork };

// Off every face past a convex edge, the proxy would sweep towards the goal to find the
// face beyond, then slide along it: two sweeps. When the face beyond is known (see
// face_beyond_edge), one leg goes straight to the goal's foot on its plane instead, swept
// against everything, so it crosses nothing whichever face the guess is; the guess only
// decides where the leg ends. Ending there unhit, the proxy rests on that plane as on a
// constraint it met.
Step slide_onto_face_beyond(const CollisionWorld& world, double skin_m, const Eigen::Vector3d& goal, Motion& m,
                            ProxyState& state, TickWork& work) {
  const auto beyond = face_beyond_edge(world, work.sweep, skin_m, m.p, goal);
  if (!beyond) return Step::Stay;
  const HalfSpace plane{beyond->normal_W, beyond->plane_offset_m + skin_m};
  const auto target = project_onto_half_spaces(goal, std::span<const HalfSpace>(&plane, 1),
                                               kFeasibleTolerancePerSkin * skin_m);
  if (!target) return Step::Stay;
  std::optional<SweepHit> hit;
  if ((*target - m.p).norm() <= kMinStepPerSkin * skin_m) {
    // Already at the goal's foot on that plane (a coplanar twin past a diagonal): the face
    // holds the proxy where it is if it stops the segment to the goal at once.
    hit = hit_at_once(world, beyond->where, m.p, goal, skin_m, work);
    if (!hit) return Step::Stay;
  } else {
    if (!sweep_past_grazes(world, work, m.p, *target, skin_m, {}, hit)) return Step::OutOfWork;
    advance(m, *target, hit, state);
  }
  if (!add_constraint(m, hit ? *hit : *beyond, skin_m)) {
    work.exhausted = true;
    return Step::OutOfWork;
  }
  return Step::Moved;
}

enum class Release { None, Moved, OutOfWork };

// Least gain in distance to the goal, as a fraction of it, that a release must make and
// that counts as progress; and the sweeps a motion may make without progress.
constexpr double kMinReleaseGainPerDistance = 1e-3;
constexpr int kMaxSweepsWithoutGain = 8;

// The active-set step at the minimum over the collected planes: a plane whose own
// triangle does not stop a move towards the projection of the goal on the other planes
// holds the proxy only as an infinite plane (a saddle, a convex edge seen from the side,
// a graze of an open boundary) and goes. The move is swept against that plane's
// triangles and stays inside the others, so it crosses nothing.
Release release_one_plane(const CollisionWorld& world, double skin_m, const Eigen::Vector3d& goal, Motion& m,
                          ProxyState& state, TickWork& work) {
  const double min_step = kMinStepPerSkin * skin_m;
  for (int i = 0; i < m.plane_count; ++i) {
    std::array<HalfSpace, kMaxHalfSpaces> others{};
    int n = 0;
    for (int j = 0; j < m.plane_count; ++j) {
      if (j != i) others[at(n++)] = m.planes[at(j)];
    }
    const auto target = project_onto_half_spaces(goal, std::span<const HalfSpace>(others.data(), at(n)),
                                                 kFeasibleTolerancePerSkin * skin_m);
    if (!target || (*target - m.p).norm() <= min_step) continue;
    // Triangles of the other planes stay ignored; plane i's are tested.
    std::array<TriangleRef, kMaxIgnored> keep{};
    int k = 0;
    for (int j = 0; j < m.ignored_count; ++j) {
      if (m.ignored[at(j)].plane != i) keep[at(k++)] = m.ignored[at(j)].triangle;
    }
    if (collected_blocks_at_once(world, skin_m, m, *target, i, work)) continue;  // plane i holds
    std::optional<SweepHit> hit;
    if (!sweep_past_grazes(world, work, m.p, *target, skin_m, std::span<const TriangleRef>(keep.data(), at(k)), hit)) {
      return Release::OutOfWork;
    }
    if (hit && hit->t_stop * (*target - m.p).norm() <= min_step) continue;  // plane i really holds
    // A release must bring the proxy clearly nearer the goal, or releases and re-hits of
    // the planes round a vertex could take turns for ever.
    const Eigen::Vector3d next = hit ? Eigen::Vector3d(m.p + hit->t_stop * (*target - m.p)) : *target;
    const double before = (goal - m.p).norm();
    if ((goal - next).norm() > before - std::max(min_step, kMinReleaseGainPerDistance * before)) continue;
    drop_plane(m, i);
    advance(m, *target, hit, state);
    drop_violated_planes(m, skin_m);
    if (hit && !add_constraint(m, *hit, skin_m)) {
      work.exhausted = true;
      return Release::OutOfWork;
    }
    return Release::Moved;
  }
  return Release::None;
}

}  // namespace

bool go_if_visible(const CollisionWorld& world, double skin_m, const Eigen::Vector3d& goal, Motion& m,
                   ProxyState& state, TickWork& work) {
  std::optional<SweepHit> hit;
  if ((goal - m.p).norm() <= kMinStepPerSkin * skin_m) return false;
  if (!sweep_past_grazes(world, work, m.p, goal, skin_m, {}, hit) || hit) return false;
  advance(m, goal, hit, state);
  m.plane_count = 0;
  m.ignored_count = 0;
  return true;
}

// Zilles-Salisbury with a checked active set. Each step either moves the proxy nearer
// the goal along a swept leg or changes the constraint set, and every leg is either
// swept against every triangle it could cross or stays inside the collected half-spaces
// (whose triangles are then the only ones it skips), so the proxy never crosses the
// surface. Planes are never carried over from the last tick: they are found again by
// the first sweep, so a plane that no longer blocks cannot hold the proxy.
namespace {

void solve_motion_steps(const CollisionWorld& world, double skin_m, const Eigen::Vector3d& start,
                        const Eigen::Vector3d& goal, Motion& m, ProxyState& state, TickWork& work,
                        const TriangleRef* resting_on) {
  const double min_step = kMinStepPerSkin * skin_m;
  m.p = start;
  state.path_points = 0;
  append_path(state, start);
  std::optional<SweepHit> hit;
  // The straight segment first, nothing ignored: if it is free the proxy is at the goal.
  // A proxy pressed onto the face it rested on finds that face in the way at once, which
  // needs no sweep of the whole world (hit_at_once; at once is within the least step, as
  // rounding leaves the proxy a hair over one skin off as often as under).
  if (resting_on != nullptr && (goal - m.p).norm() > min_step) {
    hit = hit_at_once(world, *resting_on, m.p, goal, skin_m, work);
  }
  if (!hit && !sweep_past_grazes(world, work, m.p, goal, skin_m, {}, hit)) return;
  advance(m, goal, hit, state);
  if (!hit) return;
  if (!add_constraint(m, *hit, skin_m)) {
    work.exhausted = true;
    return;
  }
  // Progress guard: constraint changes round a vertex of a fine mesh can take turns
  // without bringing the proxy nearer; a motion that has not gained for a few sweeps is at
  // its minimum as far as these planes can tell.
  // Before giving up on the planes (no progress, or no point satisfies them all): a
  // proxy that has worked its way round an edge may see the goal.
  auto last_look = [&] { (void)go_if_visible(world, skin_m, goal, m, state, work); };
  double best_distance = (goal - m.p).norm();
  int sweeps_at_best = work.sweeps;
  for (;;) {
    const double distance = (goal - m.p).norm();
    if (distance < best_distance - std::max(min_step, kMinReleaseGainPerDistance * best_distance)) {
      best_distance = distance;
      sweeps_at_best = work.sweeps;
    } else if (m.plane_count > 0 && work.sweeps - sweeps_at_best >= kMaxSweepsWithoutGain) {
      last_look();
      return;
    }
    const bool on_exact = turn_exact_planes(world, m, skin_m);
    const auto target = project_onto_half_spaces(goal, std::span<const HalfSpace>(m.planes.data(), at(m.plane_count)),
                                                 kFeasibleTolerancePerSkin * skin_m);
    if (!target) {  // numerically empty (e.g. both sides of a thin fin): stay, crossing-free
      last_look();
      return;
    }
    if ((*target - m.p).norm() > min_step) {
      if (!budgeted_sweep(world, work, m.p, *target, skin_m, ignored_of(m), hit)) return;
      advance(m, *target, hit, state);
      if (hit) {
        if (!add_constraint(m, *hit, skin_m)) {
          work.exhausted = true;
          return;
        }
        continue;
      }
      // A move on an exact shape's tangent plane leaves the curved surface: turn the
      // plane and project again, until the projection no longer moves the proxy.
      if (on_exact) continue;
    }
    // Off a triangle past a convex edge, whether this step moved or an earlier one did.
    if (release_passed_constraints(world, m, skin_m)) {
      if (m.plane_count == 0 && slide_onto_face_beyond(world, skin_m, goal, m, state, work) == Step::OutOfWork) {
        return;
      }
      continue;
    }
    if (m.plane_count == 0 || (goal - m.p).norm() <= min_step) return;  // at the goal
    if (single_face_under(world, m)) return;  // pressed onto one face: a minimum
    // At the minimum over the collected planes. Check it against the surface itself:
    // the straight segment to the goal, nothing ignored (no sweep needed when a collected
    // triangle blocks it at once).
    if (const auto at_once = tested_blocks_at_once(world, skin_m, m, goal, work)) {
      if (!add_constraint(m, *at_once, skin_m)) {
        work.exhausted = true;
        return;
      }
      continue;
    }
    if (collected_blocks_at_once(world, skin_m, m, goal, -1, work)) {
      if (release_one_plane(world, skin_m, goal, m, state, work) != Release::Moved) return;
      continue;
    }
    if (!sweep_past_grazes(world, work, m.p, goal, skin_m, {}, hit)) return;
    if (!hit) {
      advance(m, goal, hit, state);
      m.plane_count = 0;
      m.ignored_count = 0;
      return;
    }
    const bool moved = hit->t_stop * (goal - m.p).norm() > min_step;
    if (moved) {
      advance(m, goal, hit, state);
      drop_violated_planes(m, skin_m);
    }
    if (!is_collected(m, hit->where)) {
      if (!add_constraint(m, *hit, skin_m)) {
        work.exhausted = true;
        return;
      }
      continue;
    }
    if (moved) continue;
    // Blocked straight ahead by a collected triangle: a true minimum, unless one of the
    // planes holds only as an infinite plane or a graze.
    const Release r = release_one_plane(world, skin_m, goal, m, state, work);
    if (r != Release::Moved) return;
  }
}

}  // namespace

void solve_motion(const CollisionWorld& world, double skin_m, const Eigen::Vector3d& start,
                  const Eigen::Vector3d& goal, Motion& m, ProxyState& state, TickWork& work,
                  const TriangleRef* resting_on) {
  work.has_partway = false;
  solve_motion_steps(world, skin_m, start, goal, m, state, work, resting_on);
  // Out of work in a sweep that cleared part of its leg (a spot of more triangles than a
  // tick may test, such as a fine mesh's pole): the proxy goes that far, so that over a few
  // ticks it leaves the spot instead of staying there while the hand moves on. Every leg
  // stays within the planes it ignores, or is not one that ignores any, so the part swept
  // clear crosses nothing.
  if (work.exhausted && work.has_partway && work.partway_from == m.p) {
    m.p = work.partway;
    append_path(state, m.p);
    drop_violated_planes(m, skin_m);
    work.went_partway = true;
  }
  work.has_partway = false;
}

}  // namespace mhd::proxy_detail
