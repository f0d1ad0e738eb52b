#include "realtime/periodic_timer.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

namespace {

using mhd::realtime::PeriodicTimer;

TEST(PeriodicTimer, DeadlinesAreAbsoluteMultiplesOfThePeriod) {
  PeriodicTimer timer(0.002);
  const double first = timer.wait_next();
  const double second = timer.wait_next();
  const double third = timer.wait_next();
  // Exact schedule, whatever the wake-up latency: no drift accumulates. (On a loaded
  // machine a late wake-up skips whole periods, so the gaps are whole multiples.)
  for (const double gap : {second - first, third - second}) {
    const double periods = gap / 0.002;
    EXPECT_GE(periods, 1.0 - 1e-6);
    EXPECT_NEAR(periods, std::round(periods), 1e-6);
  }
  EXPECT_GE(PeriodicTimer::monotonic_now_s(), third);
  EXPECT_EQ(timer.stats().ticks, 3u);
}

TEST(PeriodicTimer, ALateTickCountsAnOverrunAndSkipsTheMissedDeadlines) {
  PeriodicTimer timer(0.001);
  const double first = timer.wait_next();
  const auto before = timer.stats();
  // Work that runs well past the next deadlines (sleep never returns early).
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const double after = timer.wait_next();
  EXPECT_EQ(timer.stats().overruns - before.overruns, 1u);
  EXPECT_GE(timer.stats().missed_deadlines - before.missed_deadlines, 4u);
  // It woke for a deadline still on the schedule and in the future of the late work,
  // not for each missed one in a burst.
  EXPECT_GE(after - first, 0.005);
  const double steps = (after - first) / 0.001;
  EXPECT_NEAR(steps, std::round(steps), 1e-6);
}

}  // namespace
