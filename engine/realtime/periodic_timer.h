#pragma once
// Runs a loop at a fixed rate against absolute deadlines on CLOCK_MONOTONIC: deadline k
// is start + k * period, so lateness never accumulates into drift. A tick that finishes
// after its next deadline is an overrun; the timer then skips the deadlines already
// missed (it does not burst to catch up) and counts them.

#include <cstdint>
#include <ctime>

namespace mhd::realtime {

struct TimerStats {
  std::uint64_t ticks = 0;
  std::uint64_t overruns = 0;         ///< ticks that ended after the next deadline
  std::uint64_t missed_deadlines = 0;  ///< deadlines skipped because of overruns
};

class PeriodicTimer {
 public:
  /// `period_s` > 0. The first deadline is one period after construction (or restart()).
  explicit PeriodicTimer(double period_s) noexcept;

  /// Sleeps until the next deadline; returns the deadline woken for, in seconds on the
  /// monotonic clock. Counts an overrun when the deadline had already passed.
  double wait_next() noexcept;
  /// Makes now the start of the schedule.
  void restart() noexcept;

  [[nodiscard]] double period_s() const noexcept { return period_s_; }
  [[nodiscard]] const TimerStats& stats() const noexcept { return stats_; }

  /// Seconds on CLOCK_MONOTONIC.
  [[nodiscard]] static double monotonic_now_s() noexcept;

 private:
  double period_s_;
  std::int64_t period_ns_;
  std::int64_t next_ns_ = 0;
  TimerStats stats_;
};

}  // namespace mhd::realtime
