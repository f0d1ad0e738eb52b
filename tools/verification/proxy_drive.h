#pragma once
// Drives the proxy along a HIP path at a fixed rate, records every tick, and checks the
// proxy's recorded path against the exact oracle. No GoogleTest here, so benchmarks can
// use it too; SceneFixture wraps it for tests.

#include "proxy/god_object.h"
#include "scene_compiler/compiled_scene.h"
#include "verification/follow_check.h"
#include "verification/surface_crossing_oracle.h"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace mhd::verify {

/// What one tick did.
struct TickSample {
  Eigen::Vector3d p_W_hip = Eigen::Vector3d::Zero();
  Eigen::Vector3d proxy_W = Eigen::Vector3d::Zero();  ///< at the end of the tick
  Eigen::Vector3d force_W = Eigen::Vector3d::Zero();
  bool in_contact = false;
  bool force_clamped = false;
  int plane_count = 0;
  /// ProxyState::path_W[0 .. path_points) after the tick.
  int path_points = 0;
  std::array<Eigen::Vector3d, kMaxProxyPath> path_W{};
};

/// One sample per tick, in order.
using TickRecord = std::vector<TickSample>;

/// The sample of one tick: the HIP it was given, what step_proxy returned and the path
/// it left in `state`.
[[nodiscard]] TickSample make_tick_sample(const Eigen::Vector3d& p_W_hip, const ProxyOutput& out,
                                          const ProxyState& state);

/// Resets the proxy at hip_path_W[0] (which must be in free space), then steps it once
/// per sample, the first included, with dt = 1 / rate_Hz. An empty path gives an empty
/// record. Precondition: rate_Hz > 0, materials indexed like the world's objects.
[[nodiscard]] TickRecord drive_proxy(const CollisionWorld& world, std::span<const HapticMaterial> materials,
                                     const ProxySettings& settings, std::span<const Eigen::Vector3d> hip_path_W,
                                     double rate_Hz);
[[nodiscard]] TickRecord drive_proxy(const CompiledScene& scene, std::span<const Eigen::Vector3d> hip_path_W,
                                     double rate_Hz);

/// A leg of the proxy's path that touches the surface (a pop-through, or a proxy that
/// lost its skin: both break "the proxy never reaches the surface").
struct Crossing {
  std::size_t tick = 0;
  /// -1: from the previous tick's proxy to this tick's path_W[0]; i >= 0: from path_W[i]
  /// to path_W[i + 1], or to the tick's proxy_W for the last waypoint.
  int leg = 0;
  Eigen::Vector3d from_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d to_W = Eigen::Vector3d::Zero();
  OracleHit first_hit;
};

/// Checks every leg of every tick: the tick's waypoints in order, joined to the previous
/// tick's proxy and to the tick's own final proxy where those differ from the ends of
/// path_W (so a proxy that jumps without a recorded path is checked too).
[[nodiscard]] std::vector<Crossing> find_crossings(const SurfaceCrossingOracle& oracle, const TickRecord& records);
/// find_crossings(...).size(): the number of legs that touch the surface.
[[nodiscard]] std::size_t count_crossings(const SurfaceCrossingOracle& oracle, const TickRecord& records);
/// Ticks that ended with the proxy inside or on a closed object (the benchmark protocol's "ended
/// inside the surface"). Open objects have no inside and never count.
[[nodiscard]] std::size_t count_ticks_inside(const SurfaceCrossingOracle& oracle, const TickRecord& records);

/// A hand farther than this from its proxy, with a face's front towards the hand between
/// them, is held behind that face (not pressing into it from the front).
inline constexpr double kHeldGap_m = 0.010;

/// Ticks that ended with the proxy over kHeldGap_m from the HIP and behind a face the HIP
/// is in front of (SurfaceCrossingOracle::segment_meets_a_front): the hand pulled back to
/// the front of an open surface while the proxy stays behind it. Zero on a surface
/// touchable from the front only.
[[nodiscard]] std::size_t count_held_ticks(const SurfaceCrossingOracle& oracle, const TickRecord& records);
/// Of the strokes that begin at the ticks `starts` of one continuous run, those whose
/// first tick is held (as count_held_ticks judges it): the proxy left behind a surface
/// by the strokes before. Starts past the record are not counted.
[[nodiscard]] std::size_t count_strokes_starting_behind(const SurfaceCrossingOracle& oracle,
                                                        const TickRecord& records,
                                                        std::span<const std::size_t> starts);

/// A tick that broke "otherwise go to the hand" (follow_check.h).
struct FollowFailure {
  std::size_t tick = 0;
  FollowVerdict verdict;
  Eigen::Vector3d previous_proxy_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_W_hip = Eigen::Vector3d::Zero();
  Eigen::Vector3d proxy_W = Eigen::Vector3d::Zero();
};

/// Every tick's follow verdict, summed up.
struct FollowCheck {
  std::vector<FollowFailure> failures;
  /// The largest |proxy - HIP| on a tick whose segment proxy -> HIP was free, and the
  /// force on that tick (the follow contract: no such gap over 10 mm).
  double max_free_gap_m = 0.0;
  double force_at_max_free_gap_N = 0.0;
};

/// Checks every tick with check_follow(); the previous proxy of the first tick is where
/// it was reset (its path_W[0], as find_crossings()).
[[nodiscard]] FollowCheck find_follow_failures(const SurfaceCrossingOracle& oracle, const TickRecord& records,
                                               const FollowTolerance& tolerance);

}  // namespace mhd::verify
