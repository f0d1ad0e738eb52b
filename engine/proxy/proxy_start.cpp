#include "proxy/proxy_start.h"

#include "collision/point_containment.h"

#include <fmt/core.h>

namespace mhd {

std::optional<std::string> proxy_start_blocked(const CollisionWorld& world, const Eigen::Vector3d& p_W,
                                               double skin_m) {
  if (point_inside_surface(world, p_W)) return std::string("is inside an object");
  // A sweep of one skin's length along each axis that must stop at once started within the skin.
  for (int axis = 0; axis < 3; ++axis) {
    for (const double sign : {1.0, -1.0}) {
      const Eigen::Vector3d step = sign * skin_m * Eigen::Vector3d::Unit(axis);
      const auto hit = world.sweep(p_W, p_W + step, skin_m);
      if (hit && hit->t_stop == 0.0) return fmt::format("touches a surface (closer than skin_m = {} m)", skin_m);
    }
  }
  return std::nullopt;
}

}  // namespace mhd
