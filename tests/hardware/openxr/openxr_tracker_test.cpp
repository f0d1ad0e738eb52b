// The `openxr` tracker driven by `mhd run` through the real OpenXR loader, against the fake
// runtime (fake_openxr_runtime.cpp) that XR_RUNTIME_JSON names. The head comes from the
// headset, the base pose from the simulated base's odometry; judged from the headset's
// log (the session begun, ended and destroyed) and the base's (every twist it received).
#include "hardware_run.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using mhd::test::CommandLogRow;
using mhd::test::MhdRunProcess;
using namespace mhd::test::hardware;

/// How long after the head's last tracked pose the base may still get a non-zero twist:
/// the guard's tracker_timeout_s (0.05 s), one base command period (10 Hz: 0.1 s) and the
/// slack of lining up the two logs (their clocks meet at the run's end, a few ms apart).
constexpr double kStaleHeadStopsBaseWithin_s = 0.25;

fs::path fresh_dir(const std::string& name) { return mhd::test::scratch_dir("openxr", name); }

void write_scene(const fs::path& dir, const std::string& tracker_params = "", const std::string& extra = "") {
  std::ofstream(dir / "scene.xml") << mhd::test::fill_scene_template(
      fs::path(MHD_SOURCE_DIR) / "tests/data/hardware/openxr_mobile.xml",
      {{"<!--TRACKER-->", tracker_params}, {"<!--EXTRA-->", extra}});
}

/// The fake runtime's configuration (simulated_headset.h).
struct Fake {
  std::string fault = "none";
  double fault_after_s = 1.0;
  bool installed = true;  ///< XR_RUNTIME_JSON names the fake's manifest, else a file that is not there
};

MhdRunProcess run(const fs::path& dir, double duration_s, const Fake& fake = {}, const std::string& verb = "run") {
  std::vector<std::string> argv{MHD_CLI, verb, (dir / "scene.xml").string()};
  if (verb == "run") {
    argv.insert(argv.end(), {"--duration", std::to_string(duration_s), "-q"});
  }
  for (const char* a : {"--plugin-path", MHD_SIM_PLUGIN_DIR, "--plugin-path", MHD_FAULT_INJECTION_PLUGIN_DIR}) {
    argv.emplace_back(a);
  }
  return MhdRunProcess(
      {.argv = argv,
       .dir = dir,
       .env = {{"XR_RUNTIME_JSON",
                fake.installed ? MHD_FAKE_OPENXR_MANIFEST : (dir / "no_runtime_here/active_runtime.json").string()},
               {"MHD_FAKE_LOG", (dir / "headset.csv").string()},
               {"MHD_FAKE_FAULT", fake.fault},
               {"MHD_FAKE_FAULT_AFTER_S", std::to_string(fake.fault_after_s)}}});
}

/// The headset's session events in order, without locates and spaces.
std::vector<std::string> session_events(const fs::path& dir) {
  std::vector<std::string> out;
  for (const CommandLogRow& r : log_of(dir / "headset.csv")) {
    if (r.event != "locate" && r.event != "destroy_space") out.push_back(r.event);
  }
  return out;
}

std::string joined(const std::vector<std::string>& events) {
  std::string out;
  for (const std::string& e : events) out += e + " ";
  return out;
}

/// The session was begun, then ended and everything destroyed, in that order, last.
void expect_session_closed(const fs::path& dir, const std::string& output) {
  const std::vector<std::string> events = session_events(dir);
  ASSERT_GE(events.size(), 3u) << joined(events) << "\n" << output;
  EXPECT_NE(std::find(events.begin(), events.end(), "begin_session"), events.end()) << joined(events);
  const std::vector<std::string> last(events.end() - 3, events.end());
  EXPECT_EQ(last, (std::vector<std::string>{"end_session", "destroy_session", "destroy_instance"}))
      << joined(events) << "\n" << output;
  // Both spaces were destroyed before the session.
  EXPECT_EQ(rows_of(dir / "headset.csv", "destroy_space").size(), 2u);
}

/// The base's last command (or its watchdog's) is zero.
void expect_base_stopped(const fs::path& dir, const std::string& output) {
  const auto all = log_of(dir / "base.csv");
  const auto last = std::find_if(all.rbegin(), all.rend(), [](const CommandLogRow& r) {
    return r.event == "command" || r.event == "timeout";
  });
  ASSERT_NE(last, all.rend()) << "the base got no command: " << output;
  EXPECT_TRUE(last->is_zero()) << last->event << " at " << last->t_s << " s\n" << output;
}

/// The "tracker: N samples" count of the run's summary.
long tracker_samples(const std::string& output) {
  const std::size_t at = output.find("tracker: ");
  return at == std::string::npos ? -1 : std::stol(output.substr(at + 9));
}

// ---- the head pose tracks --------------------------------------------------------------

TEST(OpenXrTracker, TheHeadPoseTracksAndNoPoseIsDropped) {
  const fs::path dir = fresh_dir("tracks");
  write_scene(dir);
  MhdRunProcess mhd = run(dir, 2.0);
  EXPECT_EQ(exit_status(mhd), 0) << mhd.output();
  // 100 Hz for about 2 s: every pose the headset gave was taken (none dropped by the
  // plugin, which would show as "(plugin: ...)", nor by the server).
  EXPECT_GT(tracker_samples(mhd.output()), 100) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), " samples, 0 dropped;")) << mhd.output();
  EXPECT_FALSE(has(mhd.output(), "(plugin:")) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "0 head stale")) << mhd.output();
  const auto locates = rows_of(dir / "headset.csv", "locate");
  EXPECT_EQ(static_cast<long>(locates.size()), tracker_samples(mhd.output())) << mhd.output();
  // The base, starting 0.8 m from where the planner wants it, is still driven after 1.2 s (the dual
  // of the stale head's stop below).
  const auto commands = rows_of(dir / "base.csv", "command");
  EXPECT_TRUE(std::any_of(commands.begin(), commands.end(),
                          [](const CommandLogRow& r) { return r.t_s > 1.2 && !r.is_zero(); }))
      << mhd.output();
  expect_session_closed(dir, mhd.output());
  expect_base_stopped(dir, mhd.output());
}

// ---- every end of a run ----------------------------------------------------------------

struct StopCase {
  int signal;
  int status;
  const char* name;
};

class OpenXrTrackerStop : public ::testing::TestWithParam<StopCase> {};

TEST_P(OpenXrTrackerStop, TheSignalEndsTheSessionAndStopsTheBase) {
  const StopCase c = GetParam();
  const fs::path dir = fresh_dir(std::string("stop_") + c.name);
  write_scene(dir);
  MhdRunProcess mhd = run(dir, 30.0);
  ASSERT_TRUE(mhd.wait_until_logged("headset.csv", 50, "locate")) << mhd.output();
  mhd.signal(c.signal);
  EXPECT_EQ(exit_status(mhd), c.status) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), std::string("stopped by ") + c.name)) << mhd.output();
  expect_session_closed(dir, mhd.output());
  expect_base_stopped(dir, mhd.output());
}

INSTANTIATE_TEST_SUITE_P(OpenXr, OpenXrTrackerStop,
                         ::testing::Values(StopCase{SIGINT, 0, "SIGINT"}, StopCase{SIGTERM, 0, "SIGTERM"},
                                           StopCase{SIGHUP, 128 + SIGHUP, "SIGHUP"}),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(OpenXrTracker, AnotherPluginCrashingLeavesTheBaseStopped) {
  const fs::path dir = fresh_dir("crash");
  write_scene(dir, "", "<plugin kind=\"display\" name=\"fi_crash\"><param name=\"crash\" value=\"abort\"/>"
                       "<param name=\"crash_on_call\" value=\"80\"/></plugin>");
  MhdRunProcess mhd = run(dir, 30.0);
  EXPECT_EQ(exit_status(mhd), kExitLastGasp) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "last gasp")) << mhd.output();
  EXPECT_FALSE(rows_of(dir / "headset.csv", "locate").empty()) << "the head was never located: " << mhd.output();
  expect_base_stopped(dir, mhd.output());
}

// ---- what is missing before the run ----------------------------------------------------

TEST(OpenXrTracker, AMissingRuntimeIsOneLineNamingItAndHowToInstallOne) {
  const fs::path dir = fresh_dir("missing");
  write_scene(dir);
  MhdRunProcess mhd = run(dir, 5.0, Fake{.installed = false});
  EXPECT_EQ(exit_status(mhd), 1) << mhd.output();
  const std::string out = mhd.output();
  EXPECT_TRUE(has(out, "no OpenXR runtime (xrCreateInstance: XR_ERROR_RUNTIME_")) << out;
  EXPECT_TRUE(has(out, "such as Monado")) << out;
  EXPECT_TRUE(has(out, "set XR_RUNTIME_JSON to its manifest (docs/hardware.md)\n")) << "the hint was cut: " << out;
  // One line in all: the loader's own error lines are quiet unless XR_LOADER_DEBUG asks.
  std::istringstream lines(out);
  int count = 0;
  for (std::string line; std::getline(lines, line);) count += line.empty() ? 0 : 1;
  EXPECT_EQ(count, 1) << out;
  EXPECT_FALSE(fs::exists(dir / "headset.csv"));
  for (const CommandLogRow& r : log_of(dir / "base.csv")) EXPECT_TRUE(r.is_zero()) << r.event;
}

TEST(OpenXrTracker, AMissingRuntimeWithXrLoaderDebugShowsTheLoadersOwnLines) {
  const fs::path dir = fresh_dir("missing_loader_debug");
  write_scene(dir);
  std::vector<std::string> argv{MHD_CLI, "run", (dir / "scene.xml").string(), "--duration", "5", "-q",
                                "--plugin-path", MHD_SIM_PLUGIN_DIR};
  MhdRunProcess mhd({.argv = argv,
                     .dir = dir,
                     .env = {{"XR_RUNTIME_JSON", (dir / "no_runtime_here/active_runtime.json").string()},
                             {"XR_LOADER_DEBUG", "error"}}});
  EXPECT_EQ(exit_status(mhd), 1) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "OpenXR-Loader")) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "no OpenXR runtime (xrCreateInstance: XR_ERROR_RUNTIME_")) << mhd.output();
}

TEST(OpenXrTracker, TheFakeRuntimeInstalledIsFound) {  // the dual of the missing runtime
  const fs::path dir = fresh_dir("found");
  write_scene(dir);
  MhdRunProcess mhd = run(dir, 0.5);
  EXPECT_EQ(exit_status(mhd), 0) << mhd.output();
  EXPECT_FALSE(has(mhd.output(), "no OpenXR runtime")) << mhd.output();
  EXPECT_EQ(rows_of(dir / "headset.csv", "create_instance").size(), 1u) << mhd.output();
}

TEST(OpenXrTracker, NoHeadsetIsNamedAndNothingMoves) {
  const fs::path dir = fresh_dir("no_system");
  write_scene(dir);
  MhdRunProcess mhd = run(dir, 5.0, Fake{.fault = "no_system"});
  EXPECT_EQ(exit_status(mhd), 1) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "xrGetSystem (head-mounted display): XR_ERROR_FORM_FACTOR_UNAVAILABLE"))
      << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "is the headset plugged in")) << mhd.output();
  // What was created was destroyed; no session.
  EXPECT_EQ(session_events(dir), (std::vector<std::string>{"create_instance", "get_system", "destroy_instance"}));
  for (const CommandLogRow& r : log_of(dir / "base.csv")) EXPECT_TRUE(r.is_zero()) << r.event;
}

// ---- faults mid-run --------------------------------------------------------------------

TEST(OpenXrTracker, ALostSessionEndsTheRunNamedWithTheBaseStopped) {
  const fs::path dir = fresh_dir("session_lost");
  write_scene(dir);
  MhdRunProcess mhd = run(dir, 30.0, Fake{.fault = "session_lost", .fault_after_s = 1.0});
  EXPECT_EQ(exit_status(mhd), kExitFault) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "the OpenXR session is being lost (XR_SESSION_STATE_LOSS_PENDING)")) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "base stopped")) << mhd.output();
  EXPECT_FALSE(rows_of(dir / "headset.csv", "locate").empty()) << mhd.output();
  expect_base_stopped(dir, mhd.output());
  // The lost session is still destroyed, and the instance with it.
  const std::vector<std::string> events = session_events(dir);
  ASSERT_GE(events.size(), 2u);
  EXPECT_EQ(events.back(), "destroy_instance") << joined(events);
}

TEST(OpenXrTracker, ARuntimeCallThatNeverReturnsEndsTheRunByTheWatchdog) {
  const fs::path dir = fresh_dir("hang");
  write_scene(dir);
  MhdRunProcess mhd = run(dir, 30.0, Fake{.fault = "hang", .fault_after_s = 1.0});
  EXPECT_EQ(exit_status(mhd), kExitFault) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "tracker_read has not returned")) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "safe state: zero force sent, base stopped")) << mhd.output();
  EXPECT_FALSE(rows_of(dir / "headset.csv", "locate").empty()) << "never tracked: " << mhd.output();
  expect_base_stopped(dir, mhd.output());
}

struct DroppedCase {
  const char* fault;
  const char* says;      ///< the plugin's counter in the run's summary
  bool bad_pose;         ///< the fake's log: flags set but the pose non-finite (else flags cleared)
};

class OpenXrTrackerDropped : public ::testing::TestWithParam<DroppedCase> {};

/// The host time of the headset's first bad pose: the two logs' clocks lined up at the
/// run's end (the base's stop and the session's end, both in the run's shutdown).
double host_time_of_first_bad_pose(const fs::path& dir, bool bad_pose) {
  const auto locates = rows_of(dir / "headset.csv", "locate");
  const auto bad = std::find_if(locates.begin(), locates.end(), [&](const CommandLogRow& r) {
    return bad_pose ? r.values[1] == 0.0 : r.values[0] == 0.0;
  });
  const auto ended = rows_of(dir / "headset.csv", "end_session");
  const auto stopped = rows_of(dir / "base.csv", "stop");
  if (bad == locates.end() || ended.empty() || stopped.empty()) return -1.0;
  return stopped.back().t_s - (ended.back().t_s - bad->t_s);
}

TEST_P(OpenXrTrackerDropped, BadPosesAreCountedNeverUsedAndTheBaseStops) {
  const DroppedCase c = GetParam();
  const fs::path dir = fresh_dir(std::string("dropped_") + c.fault);
  write_scene(dir);
  MhdRunProcess mhd = run(dir, 3.0, Fake{.fault = c.fault, .fault_after_s = 1.0});
  EXPECT_EQ(exit_status(mhd), 0) << mhd.output();
  // About 1 s of good poses, then about 2 s of bad ones, each dropped by the plugin.
  EXPECT_GT(tracker_samples(mhd.output()), 50) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), std::string("(plugin: ") + c.says + " ")) << mhd.output();
  EXPECT_FALSE(has(mhd.output(), "0 head stale")) << "the stale head never stopped the base: " << mhd.output();
  const double bad_at_s = host_time_of_first_bad_pose(dir, c.bad_pose);
  ASSERT_GT(bad_at_s, 0.0) << mhd.output();
  std::size_t after = 0;
  std::size_t moving_before = 0;
  for (const CommandLogRow& r : rows_of(dir / "base.csv", "command")) {
    if (r.t_s > bad_at_s - 0.3 && r.t_s <= bad_at_s && !r.is_zero()) ++moving_before;
    if (r.t_s <= bad_at_s + kStaleHeadStopsBaseWithin_s) continue;
    ++after;
    EXPECT_TRUE(r.is_zero()) << "twist " << r.values[0] << " " << r.values[1] << " " << r.values[2] << " at "
                             << r.t_s - bad_at_s << " s after the head went bad";
  }
  EXPECT_GT(after, 5u) << "the base got no command after the head went bad: " << mhd.output();
  EXPECT_GT(moving_before, 0u) << "the base was not moving when the head went bad: " << mhd.output();
  expect_session_closed(dir, mhd.output());
}

INSTANTIATE_TEST_SUITE_P(OpenXr, OpenXrTrackerDropped,
                         ::testing::Values(DroppedCase{"tracking_lost", "not_tracked", false},
                                           DroppedCase{"nan_pose", "non_finite", true}),
                         [](const auto& param_info) { return std::string(param_info.param.fault); });

// ---- mhd validate ----------------------------------------------------------------------

struct ParamCase {
  const char* name;
  const char* params;
  const char* says;
};

class OpenXrTrackerValidate : public ::testing::TestWithParam<ParamCase> {};

TEST_P(OpenXrTrackerValidate, ABadParameterIsRefusedWithItsLine) {
  const fs::path dir = fresh_dir(std::string("validate_") + GetParam().name);
  write_scene(dir, GetParam().params);
  MhdRunProcess mhd = run(dir, 0.0, Fake{.installed = false}, "validate");
  EXPECT_NE(exit_status(mhd), 0) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "scene.xml:16: error: plugin 'openxr': ")) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), GetParam().says)) << mhd.output();
}

INSTANTIATE_TEST_SUITE_P(
    OpenXr, OpenXrTrackerValidate,
    ::testing::Values(ParamCase{"sensor_99", "<param name=\"head_sensor_id\" value=\"99\"/>", "head_sensor_id"},
                      ParamCase{"moon", "<param name=\"reference_space\" value=\"moon\"/>", "reference_space"},
                      ParamCase{"far", "<param name=\"max_position_m\" value=\"0\"/>", "max_position_m"},
                      ParamCase{"rate", "<param name=\"rate_hz\" value=\"nan\"/>", "rate_hz"},
                      ParamCase{"unknown", "<param name=\"fov_deg\" value=\"90\"/>", "fov_deg"}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(OpenXrTracker, GoodParametersAreAcceptedWithoutTheRuntime) {
  const fs::path dir = fresh_dir("validate_good");
  write_scene(dir, "<param name=\"reference_space\" value=\"local\"/><param name=\"head_sensor_id\" value=\"1\"/>"
                   "<param name=\"max_position_m\" value=\"5\"/><param name=\"rate_hz\" value=\"90\"/>");
  MhdRunProcess mhd = run(dir, 0.0, Fake{.installed = false}, "validate");
  EXPECT_EQ(exit_status(mhd), 0) << mhd.output();
}

}  // namespace
