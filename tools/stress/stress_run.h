#pragma once
// Throws stress strokes (stress_strokes.h) at one object of a compiled scene through
// the engine's god-object proxy, ticking it exactly as the haptic server does
// (reset_proxy at a free start, then step_proxy once per HIP sample with the scene's
// materials and proxy settings), and checks every tick (popthrough_check.h).
// Strokes come in chains: the first stroke of a chain resets the proxy, the others
// continue from where the previous one left the HIP (joined at full speed) where their
// start is near enough, else they reset too. A share of the chains are tours: every
// stroke of the chain a Tour, one continuous path (tour_strokes.h).

#include "scene_compiler/compiled_scene.h"
#include "stress/popthrough_check.h"
#include "stress/stress_strokes.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace mhd::stress {

struct StressSettings {
  std::size_t strokes = 100000;
  std::uint64_t seed = 1;
  /// Strokes per chain; 1 resets the proxy before every stroke.
  std::size_t chain_length = 8;
  StressStrokeParams stroke;
  EngineContainment engine = EngineContainment::Contact;
  int engine_stride = 1;  ///< ask the engine on every n-th tick the policy allows
  /// Follow failures allow this gap, and its spring force at the scene's stiffest material.
  double follow_tolerance_m = verify::kFollowTolerance_m;
  /// Failing strokes kept in the report (all are counted).
  std::size_t max_failures_kept = 10;
  /// For the checker's own tests only: called after every step_proxy to break the
  /// proxy on purpose (e.g. move it to the HIP); the check sees the altered result.
  std::function<void(const Eigen::Vector3d& p_W_hip, ProxyState&, ProxyOutput&)> tamper;
};

/// The first failing tick of one stroke.
struct StrokeFailure {
  std::size_t stroke = 0;
  StrokeKind kind = StrokeKind::Random;
  std::size_t tick = 0;  ///< within the stroke (connector samples included)
  Eigen::Vector3d p_W_hip = Eigen::Vector3d::Zero();
  Eigen::Vector3d proxy_W = Eigen::Vector3d::Zero();
  TickVerdict verdict;
};

struct ObjectStressReport {
  std::string object_name;
  std::size_t triangles = 0;
  bool closed = false;
  std::size_t ridges = 0, creases = 0, corners = 0;
  std::size_t strokes = 0;
  std::array<std::size_t, kStrokeKindCount> strokes_by_kind{};
  std::size_t resets = 0;  ///< strokes that started with a proxy reset (the others continued)
  std::size_t ticks = 0;
  std::size_t contact_ticks = 0;
  std::size_t inside_ticks = 0;         ///< exact: proxy inside or on a closed object
  std::size_t crossing_ticks = 0;       ///< exact: a leg of the proxy's motion touched the surface
  std::size_t engine_checks = 0;        ///< ticks on which point_inside_surface was asked
  std::size_t inside_engine_ticks = 0;  ///< ... and said inside
  /// Exact: the proxy did not go to a HIP it could reach (F1 or F2, follow_check.h) ...
  std::size_t follow_failure_ticks = 0;
  std::size_t stuck_ticks = 0;                ///< ... of which F1 (the straight way was free)
  std::size_t brushed_ticks = 0;              ///< not failures: the way passed a surface closer than the proxy's skin
  std::size_t longest_follow_failure_ticks = 0;  ///< longest run of consecutive such ticks
  /// Largest |proxy - HIP| on a tick whose segment proxy -> HIP was free, and the force then.
  double max_free_gap_m = 0.0;
  double force_at_max_free_gap_N = 0.0;
  std::size_t failing_strokes = 0;  ///< a pop-through or a follow failure
  std::size_t failing_strokes_by_kind[kStrokeKindCount] = {};
  double worst_penetration_m = 0.0;  ///< of the proxy (0 for a clean run)
  double max_hip_depth_m = 0.0;      ///< largest HIP-proxy distance in contact: how hard strokes pushed
  int max_plane_count = 0;
  std::size_t start_redraws = 0;  ///< stroke starts drawn again (not free)
  /// step_proxy() wall time per tick, microseconds (quantiles from a histogram with
  /// 20 log-spaced bins per decade, so within about 12 %; the maximum is exact). Taken
  /// on whatever else the machine runs: a bound on the engine's own cost, not a benchmark.
  double step_median_us = 0.0, step_p99_us = 0.0, step_p999_us = 0.0, step_max_us = 0.0;
  double seconds = 0.0;
  std::vector<StrokeFailure> failures;  ///< the first max_failures_kept failing strokes
  [[nodiscard]] bool clean() const { return failing_strokes == 0; }
};

/// What to report while running: nothing, or one line per tick of the given stroke.
struct StressTrace {
  std::FILE* out = nullptr;
  std::size_t stroke = 0;
};

/// Runs strokes [0, settings.strokes) at `object`. `object_key` names the random stream
/// (name_key of "scene/object"), so a stroke's geometry depends on (seed, key, index) only.
[[nodiscard]] ObjectStressReport stress_object(const CompiledScene& scene, const verify::SurfaceCrossingOracle& oracle,
                                               int object, std::uint64_t object_key, const StressSettings& settings);

/// Reruns the chain that holds stroke `stroke` up to and including it, printing every
/// tick of that stroke to `out`. Returns the report of the strokes run.
ObjectStressReport replay_stroke(const CompiledScene& scene, const verify::SurfaceCrossingOracle& oracle, int object,
                                 std::uint64_t object_key, const StressSettings& settings, std::size_t stroke,
                                 std::FILE* out);

}  // namespace mhd::stress
