#pragma once
// Runs a stroke set through the proxy at a fixed rate, timing every update and checking
// every proxy move against the exact surface oracle. Used by `mhd run` and the bench.

#include "verification/proxy_drive.h"
#include "verification/stroke_set.h"

#include <cstddef>
#include <vector>

namespace mhd::verify {

/// Order statistics of per-update times, microseconds.
struct LatencySummary {
  std::size_t count = 0;
  double median_us = 0, p99_us = 0, p999_us = 0, max_us = 0;
};

/// Sorts `samples_us` and summarises it (all zero for an empty input).
[[nodiscard]] LatencySummary summarize_latency(std::vector<double>& samples_us);

struct StrokeRunReport {
  std::size_t strokes = 0;
  std::size_t ticks = 0;
  std::size_t contact_ticks = 0;
  std::size_t clamped_ticks = 0;
  int max_plane_count = 0;
  double max_force_N = 0.0;
  double mean_contact_force_N = 0.0;
  LatencySummary contact_updates;  ///< ticks that ended in contact
  LatencySummary all_updates;  ///< every tick, free-space transit included
  /// The look-aheads between ticks (proxy/proxy_look_ahead.h), timed apart from the ticks:
  /// the haptic thread's other work, off the path from the reading to the force. Empty
  /// when the run did not look ahead.
  LatencySummary look_ahead_updates;
  std::size_t budget_exhausted_ticks = 0;  ///< ticks whose proxy hit its work budget
  int max_sweeps = 0;                      ///< most sweeps one tick made
  /// Contact ticks and summed force magnitude per object (indexed like the world).
  std::vector<std::size_t> contact_ticks_by_object;
  std::vector<double> force_sum_by_object_N;
  std::size_t pop_throughs = 0;  ///< proxy moves that touched the surface (exact check)
  std::size_t ticks_inside = 0;  ///< ticks that ended inside a closed object
  std::size_t held_ticks = 0;    ///< ticks held behind a face the hand is in front of (count_held_ticks)
  /// Strokes begun, each joined one of a continuous run counted (Stroke::stroke_starts),
  /// and those begun with the proxy held behind a surface (count_strokes_starting_behind).
  std::size_t strokes_begun = 0;
  std::size_t strokes_starting_behind = 0;
  /// Ticks where the proxy did not go to a HIP it could reach (follow_check.h, exact,
  /// tolerance kFollowTolerance_m at the scene's stiffest material).
  std::size_t follow_failures = 0;
  double max_free_gap_m = 0.0;  ///< largest |proxy - HIP| with the segment between them free
  /// Page faults of the thread that stepped the strokes, while it stepped them (time_strokes
  /// only: with an oracle, its checks between strokes would count too). Minor: the page was
  /// in memory (the page cache, a page let go); major: it came from the disk.
  long minor_page_faults = 0;
  long major_page_faults = 0;
};

/// Steps the proxy along every stroke (reset at each stroke's first sample). With
/// `look_ahead`, between ticks as the haptic server does.
[[nodiscard]] StrokeRunReport run_strokes(const CompiledScene& scene, const SurfaceCrossingOracle& oracle,
                                          const StrokeSet& strokes, double rate_Hz, bool look_ahead = true);

/// run_strokes() timing the ticks only: nothing is judged (the exact counts stay 0), so no
/// oracle is built. For meshes whose oracle does not fit in memory (about 250 bytes a
/// triangle beside the engine's), driven along a path made on a coarser mesh of the shape.
[[nodiscard]] StrokeRunReport time_strokes(const CompiledScene& scene, const StrokeSet& strokes, double rate_Hz,
                                           bool look_ahead = true);

}  // namespace mhd::verify
