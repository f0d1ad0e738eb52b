#pragma once
// The look-ahead between ticks. A tick's time goes mostly to waiting on memory when the
// proxy reaches a part of a large mesh it has not touched lately: the BVH nodes, the
// candidate list's triangles and their corners (docs/benchmarks.md, "first" against
// "again"). The haptic thread is idle for most of its period, so after it has sent a tick's
// force it steps a copy of the proxy to where the HIP will be at the next tick, predicted
// at constant velocity, and throws the result away but for the copy's candidate list: what
// the next tick reads is then in the cache, and the triangles it sweeps listed. It changes
// nothing the proxy renders, and the next tick costs what it costs warm where the
// prediction was close. It costs about one tick's work, off the path from
// the device's reading to its force.

#include "proxy/god_object.h"

namespace mhd {

struct LookAheadReport {
  bool ran = false;                                    ///< false: no proxy to look ahead for
  Eigen::Vector3d p_W_hip = Eigen::Vector3d::Zero();  ///< the HIP predicted for the next tick
  Eigen::Vector3d proxy_W = Eigen::Vector3d::Zero();  ///< where the next tick would end there
  int sweeps = 0;                                      ///< the work it did, as ProxyOutput counts it
  int triangle_tests = 0;
};

class ProxyLookAhead {
 public:
  /// Call after each tick's step_proxy with the state it left and the tick's interval and
  /// twists. Steps a copy of `state` towards the HIP extrapolated from the last two it saw
  /// (the tick's own HIP after the first call, or after a state not yet started). Of
  /// `state` it changes only the list of triangles near the proxy (ProxyState::near), which
  /// takes what the copy gathered: the next tick then finds them listed, not only cached.
  /// That list changes what a sweep costs, never its answer, so nothing the proxy renders
  /// changes. Never changes the world; allocates nothing; its work is bounded by the tick's
  /// budget.
  LookAheadReport run(const CollisionWorld& world, std::span<const HapticMaterial> materials,
                      const ProxySettings& settings, ProxyState& state, double dt_s,
                      std::span<const ObjectTwist> twists = {});

 private:
  ProxyState scratch_;  // a member, so that the thread's stack does not hold a second 6 KB state
  Eigen::Vector3d last_p_W_hip_ = Eigen::Vector3d::Zero();
  bool has_last_ = false;
};

}  // namespace mhd
