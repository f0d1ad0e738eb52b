#include "proxy/proxy_look_ahead.h"

namespace mhd {

LookAheadReport ProxyLookAhead::run(const CollisionWorld& world, std::span<const HapticMaterial> materials,
                                    const ProxySettings& settings, ProxyState& state, double dt_s,
                                    std::span<const ObjectTwist> twists) {
  LookAheadReport report;
  if (!state.initialised || !state.p_W_hip.allFinite()) {
    has_last_ = false;
    return report;
  }
  const Eigen::Vector3d& p_W_hip = state.p_W_hip;
  // Constant velocity over one tick: the hand cannot change its speed much in a millisecond,
  // and a wrong guess costs only the cache's warmth, never a force.
  report.p_W_hip = has_last_ ? Eigen::Vector3d(p_W_hip + (p_W_hip - last_p_W_hip_)) : p_W_hip;
  last_p_W_hip_ = p_W_hip;
  has_last_ = true;
  scratch_ = state;
  const ProxyOutput out = step_proxy(world, materials, settings, scratch_, report.p_W_hip, dt_s, twists);
  // A gather walks the tree into the list; handing a new list over spares the next tick
  // that walk. On a fine mesh the proxy leaves a list's box every few ticks. Only a list
  // the copy gathered: its walks that gathered nothing stay its own, or the next tick
  // would count them towards a gather, and a free-space tick beside a fine mesh would
  // gather a list it never uses. The copy is of the part in use, up to 4 KB.
  if (scratch_.near.gathers() != state.near.gathers()) state.near = scratch_.near;
  report.ran = true;
  report.proxy_W = out.proxy_W;
  report.sweeps = out.sweeps;
  report.triangle_tests = out.triangle_tests;
  return report;
}

}  // namespace mhd
