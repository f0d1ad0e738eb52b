#include "verification/moving_tick_check.h"

#include <memory>

namespace mhd::verify {
namespace {

Pose X_OW(const CollisionWorld& world, std::size_t o) { return world.pose(static_cast<int>(o)).inverse(Eigen::Isometry); }

}  // namespace

MovingTickCheck::MovingTickCheck(const CollisionWorld& world) {
  const auto n = static_cast<std::size_t>(world.object_count());
  oracles_O_.reserve(n);
  for (std::size_t o = 0; o < n; ++o) {
    // The object alone at the identity: its own frame, its exact shape where it has one.
    const int i = static_cast<int>(o);
    CollisionWorld alone;
    (void)alone.add_object(std::shared_ptr<const MeshBvh>(std::shared_ptr<const MeshBvh>{}, &world.shape(i)),
                           Pose::Identity());
    if (const ExactShape* exact = world.exact_shape(i)) alone.set_exact_shape(0, *exact);
    oracles_O_.emplace_back(alone);
  }
  X_OW_before_.resize(n, Pose::Identity());
}

void MovingTickCheck::before_move(const CollisionWorld& world) {
  for (std::size_t o = 0; o < oracles_O_.size(); ++o) X_OW_before_[o] = X_OW(world, o);
}

bool MovingTickCheck::touches(const CollisionWorld& world, const Eigen::Vector3d& a_W,
                              const Eigen::Vector3d& b_W) const {
  for (std::size_t o = 0; o < oracles_O_.size(); ++o) {
    const Pose X = X_OW(world, o);
    if (oracles_O_[o].segment_touches_surface(X * a_W, X * b_W)) return true;
  }
  return false;
}

MovingTickVerdict MovingTickCheck::judge(const CollisionWorld& world, const Eigen::Vector3d& p_before_W,
                                         const Eigen::Vector3d& p_carried_W, std::span<const Eigen::Vector3d> path_W,
                                         const ProxyOutput& out, const Eigen::Vector3d& p_W_hip,
                                         int overlap_object) const {
  MovingTickVerdict v;
  for (std::size_t o = 0; o < oracles_O_.size() && !v.crossed; ++o) {
    const Pose X = X_OW(world, o);
    bool crossed = oracles_O_[o].segment_touches_surface(X_OW_before_[o] * p_before_W, X * p_carried_W);
    for (std::size_t i = 0; i + 1 < path_W.size() && !crossed; ++i) {
      crossed = oracles_O_[o].segment_touches_surface(X * path_W[i], X * path_W[i + 1]);
    }
    const bool inside = oracles_O_[o].point_inside_closed_mesh(X * out.proxy_W);
    if (static_cast<int>(o) == overlap_object) {
      v.overlap = crossed || inside;
    } else {
      v.crossed = crossed;
      v.inside = v.inside || inside;
    }
  }
  if ((out.proxy_W - p_W_hip).norm() > kMovingFollowTolerance_m) {
    v.not_followed = !touches(world, p_carried_W, p_W_hip);
    v.free_force = out.force_W.norm() > 0.0 && !touches(world, out.proxy_W, p_W_hip);
  }
  return v;
}

}  // namespace mhd::verify
