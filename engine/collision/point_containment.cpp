#include "collision/point_containment.h"

namespace mhd {

bool point_inside_surface(const CollisionWorld& world, const Eigen::Vector3d& p_W) {
  if (!p_W.allFinite()) return false;
  static const Eigen::Vector3d kDirection = Eigen::Vector3d(0.1234, 1.0, 0.0567).normalized();
  constexpr double kRayLength_m = 1000.0;
  constexpr double kSkin_m = 1e-9;
  const auto hit = world.sweep(p_W, p_W + kRayLength_m * kDirection, kSkin_m);
  if (!hit) return false;
  return world.face_normal_W(hit->where).dot(kDirection) > 0.0;
}

}  // namespace mhd
