#pragma once
// What a rig knows of the other rigs on its floor, from the shared tracking: each other
// user's and base's newest position, its velocity and when it was measured; and the
// keep-outs that gives at a moment. The server's io thread fills a FloorView from its
// tracker's samples, the planner thread turns it into keep-outs; `mhd plan-sim
// --shared-floor` does the same from its simulated tracking. Fixed size, no allocation.

#include "planner/keep_outs.h"
#include "planner/planner_settings.h"

#include <Eigen/Core>

#include <array>
#include <cstddef>

namespace mhd {

/// The most other rigs a floor view holds: a user and a base each.
inline constexpr std::size_t kMaxOtherRigs = KeepOuts::kCapacity / 2;

/// One tracked disc on the floor (world x, z).
struct TrackedDisc {
  bool known = false;  ///< measured at least once
  double t_s = 0.0;    ///< when the newest position was measured
  Eigen::Vector2d p_W = Eigen::Vector2d::Zero();
  Eigen::Vector2d v_W = Eigen::Vector2d::Zero();  ///< tracked velocity (0 until two samples)
};

struct OtherRigTrack {
  TrackedDisc user;
  TrackedDisc base;
};

struct FloorView {
  std::array<OtherRigTrack, kMaxOtherRigs> rigs{};
  std::size_t count = 0;  ///< other rigs declared (none: a one-rig scene)
};

struct FloorKeepOuts {
  KeepOuts keep_outs;
  bool current = true;  ///< every declared disc measured, and none older than the limit
};

/// The keep-outs at `now_s`: each disc extrapolated over its age by its velocity, its
/// radius (the human radius for a user, the robot radius for a base) grown by half that
/// extrapolation (its error) and by how far it goes in one command period (the planner's
/// guard sees only its own base's motion). Not current when a declared disc was never
/// measured or is older than `stale_after_s`.
[[nodiscard]] FloorKeepOuts floor_keep_outs(const FloorView& view, double now_s, double stale_after_s,
                                            const PlannerSettings& settings) noexcept;

}  // namespace mhd
