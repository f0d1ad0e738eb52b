#include "head_pose_check.h"

#include <array>
#include <cmath>

namespace mhd::openxr {

HeadPoseVerdict check_head_pose(const XrSpaceLocation& location, double max_position_m) noexcept {
  // Valid alone may be a runtime's guess from the last known pose (inertial only):
  // stale head data must stop the base, not steer it.
  constexpr XrSpaceLocationFlags kNeeded =
      XR_SPACE_LOCATION_POSITION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_VALID_BIT |
      XR_SPACE_LOCATION_POSITION_TRACKED_BIT | XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT;
  if ((location.locationFlags & kNeeded) != kNeeded) return HeadPoseVerdict::NotTracked;
  const XrVector3f& p_m = location.pose.position;
  const XrQuaternionf& q = location.pose.orientation;
  const std::array<double, 7> all{p_m.x, p_m.y, p_m.z, q.x, q.y, q.z, q.w};
  for (const double v : all) {
    if (!std::isfinite(v)) return HeadPoseVerdict::NonFinite;
  }
  for (std::size_t i = 0; i < 3; ++i) {
    if (std::fabs(all[i]) > max_position_m) return HeadPoseVerdict::OutOfRange;
  }
  const double norm = std::sqrt(all[3] * all[3] + all[4] * all[4] + all[5] * all[5] + all[6] * all[6]);
  if (std::fabs(norm - 1.0) > kUnitTolerance) return HeadPoseVerdict::BadQuaternion;
  return HeadPoseVerdict::Accepted;
}

}  // namespace mhd::openxr
