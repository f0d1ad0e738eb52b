#include "realtime/periodic_timer.h"
#include "realtime/wake_event.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

namespace {

using mhd::realtime::PeriodicTimer;
using mhd::realtime::WakeEvent;

std::int64_t ns(double s) { return std::llround(s * 1e9); }

TEST(WakeEvent, AWaitWithoutSignalTimesOutAndAPendingSignalReturnsAtOnce) {
  WakeEvent event;
  EXPECT_FALSE(event.try_consume());
  EXPECT_FALSE(event.wait_until_ns(ns(PeriodicTimer::monotonic_now_s() + 0.002)));
  event.signal();
  // Far deadline: only the signal can end this wait.
  EXPECT_TRUE(event.wait_until_ns(ns(PeriodicTimer::monotonic_now_s() + 600.0)));
}

TEST(WakeEvent, SignalsDoNotPileUp) {
  WakeEvent event;
  event.signal();
  event.signal();
  event.signal();
  EXPECT_TRUE(event.wait_until_ns(ns(PeriodicTimer::monotonic_now_s() + 600.0)));
  EXPECT_FALSE(event.try_consume());
  EXPECT_FALSE(event.wait_until_ns(ns(PeriodicTimer::monotonic_now_s() + 0.001)));
}

TEST(WakeEvent, ASignalFromAnotherThreadWakesTheWaiter) {
  WakeEvent event;
  std::thread signaller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    event.signal();
  });
  EXPECT_TRUE(event.wait_until_ns(ns(PeriodicTimer::monotonic_now_s() + 600.0)));
  signaller.join();
}

TEST(PeriodicTimerWithEvent, WithoutAnEventItKeepsTheSchedule) {
  WakeEvent event;
  PeriodicTimer timer(0.002);
  const double first = timer.wait_next_or(event, 0.001);
  const double second = timer.wait_next_or(event, 0.001);
  const double periods = (second - first) / 0.002;
  EXPECT_GE(periods, 1.0 - 1e-6);
  EXPECT_NEAR(periods, std::round(periods), 1e-6);
  EXPECT_EQ(timer.stats().early_wakes, 0u);
}

TEST(PeriodicTimerWithEvent, AnEventStartsAnExtraTickAndTheScheduleStays) {
  WakeEvent event;
  PeriodicTimer timer(60.0);  // a deadline nothing in this test reaches
  const double started_s = PeriodicTimer::monotonic_now_s();
  const double deadline_s = timer.next_deadline_s();
  std::thread signaller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    event.signal();
  });
  const double tick_s = timer.wait_next_or(event, 0.0);
  signaller.join();
  EXPECT_LT(tick_s - started_s, 30.0);
  EXPECT_EQ(timer.stats().early_wakes, 1u);
  EXPECT_EQ(timer.stats().ticks, 1u);
  EXPECT_EQ(timer.next_deadline_s(), deadline_s);
}

TEST(PeriodicTimerWithEvent, AnEventTooCloseToTheDeadlineIsLeftToTheDeadlinesTick) {
  WakeEvent event;
  PeriodicTimer timer(0.05);
  const double deadline_s = timer.next_deadline_s();
  event.signal();
  // An extra tick would have to wait 40 ms for the minimum interval, and then be 10 ms
  // from the deadline: the deadline's tick takes it.
  const double tick_s = timer.wait_next_or(event, 0.04);
  EXPECT_EQ(tick_s, deadline_s);
  EXPECT_EQ(timer.stats().early_wakes, 0u);
  EXPECT_NEAR(timer.next_deadline_s() - deadline_s, 0.05, 1e-9);
}

TEST(PeriodicTimerWithEvent, AnEarlyTickWaitsForTheMinimumInterval) {
  WakeEvent event;
  PeriodicTimer timer(60.0);
  event.signal();
  const double first = timer.wait_next_or(event, 0.0);
  event.signal();  // already pending when the next wait starts
  const double second = timer.wait_next_or(event, 0.02);
  EXPECT_GE(second - first, 0.02 - 1e-9);
  EXPECT_LT(second - first, 30.0);
  EXPECT_EQ(timer.stats().early_wakes, 2u);
}

}  // namespace
