#include "proxy/proxy_carry.h"

#include <cstddef>
#include <limits>

namespace mhd {
namespace {

bool rests_on(const ProxyState& state, int object) {
  for (int i = 0; i < state.plane_count; ++i) {
    if (state.planes[static_cast<std::size_t>(i)].triangle.object == object) return true;
  }
  return false;
}

// The first surface of an object other than `moved` that the move from a_W to b_W meets.
std::optional<SweepHit> first_other_hit(const CollisionWorld& world, int moved, const Eigen::Vector3d& a_W,
                                        const Eigen::Vector3d& b_W, double skin_m) {
  std::optional<SweepHit> first;
  for (int j = 0; j < world.object_count(); ++j) {
    if (j == moved) continue;
    const auto hit = world.sweep_object(j, a_W, b_W, skin_m);
    if (hit && (!first || hit->t_stop < first->t_stop)) first = hit;
  }
  return first;
}

}  // namespace

CarryOutput carry_proxy(const CollisionWorld& world, std::span<const Pose> X_WO_before, double skin_m,
                        ProxyState& state) {
  CarryOutput out;
  if (!state.initialised) return out;
  for (int o = 0; o < world.object_count(); ++o) {
    const Pose& X_before = X_WO_before[static_cast<std::size_t>(o)];
    const Pose& X_now = world.pose(o);
    if (X_before.matrix() == X_now.matrix()) continue;
    // M carries a point fixed to the object from where it was to where it is.
    const Pose M = X_now * X_before.inverse(Eigen::Isometry);
    const Eigen::Vector3d p_W = state.proxy_W;
    const Eigen::Vector3d p_W_attached = M * p_W;
    Eigen::Vector3d target_W = p_W;
    if (rests_on(state, o)) {
      target_W = p_W_attached;
      ++out.rode;
    } else if (const auto hit = world.sweep_object(o, p_W_attached, p_W, skin_m)) {
      // Relative to the object the proxy went from p_W_attached to p_W (both in the
      // object's current pose); it stops where the surface met it.
      target_W = p_W_attached + hit->t_stop * (p_W - p_W_attached);
      ++out.pushed;
    } else {
      continue;  // the object moved without reaching the proxy
    }
    if (const auto block = first_other_hit(world, o, p_W, target_W, skin_m)) {
      target_W = p_W + block->t_stop * (target_W - p_W);
      out.squeezed = true;
    }
    state.proxy_W = target_W;
    // The object's planes turn and move with it; the next step checks them by a sweep.
    for (int i = 0; i < state.plane_count; ++i) {
      ConstraintPlane& plane = state.planes[static_cast<std::size_t>(i)];
      if (plane.triangle.object != o) continue;
      const Eigen::Vector3d on_plane_W = M * Eigen::Vector3d(plane.normal_W * plane.offset_m);
      plane.normal_W = M.linear() * plane.normal_W;
      plane.offset_m = plane.normal_W.dot(on_plane_W);
    }
  }
  return out;
}

}  // namespace mhd
