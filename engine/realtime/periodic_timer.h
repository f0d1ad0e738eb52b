#pragma once
// Runs a loop at a fixed rate against absolute deadlines on CLOCK_MONOTONIC: deadline k
// is start + k * period, so lateness never accumulates into drift. A tick that finishes
// after its next deadline is an overrun; the timer then skips the deadlines already
// missed (it does not burst to catch up) and counts them.
// wait_next_or() also wakes on an event (a new tracker sample) for an extra tick between
// deadlines, so a loop can act on fresh input at once; the schedule itself never moves.

#include "realtime/wake_event.h"

#include <cstdint>
#include <ctime>

namespace mhd::realtime {

struct TimerStats {
  std::uint64_t ticks = 0;
  std::uint64_t overruns = 0;         ///< ticks that ended after the next deadline
  std::uint64_t missed_deadlines = 0;  ///< deadlines skipped because of overruns
  std::uint64_t early_wakes = 0;       ///< extra ticks started by an event between deadlines
};

class PeriodicTimer {
 public:
  /// `period_s` > 0. The first deadline is one period after construction (or restart()).
  explicit PeriodicTimer(double period_s) noexcept;

  /// Sleeps until the next deadline; returns the deadline woken for, in seconds on the
  /// monotonic clock. Counts an overrun when the deadline had already passed.
  double wait_next() noexcept;
  /// As wait_next(), but an `event` signalled before the deadline starts an extra tick:
  /// at once, or `min_interval_s` after the previous tick's start if that is later, as
  /// long as it also starts `min_interval_s` before the deadline (else the deadline's
  /// tick serves). Ticks are thus never closer than min_interval_s, and the deadlines
  /// stay those of wait_next(). Returns the tick's start time.
  double wait_next_or(WakeEvent& event, double min_interval_s) noexcept;
  /// The deadline the next wait_next() sleeps until, in seconds on the monotonic clock.
  [[nodiscard]] double next_deadline_s() const noexcept { return static_cast<double>(next_ns_) * 1e-9; }
  /// Makes now the start of the schedule.
  void restart() noexcept;

  [[nodiscard]] double period_s() const noexcept { return period_s_; }
  [[nodiscard]] const TimerStats& stats() const noexcept { return stats_; }

  /// Seconds on CLOCK_MONOTONIC.
  [[nodiscard]] static double monotonic_now_s() noexcept;

 private:
  void skip_missed_deadlines() noexcept;
  /// Sleeps to the next deadline (if still ahead), starts its tick and moves the schedule on.
  double start_deadline_tick() noexcept;

  double period_s_;
  std::int64_t period_ns_;
  std::int64_t next_ns_ = 0;
  std::int64_t last_tick_ns_ = 0;  ///< start of the previous tick
  TimerStats stats_;
};

}  // namespace mhd::realtime
