// The watchdog on plugin calls, alone: a call shorter than the timeout passes, one longer
// is reported once (the first watched, with its name and how long), and the message is
// the one docs/haptic_server.md shows.
#include "haptic_server/plugin_watchdog.h"

#include <gtest/gtest.h>

namespace {

using namespace mhd;

constexpr double kTimeout_s = 0.1;

void enter(CallWatch& w, const char* call, double since_s) {
  w.call.store(call);
  w.since_s.store(since_s);
}

TEST(PluginWatchdog, IdlePluginsAndCallsWithinTheTimeoutPass) {
  CallWatch device, tracker;
  PluginWatchdog watchdog(kTimeout_s);
  EXPECT_EQ(watchdog.watch(device), 0u);
  EXPECT_EQ(watchdog.watch(tracker), 1u);
  EXPECT_FALSE(watchdog.check(100.0));  // no call under way
  enter(tracker, "tracker_read", 100.0);
  EXPECT_FALSE(watchdog.check(100.1));  // exactly the timeout: not past it
}

TEST(PluginWatchdog, ACallPastTheTimeoutIsReportedOnceWithItsNameAndDuration) {
  CallWatch device, tracker;
  PluginWatchdog watchdog(kTimeout_s);
  (void)watchdog.watch(device);
  (void)watchdog.watch(tracker);
  enter(tracker, "tracker_read", 100.0);
  const auto stuck = watchdog.check(100.103);
  ASSERT_TRUE(stuck);
  EXPECT_EQ(stuck->index, 1u);
  EXPECT_STREQ(stuck->call, "tracker_read");
  EXPECT_NEAR(stuck->running_for_s, 0.103, 1e-9);
  EXPECT_FALSE(watchdog.check(100.2));  // the run ends once
}

TEST(PluginWatchdog, TheFirstWatchedIsReportedWhenTwoAreStuck) {
  CallWatch device, tracker;
  PluginWatchdog watchdog(kTimeout_s);
  (void)watchdog.watch(device);
  (void)watchdog.watch(tracker);
  enter(tracker, "tracker_read", 100.0);
  enter(device, "device_read", 100.05);
  const auto stuck = watchdog.check(100.3);
  ASSERT_TRUE(stuck);
  EXPECT_EQ(stuck->index, 0u);
}

TEST(PluginWatchdog, ACallThatReturnedIsNotStuck) {
  CallWatch base;
  PluginWatchdog watchdog(kTimeout_s);
  (void)watchdog.watch(base);
  enter(base, "base_write", 100.0);
  base.since_s.store(0.0);  // returned
  EXPECT_FALSE(watchdog.check(200.0));
}

TEST(PluginWatchdog, TheMessageNamesThePluginTheCallAndTheTime) {
  EXPECT_EQ(stuck_call_message("fault_tracker", {1, "tracker_read", 0.1034}),
            "plugin 'fault_tracker': tracker_read has not returned after 103 ms (plugin_call_timeout_s); "
            "the run ends");
  EXPECT_EQ(stuck_call_message("x", {0, nullptr, 0.5}),
            "plugin 'x': a call has not returned after 500 ms (plugin_call_timeout_s); the run ends");
}

}  // namespace
