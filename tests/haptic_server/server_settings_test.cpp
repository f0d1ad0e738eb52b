// <server> params: defaults, the event-driven tick and watchdog settings and their
// bounds, and the status line's text for a plugin's drop counters.
#include "haptic_server/plugin_counter.h"
#include "haptic_server/server_settings.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace mhd;
using ::testing::HasSubstr;

SceneDescription scene_with_server(std::map<std::string, std::string> params) {
  SceneDescription scene;
  scene.file = "scene.xml";
  ParamBlock server;
  for (const auto& [name, value] : params) {
    server.params[name] = value;
    server.param_where[name] = SourceLocation{"scene.xml", 7};
  }
  scene.server = server;
  return scene;
}

TEST(ServerSettings, TickOnTrackerSampleAndTheWatchdogHaveDefaults) {
  const Result<ServerSettings> r = server_settings_from(SceneDescription{});
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r->tick_on_tracker_sample);
  EXPECT_DOUBLE_EQ(r->min_tick_interval_s, 0.0002);
  EXPECT_DOUBLE_EQ(r->plugin_call_timeout_s, 0.1);
}

TEST(ServerSettings, TickOnTrackerSampleAndTheWatchdogAreRead) {
  const Result<ServerSettings> r = server_settings_from(scene_with_server(
      {{"tick_on_tracker_sample", "false"}, {"min_tick_interval_s", "0.0003"}, {"plugin_call_timeout_s", "0.25"}}));
  ASSERT_TRUE(r.ok());
  EXPECT_FALSE(r->tick_on_tracker_sample);
  EXPECT_DOUBLE_EQ(r->min_tick_interval_s, 0.0003);
  EXPECT_DOUBLE_EQ(r->plugin_call_timeout_s, 0.25);
}

TEST(ServerSettings, AMinimumTickIntervalLongerThanThePeriodIsRefusedAtItsLine) {
  const Result<ServerSettings> r = server_settings_from(scene_with_server({{"min_tick_interval_s", "0.002"}}));
  EXPECT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics().size(), 1u);
  EXPECT_EQ(r.diagnostics()[0].where.line, 7);
  EXPECT_THAT(r.diagnostics()[0].message, HasSubstr("'min_tick_interval_s' in <server> must not exceed the haptic period"));
}

TEST(ServerSettings, AZeroWatchdogTimeoutIsRefused) {
  const Result<ServerSettings> r = server_settings_from(scene_with_server({{"plugin_call_timeout_s", "0"}}));
  EXPECT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics().size(), 1u);
  EXPECT_THAT(r.diagnostics()[0].message, HasSubstr("plugin_call_timeout_s"));
}

TEST(ServerSettings, AbsurdRatesAndTrackingRangeAreRefusedAtTheirLines) {
  const Result<ServerSettings> r = server_settings_from(scene_with_server(
      {{"io_rate_hz", "1e-308"}, {"base_rate_hz", "1e9"}, {"display_rate_hz", "0.5"}, {"tracking_range_m", "1e9"}}));
  EXPECT_FALSE(r.ok());
  std::vector<std::string> lines;
  for (const Diagnostic& d : r.diagnostics()) lines.push_back(d.to_string());
  EXPECT_EQ(lines, (std::vector<std::string>{
                       "scene.xml:7: error: param 'io_rate_hz' in <server> must be a number in [10, 20000] Hz, got '1e-308'",
                       "scene.xml:7: error: param 'base_rate_hz' in <server> must be a number in [1, 1000] Hz, got '1e9'",
                       "scene.xml:7: error: param 'display_rate_hz' in <server> must be a number in [1, 1000] Hz, got '0.5'",
                       "scene.xml:7: error: param 'tracking_range_m' in <server> must be a number in [1, 1000] m, got '1e9'"}));
}

// The envelope of every declared number: NaN, the infinities, 0, negative, the largest and
// the smallest double are refused wherever they lie outside the declared range, and the
// range's ends and middle are accepted (the companion that a cross-rule compares with set
// so that only the range decides).
TEST(ServerSettings, EveryDeclaredNumberIsRefusedOutsideItsRangeAndAcceptedWithinIt) {
  const std::vector<std::string> envelope = {"nan", "inf", "-inf", "0", "-1", "1e308", "4.9e-324", "-4.9e-324"};
  for (const ServerNumber& n : kServerNumbers) {
    const std::string name(n.name);
    std::vector<std::string> values = envelope;
    for (const double v : {n.low, n.high, (n.low + n.high) / 2.0}) values.push_back(fmt::format("{}", v));
    for (const std::string& value : values) {
      std::map<std::string, std::string> params{{name, value}};
      // The fade must not outlast the timeout: the other one out of the way.
      if (name == "tracker_fade_s") params.emplace(std::string("tracker_timeout_s"), std::string("10"));
      if (name == "tracker_timeout_s") params.emplace(std::string("tracker_fade_s"), std::string("0"));
      const Result<ServerSettings> r = server_settings_from(scene_with_server(params));
      const double v = std::strtod(value.c_str(), nullptr);
      const bool inside = std::isfinite(v) && v >= n.low && v <= n.high &&
                          !(name == "min_tick_interval_s" && v > 0.001);  // the haptic period's own rule
      EXPECT_EQ(r.ok(), inside) << name << " = " << value;
      if (!inside && !r.diagnostics().empty()) {
        EXPECT_EQ(r.diagnostics()[0].where.line, 7) << name << " = " << value;
        EXPECT_THAT(r.diagnostics()[0].message, HasSubstr(fmt::format("'{}'", name))) << name << " = " << value;
      }
    }
  }
}

TEST(ServerSettings, SensorIdsBeyond32BitsAreRefusedNotCut) {
  const Result<ServerSettings> r = server_settings_from(scene_with_server({{"base_sensor_id", "4294967296"}}));
  ASSERT_FALSE(r.ok());
  EXPECT_THAT(r.diagnostics()[0].message, HasSubstr("'base_sensor_id' in <server> must be an integer in [0, 4294967295]"));
  EXPECT_TRUE(server_settings_from(scene_with_server({{"base_sensor_id", "4294967295"}})).ok());
}

TEST(ServerSettings, OtherRigsAreHeadBasePairsOfSensorIds) {
  const Result<ServerSettings> none = server_settings_from(SceneDescription{});
  ASSERT_TRUE(none.ok());
  EXPECT_EQ(none->other_rigs.count, 0u);
  EXPECT_DOUBLE_EQ(none->other_rigs_timeout_s, 0.3);
  const Result<ServerSettings> two =
      server_settings_from(scene_with_server({{"other_rig_sensors", " 2:3\t4294967295:17 "},
                                              {"other_rigs_timeout_s", "0.5"}}));
  ASSERT_TRUE(two.ok());
  ASSERT_EQ(two->other_rigs.count, 2u);
  EXPECT_EQ(two->other_rigs.rigs[0].head_sensor_id, 2u);
  EXPECT_EQ(two->other_rigs.rigs[0].base_sensor_id, 3u);
  EXPECT_EQ(two->other_rigs.rigs[1].head_sensor_id, 4294967295u);
  EXPECT_EQ(two->other_rigs.rigs[1].base_sensor_id, 17u);
  EXPECT_DOUBLE_EQ(two->other_rigs_timeout_s, 0.5);
  std::string eight;
  for (int i = 0; i < 8; ++i) eight += fmt::format("{}:{} ", 10 + 2 * i, 11 + 2 * i);
  const Result<ServerSettings> most = server_settings_from(scene_with_server({{"other_rig_sensors", eight}}));
  ASSERT_TRUE(most.ok());
  EXPECT_EQ(most->other_rigs.count, kMaxOtherRigs);
}

TEST(ServerSettings, BadOtherRigSensorsAreRefusedAtTheirLine) {
  std::string nine;
  for (int i = 0; i < 9; ++i) nine += fmt::format("{}:{} ", 10 + 2 * i, 11 + 2 * i);
  const std::vector<std::pair<std::string, std::string>> cases{
      {"2", "must be HEAD:BASE pairs"},          {"2:", "must be HEAD:BASE pairs"},
      {":3", "must be HEAD:BASE pairs"},         {"2:x", "must be HEAD:BASE pairs"},
      {"-2:3", "must be HEAD:BASE pairs"},       {"2:3:4", "must be HEAD:BASE pairs"},
      {"4294967296:3", "must be HEAD:BASE pairs"}, {"99999999999999999999:3", "must be HEAD:BASE pairs"},
      {"2:nan", "must be HEAD:BASE pairs"},      {"2:2", "names sensor 2 twice"},
      {"2:3 3:4", "names sensor 3 twice"},       {"0:3", "names sensor 0 twice, or one of the rig's own"},
      {"2:1", "names sensor 1 twice, or one of the rig's own"}, {nine, "names more than 8 rigs"}};
  for (const auto& [text, message] : cases) {
    const Result<ServerSettings> r = server_settings_from(scene_with_server({{"other_rig_sensors", text}}));
    ASSERT_FALSE(r.ok()) << text;
    ASSERT_EQ(r.error().size(), 1u) << text;
    EXPECT_THAT(r.error()[0].to_string(), HasSubstr("scene.xml:7: error: param 'other_rig_sensors' in <server> "))
        << text;
    EXPECT_THAT(r.error()[0].to_string(), HasSubstr(message)) << text;
  }
  for (const std::string t : {"0", "-1", "nan", "inf", "11"}) {
    EXPECT_FALSE(server_settings_from(scene_with_server({{"other_rigs_timeout_s", t}})).ok()) << t;
  }
}

TEST(ServerSettings, TheTrackingRangeHasADefaultAndIsRead) {
  EXPECT_DOUBLE_EQ(server_settings_from(SceneDescription{})->tracking_range_m, 50.0);
  const Result<ServerSettings> r = server_settings_from(scene_with_server({{"tracking_range_m", "20"}}));
  ASSERT_TRUE(r.ok());
  EXPECT_DOUBLE_EQ(r->tracking_range_m, 20.0);
}

TEST(ServerSettings, TheBasePoseComesFromTheTrackerUnlessOdometryIsAskedFor) {
  const Result<ServerSettings> by_default = server_settings_from(SceneDescription{});
  ASSERT_TRUE(by_default.ok());
  EXPECT_EQ(by_default->base_pose_source, BasePoseSource::Tracker);
  const Result<ServerSettings> odometry = server_settings_from(scene_with_server({{"base_pose_source", "odometry"}}));
  ASSERT_TRUE(odometry.ok());
  EXPECT_EQ(odometry->base_pose_source, BasePoseSource::Odometry);
  for (const char* bad : {"gps", "", "Odometry", "tracker odometry"}) {
    const Result<ServerSettings> r = server_settings_from(scene_with_server({{"base_pose_source", bad}}));
    ASSERT_FALSE(r.ok()) << bad;
    ASSERT_EQ(r.diagnostics().size(), 1u);
    EXPECT_EQ(r.diagnostics()[0].where.line, 7);
    EXPECT_THAT(r.diagnostics()[0].message,
                HasSubstr("param 'base_pose_source' in <server> must be tracker or odometry, got '" + std::string(bad) +
                          "'"));
  }
}

TEST(PluginCounters, OnlyNonZeroDropsAreShownWithoutTheirPrefix) {
  EXPECT_EQ(dropped_counts_text({}), "");
  EXPECT_EQ(dropped_counts_text({{"accepted", 120}, {"dropped_stale", 0}}), "");
  EXPECT_EQ(dropped_counts_text({{"accepted", 120}, {"dropped_stale", 3}, {"dropped_unknown_rig", 12}, {"reads", 9}}),
            "stale 3, unknown_rig 12");
}

}  // namespace
