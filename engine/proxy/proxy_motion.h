#pragma once
// The proxy's motion in one tick: from where it was towards a goal (the HIP, or the
// friction cone's rim), through free space only, to a local minimum of the distance to
// the goal (docs/proxy.md). Internal to the proxy library; step_proxy() is the API.

#include "collision/collision_world.h"
#include "proxy/constraint_projection.h"
#include "proxy/god_object.h"

#include <array>

namespace mhd::proxy_detail {

// Triangles one motion may set aside (collected planes plus coplanar twins).
inline constexpr int kMaxIgnored = 16;

// A triangle set aside by the sweeps, and the constraint plane it belongs to: its
// own, or that of a coplanar neighbour (a twin) it duplicates.
struct IgnoredTriangle {
  TriangleRef triangle;
  int plane = 0;
};

// The work one tick may still do; shared by the passes of a tick.
struct TickWork {
  int sweeps = 0;
  // Of those, the ones answered by testing known triangles alone (found at once).
  int sweeps_at_once = 0;
  int max_sweeps = kMaxProxySweeps;
  SweepWork sweep;
  bool exhausted = false;  // the budget (or the constraint store) ran out
  // A sweep that ran out partway (SweepWork::clear_fraction) leaves the point it could still
  // reach, from where it started; solve_motion() moves the proxy there.
  bool has_partway = false;
  Eigen::Vector3d partway_from = Eigen::Vector3d::Zero();
  Eigen::Vector3d partway = Eigen::Vector3d::Zero();
  bool went_partway = false;  // a motion ended there
  // The triangles near the proxy (ProxyState::near), or null.
  SweepCandidates* near = nullptr;
};

// One motion's state: where the proxy is and the constraints it has met.
struct Motion {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  std::array<HalfSpace, kMaxHalfSpaces> planes{};
  std::array<TriangleRef, kMaxHalfSpaces> plane_triangles{};
  int plane_count = 0;
  std::array<IgnoredTriangle, kMaxIgnored> ignored{};
  std::array<TriangleRef, kMaxIgnored> ignored_refs{};  // the same triangles, as sweep() takes them
  int ignored_count = 0;
};

// Moves the proxy from `start` towards `goal` and records its path in state.path_W.
// Every leg is swept; on return m.p is crossing-free-reachable from start and either
// the goal, a local minimum of the distance to it, or (work.exhausted) where the
// budget ran out: as far along the last leg as its sweep cleared before it did.
// `resting_on`: a triangle the proxy rested on at the end of the last tick, or null. If the
// segment to the goal runs into it at once, that is the motion's first hit, found without
// a sweep of the whole world (an earlier hit than at once there cannot be).
void solve_motion(const CollisionWorld& world, double skin_m, const Eigen::Vector3d& start,
                  const Eigen::Vector3d& goal, Motion& m, ProxyState& state, TickWork& work,
                  const TriangleRef* resting_on = nullptr);

// If the straight segment from m.p to `goal` crosses nothing (one sweep within the
// budget), moves the proxy there (recorded in state.path_W), clears the planes and
// returns true; otherwise leaves everything as it was.
bool go_if_visible(const CollisionWorld& world, double skin_m, const Eigen::Vector3d& goal, Motion& m,
                   ProxyState& state, TickWork& work);

}  // namespace mhd::proxy_detail
