// The one place a ServerStatus is filled: every published value reaches the snapshot, and
// the haptic rate is over the window asked for (the status line's interval, or the run).
#include "haptic_server/status_counters.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace mhd;

TEST(StatusCounters, ASnapshotCarriesEveryPublishedValue) {
  StatusCounters c;
  c.ticks = 2500;
  c.overruns = 3;
  c.early_ticks = 40;
  c.in_contact = true;
  c.force_N = 2.41;
  c.safety_gain = 0.5;
  c.tracker_age_s = 0.007;
  c.tracker_samples = 4320;
  c.tracker_rejected = 2;
  PluginCounterFrame counters;
  counters.names[0] = "stale";
  counters.values[0] = 3;
  counters.names[1] = "unknown_rig";
  counters.values[1] = 12;
  counters.count = 2;
  c.tracker_plugin_counters.write(counters);
  BasePose base;
  base.x_m = -0.14;
  base.z_m = -0.78;
  base.heading_rad = 0.5;
  c.base.set(base);

  const ServerStatus s = c.snapshot(2.5, 0, 2.5);
  EXPECT_EQ(s.elapsed_s, 2.5);
  EXPECT_EQ(s.ticks, 2500u);
  EXPECT_EQ(s.haptic_rate_hz, 1000.0);
  EXPECT_EQ(s.overruns, 3u);
  EXPECT_EQ(s.early_ticks, 40u);
  EXPECT_TRUE(s.in_contact);
  EXPECT_EQ(s.force_N, 2.41);
  EXPECT_EQ(s.safety_gain, 0.5);
  EXPECT_EQ(s.tracker_age_s, 0.007);
  EXPECT_EQ(s.tracker_samples, 4320u);
  EXPECT_EQ(s.tracker_rejected, 2u);
  ASSERT_EQ(s.tracker_plugin_counters.size(), 2u);
  EXPECT_EQ(s.tracker_plugin_counters[1].name, "unknown_rig");
  EXPECT_EQ(s.tracker_plugin_counters[1].value, 12u);
  EXPECT_EQ(s.base.x_m, -0.14);
  EXPECT_EQ(s.base.z_m, -0.78);
  EXPECT_EQ(s.base.heading_rad, 0.5);
  // A later snapshot with nothing newer still carries the counters.
  EXPECT_EQ(c.snapshot(2.6, 0, 2.6).tracker_plugin_counters.size(), 2u);
}

TEST(StatusCounters, TheRateIsOverTheWindowAndZeroWithoutOne) {
  StatusCounters c;
  c.ticks = 1500;
  EXPECT_DOUBLE_EQ(c.snapshot(1.5, 1000, 0.5).haptic_rate_hz, 1000.0);  // a status interval
  EXPECT_EQ(c.snapshot(0.0, 0, 0.0).haptic_rate_hz, 0.0);               // a run that never ran
}

TEST(StatusCounters, BeforeAnythingIsPublishedTheTrackerIsInfinitelyOld) {
  StatusCounters c;
  const ServerStatus s = c.snapshot(0.0, 0, 0.0);
  EXPECT_EQ(s.ticks, 0u);
  EXPECT_TRUE(std::isinf(s.tracker_age_s));
  EXPECT_FALSE(s.in_contact);
}

}  // namespace
