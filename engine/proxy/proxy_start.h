#pragma once
// Where a proxy may start. reset_proxy() requires the HIP to be in free space; a proxy
// placed inside a closed object would render it inside out (pull the hand in), and one
// placed within the skin of a surface starts with a plane it never found by a sweep.
// Callers that take a HIP path from outside (`mhd proxy-replay`, the Python module) ask
// this first and report the answer to their user.

#include "collision/collision_world.h"

#include <Eigen/Core>

#include <optional>
#include <string>

namespace mhd {

/// Why the proxy cannot start at p_W: "is inside an object" or "touches a surface
/// (closer than skin_m = S m)"; nullopt when p_W is in free space (outside every closed
/// object and farther than skin_m from every surface).
[[nodiscard]] std::optional<std::string> proxy_start_blocked(const CollisionWorld& world, const Eigen::Vector3d& p_W,
                                                             double skin_m);

}  // namespace mhd
