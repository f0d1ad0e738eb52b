#include "realtime/periodic_timer.h"

#include <cerrno>
#include <algorithm>
#include <cmath>

namespace mhd::realtime {
namespace {

std::int64_t now_ns() noexcept {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

void sleep_until_ns(std::int64_t t_ns) noexcept {
  timespec deadline{};
  deadline.tv_sec = static_cast<time_t>(t_ns / 1'000'000'000);
  deadline.tv_nsec = static_cast<long>(t_ns % 1'000'000'000);
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &deadline, nullptr) == EINTR) {
  }
}

}  // namespace

PeriodicTimer::PeriodicTimer(double period_s) noexcept
    : period_s_(period_s), period_ns_(std::max<std::int64_t>(1, std::llround(period_s * 1e9))) {
  restart();
}

void PeriodicTimer::restart() noexcept {
  last_tick_ns_ = now_ns();
  next_ns_ = last_tick_ns_ + period_ns_;
}

void PeriodicTimer::skip_missed_deadlines() noexcept {
  const std::int64_t now = now_ns();
  if (now > next_ns_) {
    // Late: the work since the last deadline ran past this one. Skip the deadlines that
    // are gone and wait for the next one still ahead.
    ++stats_.overruns;
    const std::int64_t behind = (now - next_ns_) / period_ns_;
    stats_.missed_deadlines += static_cast<std::uint64_t>(behind);
    next_ns_ += (behind + 1) * period_ns_;
  }
}

double PeriodicTimer::start_deadline_tick() noexcept {
  sleep_until_ns(next_ns_);
  const std::int64_t woke_for = next_ns_;
  next_ns_ += period_ns_;
  last_tick_ns_ = woke_for;
  ++stats_.ticks;
  return static_cast<double>(woke_for) * 1e-9;
}

double PeriodicTimer::wait_next() noexcept {
  skip_missed_deadlines();
  return start_deadline_tick();
}

double PeriodicTimer::wait_next_or(WakeEvent& event, double min_interval_s) noexcept {
  skip_missed_deadlines();
  if (event.wait_until_ns(next_ns_)) {
    const std::int64_t min_interval_ns = std::llround(std::max(0.0, min_interval_s) * 1e9);
    const std::int64_t now = now_ns();
    const std::int64_t start = std::max(now, last_tick_ns_ + min_interval_ns);
    // An extra tick only where it keeps min_interval_s from both neighbours; closer to
    // the deadline, the deadline's own tick is the early one.
    if (start + min_interval_ns <= next_ns_) {
      if (start > now) sleep_until_ns(start);
      last_tick_ns_ = start;
      ++stats_.early_wakes;
      ++stats_.ticks;
      return static_cast<double>(start) * 1e-9;
    }
  }
  return start_deadline_tick();
}

double PeriodicTimer::monotonic_now_s() noexcept { return static_cast<double>(now_ns()) * 1e-9; }

}  // namespace mhd::realtime
