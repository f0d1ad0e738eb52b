// The intersense tracker driven by `mhd run` through the real dlopen path against a fake
// libisense (fakes/fake_isense.cpp: a simulated IS-900 on the POMHI rig's ceiling), judged
// from the hardware's side: what the simulated base and device received last (base.csv,
// device.csv) and the fake's log of what the tracker was asked (isense.csv).
#include "hardware_run.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
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

fs::path fresh_dir(const std::string& name) { return mhd::test::scratch_dir("intersense", name); }

/// tests/data/hardware/intersense_mobile.xml in `dir`, with tracker parameters and extra
/// plugins put in.
void write_scene(const fs::path& dir, const std::string& tracker_params = "", const std::string& extra = "") {
  std::ofstream(dir / "scene.xml") << mhd::test::fill_scene_template(
      fs::path(MHD_SOURCE_DIR) / "tests/data/hardware/intersense_mobile.xml",
      {{"<!--TRACKER-->", tracker_params}, {"<!--EXTRA-->", extra}});
}

/// The fake's configuration (fakes/fake_hardware.h).
struct Fake {
  std::string fault = "none";
  double fault_after_s = 1.0;
  bool installed = true;  ///< the library on the loader's path
};

/// `mhd <verb> dir/scene.xml` with the fake as the installed runtime.
MhdRunProcess run(const fs::path& dir, double duration_s, const Fake& fake = {}, const std::string& verb = "run") {
  const fs::path nowhere = dir / "no_runtime_here";
  fs::create_directories(nowhere);
  std::vector<std::string> argv{MHD_CLI, verb, (dir / "scene.xml").string()};
  if (verb == "run") {
    for (const char* a : {"--duration", "", "-q", "--plugin-path", MHD_SIM_PLUGIN_DIR, "--plugin-path",
                          MHD_FAULT_INJECTION_PLUGIN_DIR}) {
      argv.emplace_back(a);
    }
    argv[4] = std::to_string(duration_s);
  }
  return MhdRunProcess({.argv = argv,
                        .dir = dir,
                        .env = {{"LD_LIBRARY_PATH", fake.installed ? MHD_FAKE_ISENSE_DIR : nowhere.string()},
                                {"MHD_FAKE_LOG", (dir / "isense.csv").string()},
                                {"MHD_FAKE_FAULT", fake.fault},
                                {"MHD_FAKE_FAULT_AFTER_S", std::to_string(fake.fault_after_s)}}});
}

/// The hardware's view of a safe end: the base's and the device's last commands are zero.
void expect_base_and_device_left_still(const fs::path& dir, const std::string& output) {
  expect_last_command_zero(dir / "base.csv", output);
  expect_last_command_zero(dir / "device.csv", output);
}

double largest_force_N(const fs::path& dir) {
  double largest = 0.0;
  for (const CommandLogRow& r : rows_of(dir / "device.csv", "command")) {
    largest = std::max(largest, std::hypot(r.values[0], r.values[1], r.values[2]));
  }
  return largest;
}

// ---- tracking ---------------------------------------------------------------------------

TEST(InterSense, TheBaseStationIsMhdsBaseEstimateAndTheTrackerIsClosedAtTheEnd) {
  const fs::path dir = fresh_dir("tracks");
  write_scene(dir);
  MhdRunProcess mhd = run(dir, 2.0);
  EXPECT_EQ(exit_status(mhd), 0) << mhd.output();
  // The simulated base starts at x -0.3 m; the estimate is where the IS-900 says it is.
  double x_m = 0.0;
  double z_m = 0.0;
  const std::size_t at = mhd.output().find("ends at (");
  ASSERT_NE(at, std::string::npos) << mhd.output();
  ASSERT_EQ(std::sscanf(mhd.output().c_str() + at, "ends at (%lf, %lf) m", &x_m, &z_m), 2) << mhd.output();
  EXPECT_NEAR(x_m, 0.0, 1e-3) << mhd.output();
  EXPECT_NEAR(z_m, 0.0, 1e-3) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), " samples, 0 dropped;")) << mhd.output();
  EXPECT_GT(largest_force_N(dir), 0.5) << "no contact: " << mhd.output();
  EXPECT_EQ(stale_ticks(mhd.output()), 0) << mhd.output();
  // Both stations that are on were asked for quaternions with time stamps; no other.
  const auto configured = rows_of(dir / "isense.csv", "configure");
  ASSERT_EQ(configured.size(), 2u);
  for (std::size_t i = 0; i < configured.size(); ++i) {
    EXPECT_EQ(configured[i].values[0], static_cast<double>(i + 1));
    EXPECT_EQ(configured[i].values[1], 2.0);  // ISD_QUATERNION
    EXPECT_EQ(configured[i].values[2], 1.0);
  }
  EXPECT_GT(rows_of(dir / "isense.csv", "record").size(), 200u);  // 180 Hz for 2 s
  const auto all = log_of(dir / "isense.csv");
  ASSERT_FALSE(all.empty());
  EXPECT_EQ(all.back().event, "close");
  expect_base_and_device_left_still(dir, mhd.output());
}

// ---- every end of a run -------------------------------------------------------------------

struct StopCase {
  int signal;
  int status;
  const char* name;
};

class InterSenseStop : public ::testing::TestWithParam<StopCase> {};

TEST_P(InterSenseStop, TheSignalClosesTheTrackerAndLeavesBaseAndDeviceStill) {
  const StopCase c = GetParam();
  const fs::path dir = fresh_dir(std::string("stop_") + c.name);
  write_scene(dir);
  MhdRunProcess mhd = run(dir, 30.0);
  ASSERT_TRUE(mhd.wait_until_logged("isense.csv", 200, "record")) << mhd.output();
  mhd.signal(c.signal);
  EXPECT_EQ(exit_status(mhd), c.status) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), std::string("stopped by ") + c.name)) << mhd.output();
  const auto all = log_of(dir / "isense.csv");
  ASSERT_FALSE(all.empty());
  EXPECT_EQ(all.back().event, "close");
  expect_base_and_device_left_still(dir, mhd.output());
}

INSTANTIATE_TEST_SUITE_P(InterSense, InterSenseStop,
                         ::testing::Values(StopCase{SIGINT, 0, "SIGINT"}, StopCase{SIGTERM, 0, "SIGTERM"},
                                           StopCase{SIGHUP, 128 + SIGHUP, "SIGHUP"}),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(InterSense, AnotherPluginCrashingLeavesBaseAndDeviceStill) {
  const fs::path dir = fresh_dir("crash");
  write_scene(dir, "",
              "<plugin kind=\"display\" name=\"fi_crash\"><param name=\"crash\" value=\"abort\"/>"
              "<param name=\"crash_on_call\" value=\"300\"/></plugin>");
  MhdRunProcess mhd = run(dir, 30.0);
  EXPECT_EQ(exit_status(mhd), kExitLastGasp) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "last gasp: zero torque sent")) << mhd.output();
  EXPECT_GT(rows_of(dir / "isense.csv", "record").size(), 10u) << "not tracking before the crash";
  expect_base_and_device_left_still(dir, mhd.output());
}

TEST(InterSense, AReadThatNeverReturnsEndsTheRunByTheWatchdog) {
  const fs::path dir = fresh_dir("hang");
  write_scene(dir);
  MhdRunProcess mhd = run(dir, 30.0, Fake{.fault = "hang"});
  EXPECT_EQ(exit_status(mhd), kExitFault) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "tracker_read has not returned")) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "safe state: zero force sent")) << mhd.output();
  expect_base_and_device_left_still(dir, mhd.output());
}

TEST(InterSense, ALostLinkEndsTheRunWithItsCause) {
  const fs::path dir = fresh_dir("link_lost");
  write_scene(dir);
  MhdRunProcess mhd = run(dir, 30.0, Fake{.fault = "comm_error"});
  EXPECT_EQ(exit_status(mhd), kExitFault) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "s (link_timeout_s): the link to the IS-900 is lost")) << mhd.output();
  EXPECT_FALSE(rows_of(dir / "isense.csv", "read_failed").empty());
  expect_base_and_device_left_still(dir, mhd.output());
}

// ---- bad data mid-run: dropped and counted, and the run fades safe ---------------------

struct BadDataCase {
  const char* fault;
  const char* counted_as;
};

class InterSenseBadData : public ::testing::TestWithParam<BadDataCase> {};

TEST_P(InterSenseBadData, IsNeverUsedTheForceFadesAndTheBaseStops) {
  const BadDataCase c = GetParam();
  const fs::path dir = fresh_dir(c.fault);
  write_scene(dir);
  MhdRunProcess mhd = run(dir, 3.0, Fake{.fault = c.fault, .fault_after_s = 1.0});
  EXPECT_EQ(exit_status(mhd), 0) << mhd.output();
  const std::string out = mhd.output();
  EXPECT_TRUE(has(out, std::string("(plugin: ") + c.counted_as + " ")) << out;
  EXPECT_GT(stale_ticks(out), 500) << "the data were not seen as stale: " << out;
  EXPECT_GT(largest_force_N(dir), 0.5) << "no contact before the fault: " << out;
  // The last second (the fault struck 2 s before the end): no force, no base motion.
  for (const char* file : {"device.csv", "base.csv"}) {
    const auto commands = rows_of(dir / file, "command");
    ASSERT_FALSE(commands.empty()) << file;
    for (const CommandLogRow& r : commands) {
      if (r.t_s > commands.back().t_s - 1.0) {
        EXPECT_TRUE(r.is_zero()) << file << " at " << r.t_s << " s\n" << out;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(InterSense, InterSenseBadData,
                         ::testing::Values(BadDataCase{"nan_position", "non_finite"},
                                           BadDataCase{"frozen_timestamp", "frozen_time"}),
                         [](const auto& param_info) { return std::string(param_info.param.fault); });

TEST(InterSense, AfterADropoutTrackingForceAndTheBaseComeBack) {
  const fs::path dir = fresh_dir("dropout");
  write_scene(dir);
  // The stations are lost from 1 s to 2 s of a 4 s run.
  MhdRunProcess mhd = run(dir, 4.0, Fake{.fault = "dropout", .fault_after_s = 1.0});
  EXPECT_EQ(exit_status(mhd), 0) << mhd.output();
  const std::string out = mhd.output();
  EXPECT_TRUE(has(out, "(plugin: not_tracking ")) << out;
  // Faded while lost, and pressing again in the run's last 1.5 s, when the hand presses.
  EXPECT_GT(stale_ticks(out), 500) << out;
  EXPECT_LT(stale_ticks(out), 1500) << out;
  const auto commands = rows_of(dir / "device.csv", "command");
  ASSERT_FALSE(commands.empty());
  double late_force_N = 0.0;
  for (const CommandLogRow& r : commands) {
    if (r.t_s > commands.back().t_s - 1.5) {
      late_force_N = std::max(late_force_N, std::hypot(r.values[0], r.values[1], r.values[2]));
    }
  }
  EXPECT_GT(late_force_N, 0.5) << "the force did not come back: " << out;
}

// ---- what is missing or wrong before the run ----------------------------------------------

TEST(InterSense, AMissingRuntimeIsOneLineNamingTheLibrary) {
  const fs::path dir = fresh_dir("missing");
  write_scene(dir);
  MhdRunProcess mhd = run(dir, 5.0, Fake{.installed = false});
  EXPECT_EQ(exit_status(mhd), 1) << mhd.output();
  const std::string out = mhd.output();
  EXPECT_TRUE(has(out, "cannot load the InterSense SDK 'libisense.so'")) << out;
  EXPECT_TRUE(has(out, "install the InterSense SDK for Linux")) << out;
  std::istringstream lines(out);
  int naming = 0;
  for (std::string line; std::getline(lines, line);) naming += has(line, "libisense.so") ? 1 : 0;
  EXPECT_EQ(naming, 1) << out;
  for (const char* file : {"base.csv", "device.csv"}) {
    for (const CommandLogRow& r : rows_of(dir / file, "command")) {
      EXPECT_TRUE(r.is_zero()) << file;
    }
  }
}

TEST(InterSense, NoTrackerOnAnyPortIsNamed) {
  const fs::path dir = fresh_dir("unplugged");
  write_scene(dir);
  MhdRunProcess mhd = run(dir, 5.0, Fake{.fault = "unplugged"});
  EXPECT_EQ(exit_status(mhd), 1) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "ISD_OpenTracker found no InterSense tracker on any port")) << mhd.output();
}

TEST(InterSense, ALibraryOfAnotherLayoutIsRefusedAndTheTrackerClosed) {
  const fs::path dir = fresh_dir("old_library");
  write_scene(dir);
  MhdRunProcess mhd = run(dir, 5.0, Fake{.fault = "old_library"});
  EXPECT_EQ(exit_status(mhd), 1) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "the InterSense library is version 3.58: this plugin knows the data layout of SDK 4.x"))
      << mhd.output();
  EXPECT_TRUE(rows_of(dir / "isense.csv", "configure").empty());
  EXPECT_EQ(rows_of(dir / "isense.csv", "close").size(), 1u);
}

TEST(InterSense, ATrackerThatAnswersNothingIsRefusedAndClosed) {
  const fs::path dir = fresh_dir("error_every_call");
  write_scene(dir);
  MhdRunProcess mhd = run(dir, 5.0, Fake{.fault = "error_every_call"});
  EXPECT_EQ(exit_status(mhd), 1) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "ISD_GetCommInfo failed")) << mhd.output();
  EXPECT_EQ(rows_of(dir / "isense.csv", "close").size(), 1u);
}

// ---- mhd validate: every parameter against its range, without the runtime -------------

struct ParamCase {
  const char* params;
  const char* says;
};

class InterSenseValidate : public ::testing::TestWithParam<ParamCase> {};

TEST_P(InterSenseValidate, ABadParameterIsRefusedWithItsLine) {
  const fs::path dir = fresh_dir("validate");
  write_scene(dir, GetParam().params);
  MhdRunProcess mhd = run(dir, 0.0, Fake{.installed = false}, "validate");
  EXPECT_NE(exit_status(mhd), 0) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "scene.xml:18: error: plugin 'intersense': ")) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), GetParam().says)) << mhd.output();
}

INSTANTIATE_TEST_SUITE_P(
    InterSense, InterSenseValidate,
    ::testing::Values(ParamCase{"<param name=\"port\" value=\"-1\"/>", "port"},
                      ParamCase{"<param name=\"port\" value=\"65\"/>", "port"},
                      ParamCase{"<param name=\"max_position_m\" value=\"0\"/>", "max_position_m"},
                      ParamCase{"<param name=\"max_position_m\" value=\"inf\"/>", "max_position_m"},
                      ParamCase{"<param name=\"link_timeout_s\" value=\"nan\"/>", "link_timeout_s"},
                      ParamCase{"<param name=\"link_timeout_s\" value=\"1e-9\"/>", "link_timeout_s"},
                      ParamCase{"<param name=\"baud\" value=\"9600\"/>", "baud"}),
    [](const auto& param_info) { return "case" + std::to_string(param_info.index); });

TEST(InterSense, GoodParametersAreAcceptedWithoutTheRuntime) {
  const fs::path dir = fresh_dir("validate_good");
  write_scene(dir, "<param name=\"port\" value=\"3\"/><param name=\"max_position_m\" value=\"5\"/>"
                   "<param name=\"link_timeout_s\" value=\"0.2\"/>");
  MhdRunProcess mhd = run(dir, 0.0, Fake{.installed = false}, "validate");
  EXPECT_EQ(exit_status(mhd), 0) << mhd.output();
}

// ---- mhd devices --trackers ---------------------------------------------------------------

/// `mhd devices` with `flags`, the fake installed or not; its output.
std::string devices_output(const fs::path& dir, const std::vector<std::string>& flags, bool installed) {
  std::vector<std::string> argv{MHD_CLI, "devices", "--plugin-path", MHD_SIM_PLUGIN_DIR};
  argv.insert(argv.end(), flags.begin(), flags.end());
  MhdRunProcess mhd({.argv = argv,
                     .dir = dir,
                     .env = {{"LD_LIBRARY_PATH", installed ? MHD_FAKE_ISENSE_DIR : dir.string()},
                             {"MHD_FAKE_LOG", (dir / "isense.csv").string()}}});
  EXPECT_EQ(exit_status(mhd), 0) << mhd.output();
  return mhd.output();
}

TEST(InterSense, MhdDevicesWithTrackersSaysTheTrackerAnswersAndReleasesIt) {
  const fs::path dir = fresh_dir("devices");
  const std::string out = devices_output(dir, {"--trackers"}, true);
  EXPECT_TRUE(has(out, "libmhd_intersense.so\n  found: it opened with its default parameters\n"
                       "  <plugin kind=\"tracker\" name=\"intersense\"/>"))
      << out;
  EXPECT_EQ(rows_of(dir / "isense.csv", "open").size(), 1u);
  EXPECT_EQ(rows_of(dir / "isense.csv", "close").size(), 1u);
  EXPECT_TRUE(rows_of(dir / "isense.csv", "record").empty()) << "asked, never read";
}

TEST(InterSense, MhdDevicesNamesAMissingRuntimeAndAsksTrackersOnlyWhenTold) {
  const fs::path dir = fresh_dir("devices_missing");
  const std::string out = devices_output(dir, {"--trackers"}, false);
  EXPECT_TRUE(has(out, "  no tracker: open failed: cannot load the InterSense SDK 'libisense.so'")) << out;
  EXPECT_FALSE(has(devices_output(dir, {}, true), "intersense")) << "asked without --trackers";
}

}  // namespace
