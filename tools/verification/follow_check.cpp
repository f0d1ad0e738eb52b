#include "verification/follow_check.h"

#include <algorithm>

namespace mhd::verify {

FollowTolerance follow_tolerance(std::span<const HapticMaterial> materials, double gap_m) {
  FollowTolerance t;
  t.gap_m = gap_m;
  if (!materials.empty()) {
    t.stiffness_N_per_m = 0.0;
    for (const HapticMaterial& m : materials) t.stiffness_N_per_m = std::max(t.stiffness_N_per_m, m.stiffness_N_per_m);
  }
  return t;
}

std::string_view to_string(FollowFailureKind kind) {
  switch (kind) {
    case FollowFailureKind::None: return "none";
    case FollowFailureKind::Stuck: return "stuck";
    case FollowFailureKind::FreeSpaceForce: return "free-space force";
  }
  return "?";
}

FollowVerdict check_follow(const SurfaceCrossingOracle& oracle, const Eigen::Vector3d& previous_proxy_W,
                           const Eigen::Vector3d& p_W_hip, const Eigen::Vector3d& proxy_W,
                           const Eigen::Vector3d& force_W, const FollowTolerance& tolerance) {
  FollowVerdict v;
  v.gap_m = (proxy_W - p_W_hip).norm();
  v.force_N = force_W.norm();
  v.hip_in_free_view = v.gap_m == 0.0 || !oracle.segment_touches_surface(proxy_W, p_W_hip);
  const bool away_from_hip = v.gap_m > tolerance.gap_m || v.force_N > tolerance.force_N();
  if (!away_from_hip) return v;
  if (!oracle.segment_touches_surface(previous_proxy_W, p_W_hip)) {
    v.brushed = oracle.segment_brushes_surface(previous_proxy_W, p_W_hip, tolerance.clearance_m);
    if (!v.brushed) v.kind = FollowFailureKind::Stuck;
  }
  if (v.kind == FollowFailureKind::None && v.hip_in_free_view && v.gap_m > tolerance.gap_m) {
    if (oracle.segment_brushes_surface(proxy_W, p_W_hip, tolerance.clearance_m)) {
      v.brushed = true;
    } else {
      v.kind = FollowFailureKind::FreeSpaceForce;
    }
  }
  return v;
}

}  // namespace mhd::verify
