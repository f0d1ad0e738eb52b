#pragma once
// What the server's threads publish for the status while they run, and the one place a
// ServerStatus is filled from it (for the live status line and for the report alike).
// The haptic and io threads write only atomics and lock-free hand-offs (no lock, no
// allocation); run()'s thread alone takes the snapshots.

#include "haptic_server/plugin_counter.h"
#include "haptic_server/server_status.h"
#include "haptic_server/shared_value.h"
#include "kinematics/base_pose.h"
#include "realtime/triple_buffer.h"

#include <atomic>
#include <cstdint>
#include <limits>
#include <vector>

namespace mhd {

struct StatusCounters {
  // haptic thread
  std::atomic<std::uint64_t> ticks{0}, overruns{0}, early_ticks{0};
  std::atomic<bool> in_contact{false};
  std::atomic<double> force_N{0.0}, safety_gain{0.0}, tracker_age_s{std::numeric_limits<double>::infinity()};
  // io thread
  std::atomic<std::uint64_t> tracker_samples{0}, tracker_rejected{0};
  realtime::TripleBuffer<PluginCounterFrame> tracker_plugin_counters;  ///< read by run()'s thread
  // planner thread
  SharedValue<BasePose> base;

  /// Every field now. `elapsed_s` is the run's time so far; haptic_rate_hz counts the
  /// ticks since there were `ticks_before`, over `window_s` (0 when window_s is not positive).
  /// run()'s thread only (the reader of the hand-offs).
  [[nodiscard]] ServerStatus snapshot(double elapsed_s, std::uint64_t ticks_before, double window_s);
};

}  // namespace mhd
