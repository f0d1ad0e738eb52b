#pragma once
// The exact judgement of one haptic tick in a world whose objects move, in each object's
// own frame (docs/proxy.md "Moving objects"): relative to a moving object, the proxy's
// motion over a tick is the chord from where it was (in the object's old pose) to where it
// was carried (in the new pose), then the legs of its step. Both halves of the contract:
// no chord or leg touches a surface and the proxy ends outside every closed object; and a
// proxy whose straight way from its carried place to the HIP is free ends at the HIP, with
// no force while the HIP is in view. Shared by drive_moving_proxy and the stress tool.

#include "collision/collision_world.h"
#include "geometry/pose.h"
#include "proxy/god_object.h"
#include "verification/surface_crossing_oracle.h"

#include <Eigen/Core>

#include <span>
#include <vector>

namespace mhd::verify {

/// "At the HIP", as the follow check judges it (10 µm: the skin and the sweeps' margin).
inline constexpr double kMovingFollowTolerance_m = 1e-5;

struct MovingTickVerdict {
  bool crossed = false;       ///< a relative chord or step leg touched a surface
  bool inside = false;        ///< the proxy ended inside a closed object
  bool not_followed = false;  ///< free segment from the carried proxy to the HIP, yet not at the HIP
  bool free_force = false;    ///< a force with the HIP in view of the proxy
  /// A crossing of, or the proxy inside, the overlap object (judge()): not in crossed / inside.
  bool overlap = false;
  [[nodiscard]] bool failed() const { return crossed || inside || not_followed || free_force; }
};

class MovingTickCheck {
 public:
  /// Builds an exact oracle per object of `world`, each in the object's own frame (the
  /// shapes never change; only poses do). Keeps no reference to `world`.
  explicit MovingTickCheck(const CollisionWorld& world);

  /// Call before the objects move: remembers every object's pose in `world`.
  void before_move(const CollisionWorld& world);

  /// Judges the tick: the proxy was at p_before_W (objects in their poses at before_move),
  /// was carried to p_carried_W (objects in their poses in `world` now), then stepped along
  /// `path_W` to `out.proxy_W` towards p_W_hip. `overlap_object` (-1: none) is a moving
  /// object that squeezed the proxy against a still one and may overlap it (docs/proxy.md
  /// "Moving objects"): its crossings and containment go to `overlap`, apart from the others'.
  /// Precondition: same objects as at construction.
  [[nodiscard]] MovingTickVerdict judge(const CollisionWorld& world, const Eigen::Vector3d& p_before_W,
                                        const Eigen::Vector3d& p_carried_W, std::span<const Eigen::Vector3d> path_W,
                                        const ProxyOutput& out, const Eigen::Vector3d& p_W_hip,
                                        int overlap_object = -1) const;

  /// Whether a world segment, with the objects in their poses in `world`, touches any of them.
  [[nodiscard]] bool touches(const CollisionWorld& world, const Eigen::Vector3d& a_W, const Eigen::Vector3d& b_W) const;

 private:
  std::vector<SurfaceCrossingOracle> oracles_O_;  // object o's surface in its own frame
  std::vector<Pose> X_OW_before_;
};

}  // namespace mhd::verify
