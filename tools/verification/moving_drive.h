#pragma once
// Drives the proxy along a HIP path through a world whose objects move (MovingWorld), and
// judges every tick with the exact oracle in each object's own frame (moving_tick_check.h).
// Both halves of the contract are counted: crossings, and follow failures (the straight
// segment from the carried proxy to the HIP is free, yet the proxy does not end at the HIP;
// or a force with the HIP in view). No GoogleTest here.

#include "dynamics/rigid_body_world.h"
#include "geometry/object_dynamics.h"
#include "geometry/object_motion.h"
#include "proxy/god_object.h"
#include "verification/moving_tick_check.h"

#include <Eigen/Core>

#include <optional>
#include <span>
#include <vector>

namespace mhd::verify {

struct MovingDrive {
  std::size_t ticks = 0;
  std::size_t crossings = 0;      ///< ticks with a relative chord or step leg touching a surface
  std::size_t inside = 0;         ///< ticks ending inside a closed object
  std::size_t not_followed = 0;   ///< free segment to the HIP, yet the proxy is not at the HIP
  std::size_t free_force = 0;     ///< a force with the HIP in view of the proxy
  std::size_t contact_ticks = 0;
  std::size_t pushes = 0;         ///< ticks a moving surface pushed the free proxy
  std::size_t squeezes = 0;       ///< ticks the proxy was squeezed against another surface
  std::vector<ProxyOutput> out;   ///< every tick's output, in order
  std::vector<std::vector<Pose>> X_WO;  ///< every tick's object poses (after it), in order
};

/// Places the objects at t = 0 (motions[i] moves object i of `world`; none: it stays),
/// resets the proxy at hip_path_W[0] (free space), then per sample k (k = 1, 2, ...)
/// moves the objects to t = k / rate_Hz, carries the proxy and steps it. Objects with
/// dynamics[i] are pushable bodies (physics as given): the hand's force pushes them back
/// after each step (MovingWorld::apply_reaction); their poses are in `body_poses_W`.
/// Precondition: rate_Hz > 0; motions, materials (and dynamics, unless empty) indexed like
/// the world's objects.
[[nodiscard]] MovingDrive drive_moving_proxy(const CollisionWorld& world,
                                             std::span<const std::optional<ObjectMotion>> motions,
                                             std::span<const HapticMaterial> materials, const ProxySettings& settings,
                                             std::span<const Eigen::Vector3d> hip_path_W, double rate_Hz,
                                             std::span<const std::optional<ObjectDynamics>> dynamics = {},
                                             const RigidBodySettings& physics = {});

}  // namespace mhd::verify
