// A probe for tests/layering: proxy/object_twist.h is header-only, so only the include
// root (not a missing library at link time) can refuse it to a layer below proxy.
#include "geometry/pose.h"
#include "proxy/object_twist.h"

namespace mhd::layering_probe {

Eigen::Vector3d rim_velocity_W(const ObjectTwist& twist) {
  return point_velocity_W(twist, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX());
}

}  // namespace mhd::layering_probe
