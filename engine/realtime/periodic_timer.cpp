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

}  // namespace

PeriodicTimer::PeriodicTimer(double period_s) noexcept
    : period_s_(period_s), period_ns_(std::max<std::int64_t>(1, std::llround(period_s * 1e9))) {
  restart();
}

void PeriodicTimer::restart() noexcept { next_ns_ = now_ns() + period_ns_; }

double PeriodicTimer::wait_next() noexcept {
  const std::int64_t now = now_ns();
  if (now > next_ns_) {
    // Late: the work since the last deadline ran past this one. Skip the deadlines that
    // are gone and wait for the next one still ahead.
    ++stats_.overruns;
    const std::int64_t behind = (now - next_ns_) / period_ns_;
    stats_.missed_deadlines += static_cast<std::uint64_t>(behind);
    next_ns_ += (behind + 1) * period_ns_;
  }
  timespec deadline{};
  deadline.tv_sec = static_cast<time_t>(next_ns_ / 1'000'000'000);
  deadline.tv_nsec = static_cast<long>(next_ns_ % 1'000'000'000);
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &deadline, nullptr) == EINTR) {
  }
  const std::int64_t woke_for = next_ns_;
  next_ns_ += period_ns_;
  ++stats_.ticks;
  return static_cast<double>(woke_for) * 1e-9;
}

double PeriodicTimer::monotonic_now_s() noexcept { return static_cast<double>(now_ns()) * 1e-9; }

}  // namespace mhd::realtime
