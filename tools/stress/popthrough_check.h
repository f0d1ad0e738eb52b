#pragma once
// The pop-through checker: after every proxy tick it asks the exact, independent oracle
// (CGAL, tools/verification) whether any leg of the proxy's motion touched a triangle
// ("behind": it passed through or onto the surface) and whether the proxy ended inside
// or on a closed object ("inside"); the engine's own point containment gives a second,
// independent opinion on "inside". It judges positions only, so anything that moves a
// point can be checked: the real proxy, or a broken stand-in such as the HIP itself.
// It also judges the other half of the contract, "otherwise go to the hand", with the
// shared definition of a follow failure (verification/follow_check.h).

#include "collision/collision_world.h"
#include "verification/follow_check.h"
#include "verification/surface_crossing_oracle.h"

#include <Eigen/Core>

#include <optional>
#include <span>

namespace mhd::stress {

/// When the engine's point_inside_surface() is asked too (it sweeps a long ray through
/// the BVH, so on million-triangle meshes it costs far more than the proxy tick).
enum class EngineContainment {
  Off,      ///< never
  Contact,  ///< ticks that end in contact with the proxy moved (default)
  Every,    ///< every tick whose proxy moved
};

struct TickVerdict {
  /// A leg of the tick's motion touched the surface (exact).
  bool crossed = false;
  /// The proxy ended inside or on a closed object (exact).
  bool inside = false;
  /// The engine's containment test was asked (on the closed objects only: it treats an
  /// open surface as a half-space, so a proxy behind a sheet's far side is "inside"
  /// it by design), and what it said.
  bool engine_checked = false;
  bool inside_engine = false;
  /// How far behind the surface the proxy ended: its distance to the surface when
  /// inside, else its depth behind the first crossed triangle's plane; 0 when clean.
  double penetration_m = 0.0;
  /// The first leg that touched the surface: -1 joins the previous tick's proxy to this
  /// tick's path start; i >= 0 leaves path point i (the last one joins to proxy_W).
  int leg = 0;
  Eigen::Vector3d leg_from_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d leg_to_W = Eigen::Vector3d::Zero();
  std::optional<verify::OracleHit> hit;

  /// The proxy did not go to a HIP it could reach (F1 or F2 of follow_check.h).
  bool follow_failed = false;
  verify::FollowFailureKind follow_kind = verify::FollowFailureKind::None;
  bool follow_brushed = false;  ///< verify::FollowVerdict::brushed
  /// |proxy - HIP| at the end of the tick, and whether the segment between them was free.
  double follow_gap_m = 0.0;
  bool hip_in_free_view = true;
  double force_N = 0.0;

  /// A pop-through: crossed, inside, or the engine saw the proxy inside.
  [[nodiscard]] bool popped_through() const { return crossed || inside || inside_engine; }
  /// Either half of the contract broken.
  [[nodiscard]] bool failed() const { return popped_through() || follow_failed; }
};

class PopThroughChecker {
 public:
  /// Keeps references to both; the oracle must be built from the same world, and the
  /// world's poses must not change while the checker is used.
  /// The engine's test is asked on every `engine_stride`-th tick its policy allows.
  PopThroughChecker(const CollisionWorld& world, const verify::SurfaceCrossingOracle& oracle,
                    EngineContainment engine = EngineContainment::Contact, int engine_stride = 1,
                    const verify::FollowTolerance& follow = {});

  /// The proxy was (re)started at p_W: checks the point itself (touching counts) and
  /// makes it the previous position.
  TickVerdict check_reset(const Eigen::Vector3d& p_W);

  /// One tick given p_W_hip: the proxy moved from the previous position through path_W
  /// (may be empty) to proxy_W and rendered force_W. Checks every leg, where it ended,
  /// and whether it followed the HIP. Precondition: a reset.
  TickVerdict check_tick(const Eigen::Vector3d& p_W_hip, std::span<const Eigen::Vector3d> path_W,
                         const Eigen::Vector3d& proxy_W, const Eigen::Vector3d& force_W, bool in_contact);

  [[nodiscard]] const Eigen::Vector3d& previous() const { return previous_; }

 private:
  void check_leg(int leg, const Eigen::Vector3d& a, const Eigen::Vector3d& b, TickVerdict& v) const;
  void check_end(const Eigen::Vector3d& p, bool ask_engine, TickVerdict& v);

  const CollisionWorld& world_;
  const verify::SurfaceCrossingOracle& oracle_;
  CollisionWorld closed_world_;  ///< the closed objects of world_, sharing its BVHs
  EngineContainment engine_;
  verify::FollowTolerance follow_;
  int engine_stride_ = 1;
  int engine_countdown_ = 0;
  Eigen::Vector3d previous_ = Eigen::Vector3d::Zero();
  bool started_ = false;
  // The verdict on `previous_` as an end point (a proxy that did not move is not asked again).
  bool previous_inside_ = false;
  bool previous_engine_checked_ = false;
  bool previous_inside_engine_ = false;
  double previous_depth_m_ = 0.0;
};

}  // namespace mhd::stress
