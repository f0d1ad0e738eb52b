#pragma once
// The other half of the god-object contract (docs/reliability/pop_through.md):
// where nothing is in the way, the proxy goes to the hand. A tick is a *follow failure*
// when, judged by the exact oracle alone (segment_touches_surface):
//   F1 (Stuck): the straight segment from the previous tick's proxy to this tick's HIP
//      touches no surface, yet the proxy did not end at the HIP (|proxy - HIP| > gap
//      tolerance) or the force is above the tolerance's spring force;
//   F2 (FreeSpaceForce): at the end of the tick the segment from the proxy to the HIP
//      touches no surface (the HIP is in free space on the proxy's side), yet
//      |proxy - HIP| > gap tolerance: a force with nothing in between.
// The one legitimate force with the HIP in free space (a sheet held between proxy and
// HIP) is neither: both segments cross the sheet.
// Both are judged at the proxy's resolution: the proxy keeps `clearance_m` (its skin,
// 1 µm) off every surface, so a segment that brushes a surface closer than that on its
// way (oracle.segment_brushes_surface; tour strokes aimed exactly at a rim vertex pass it
// by 1e-14 m) is not one it can follow straight; such ticks are counted apart (`brushed`).
// The surface the segment starts on does not count as brushed, so a proxy resting on a
// face with the HIP lifted off it is still judged.
// Crossings stay judged exactly, elsewhere.

#include "material/haptic_material.h"
#include "verification/surface_crossing_oracle.h"

#include <Eigen/Core>

#include <span>
#include <string_view>

namespace mhd::verify {

/// How far from the HIP a proxy that should be at it may end: the proxy keeps a 1 µm
/// skin and the engine's sweeps are conservative by about a micrometre; 10 µm is 10 mN
/// at 1 kN/m.
inline constexpr double kFollowTolerance_m = 1e-5;

/// The proxy's skin (ProxySettings::skin_m's default): how far it keeps off surfaces.
inline constexpr double kProxyClearance_m = 1e-6;

struct FollowTolerance {
  double gap_m = kFollowTolerance_m;
  double clearance_m = kProxyClearance_m;  ///< see F1 above
  /// The force allowed where the proxy should be at the HIP is the spring force of gap_m
  /// at this stiffness.
  double stiffness_N_per_m = 1000.0;
  [[nodiscard]] double force_N() const { return gap_m * stiffness_N_per_m; }
};

/// gap_m with the stiffness of the stiffest material (1000 N/m when there is none).
[[nodiscard]] FollowTolerance follow_tolerance(std::span<const HapticMaterial> materials,
                                               double gap_m = kFollowTolerance_m);

enum class FollowFailureKind { None, Stuck, FreeSpaceForce };
[[nodiscard]] std::string_view to_string(FollowFailureKind kind);

struct FollowVerdict {
  FollowFailureKind kind = FollowFailureKind::None;  ///< Stuck wins where both hold
  double gap_m = 0.0;    ///< |proxy - HIP| at the end of the tick
  double force_N = 0.0;  ///< |force| of the tick
  /// The segment proxy -> HIP touches no surface (F2's condition; true when they coincide).
  bool hip_in_free_view = false;
  /// F1 or F2 but for a brush: the segment touches nothing, exactly, yet passes a
  /// surface closer than the clearance (not a failure; counted apart).
  bool brushed = false;
  [[nodiscard]] bool failed() const { return kind != FollowFailureKind::None; }
};

/// One tick: the proxy was at previous_proxy_W, was given p_W_hip, and ended at proxy_W
/// with force_W. Asks the oracle at most three times, and not at all for a proxy at the HIP.
[[nodiscard]] FollowVerdict check_follow(const SurfaceCrossingOracle& oracle, const Eigen::Vector3d& previous_proxy_W,
                                         const Eigen::Vector3d& p_W_hip, const Eigen::Vector3d& proxy_W,
                                         const Eigen::Vector3d& force_W, const FollowTolerance& tolerance);

}  // namespace mhd::verify
