// The device backends for real hardware (openhaptics, forcedimension) driven by `mhd run`
// through the real dlopen path, each against a fake of its vendor library (fakes/), judged
// from the hardware's side: the fake's log of every force its motors gave, force output
// switched on and off, and the device's own watchdog.
#include "hardware_run.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;
using mhd::test::CommandLogRow;
using mhd::test::MhdRunProcess;
using mhd::test::read_command_log;

using mhd::test::hardware::exit_status;
using mhd::test::hardware::kExitFault;
using mhd::test::hardware::kExitLastGasp;

/// A backend and its fake.
struct Backend {
  const char* plugin;
  const char* fake_dir;      ///< where the fake library lies, under the vendor's file name
  const char* library;       ///< the plugin's default library name
  const char* runtime;       ///< in the missing-runtime message
  const char* install;       ///< ditto: how to install it
  const char* frame_rpy_deg; ///< turns the vendor's up into the world's
  const char* max_force_N;   ///< the fake device's nominal maximum (the plugin's, for DHD)
  const char* params;        ///< the device's parameters in every scene
  const char* comm_error;    ///< what a lost link is called
  const char* unplugged;     ///< what an absent device is called
  const char* mobile_model;  ///< the fake device on the mobile rig: room for the planner
  const char* mobile_workspace_mm;
  int frozen_status;         ///< a frozen process: 0 when the run rides through it
  const char* frozen_says;   ///< and what it says when it does not
  const char* force_limit;   ///< the parameter that limits force ("" : the fake's maximum instead)
};

const Backend kOpenHaptics{
    .plugin = "openhaptics",
    .fake_dir = MHD_FAKE_HD_DIR,
    .library = "libHD.so",
    .runtime = "the OpenHaptics runtime",
    .install = "install OpenHaptics for Linux",
    .frame_rpy_deg = "0 0 0",  // HDAPI: y up
    .max_force_N = "3.3",
    .params = "",
    .comm_error = "device fault in the servo loop: HD_COMM_ERROR",
    .unplugged = "HD_COMM_ERROR (0x0302, device code 3): Communication error; communication with the device failed: "
                 "is it plugged in",
    .mobile_model = "",
    .mobile_workspace_mm = "-190 -133 -95 190 133 95",  // a PHANToM Premium 1.5
    .frozen_status = 0,
    .frozen_says = "stopped by SIGINT",
    .force_limit = "",
};

const Backend kForceDimension{
    .plugin = "forcedimension",
    .fake_dir = MHD_FAKE_DHD_DIR,
    .library = "libdhd.so",
    .runtime = "the Force Dimension SDK",
    .install = "install the Force Dimension SDK",
    .frame_rpy_deg = "-90 0 0",  // the SDK: z up
    .max_force_N = "12",         // an omega.3
    // The firmware watchdog's longest: a loaded test machine may hold a tick 10 ms.
    .params = "<param name=\"command_timeout_s\" value=\"0.03\"/>",
    // Named at whichever call meets the lost link first (a read or dhdSetForce).
    .comm_error = "DHD_ERROR_COM (2): communication error between the host and the device; communication with the "
                  "device failed",
    .unplugged = "dhdOpen: DHD_ERROR_NO_DEVICE_FOUND (5): error; no device found",
    .mobile_model = "delta3",
    .mobile_workspace_mm = "",
    .frozen_status = kExitFault,
    .frozen_says = "the device turned its forces off: its firmware watchdog fired",
    .force_limit = "force_limit_N",
};

std::string name_of(const Backend& b) { return b.plugin; }

fs::path fresh_dir(const Backend& b, const std::string& name) {
  return mhd::test::scratch_dir("vendor_device", name_of(b) + "_" + name);
}

/// tests/data/hardware/<source> in `dir` as scene.xml for backend `b`, each (placeholder,
/// text) put in; `params` joins the backend's own device parameters.
void write_scene(const fs::path& dir, const Backend& b, const std::string& source,
                 std::vector<std::pair<std::string, std::string>> fills = {}, const std::string& params = "") {
  fills.emplace_back("name=\"openhaptics\"", std::string("name=\"") + b.plugin + "\"");
  if (source == "vendor_desk.xml") fills.emplace_back("rpy_deg=\"0 0 0\"", std::string("rpy_deg=\"") + b.frame_rpy_deg + "\"");
  fills.emplace_back("<!--DEVICE-->", b.params + params);
  std::ofstream(dir / "scene.xml") << mhd::test::fill_scene_template(
      fs::path(MHD_SOURCE_DIR) / "tests/data/hardware" / source, fills);
}

/// The fake's configuration (fakes/fake_hardware.h).
struct Fake {
  std::string fault = "none";
  double fault_after_s = 1.2;
  std::string max_force_N = "";  ///< "" : the backend's
  std::string workspace_mm = "-80 -60 -35 80 60 35";
  std::string model = "omega3";
  bool installed = true;  ///< the library on the loader's path
};

Fake mobile(const Backend& b) {
  Fake f;
  if (*b.mobile_workspace_mm != '\0') f.workspace_mm = b.mobile_workspace_mm;
  if (*b.mobile_model != '\0') f.model = b.mobile_model;
  return f;
}

/// `mhd run` on dir/scene.xml with the fake as the installed runtime.
MhdRunProcess run(const Backend& b, const fs::path& dir, double duration_s, const Fake& fake = {}) {
  const fs::path nowhere = dir / "no_runtime_here";
  fs::create_directories(nowhere);
  return MhdRunProcess({.argv = {MHD_CLI, "run", (dir / "scene.xml").string(), "--duration", std::to_string(duration_s),
                                 "-q", "--plugin-path", MHD_SIM_PLUGIN_DIR, "--plugin-path",
                                 MHD_FAULT_INJECTION_PLUGIN_DIR},
                        .dir = dir,
                        .env = {{"LD_LIBRARY_PATH", fake.installed ? b.fake_dir : nowhere.string()},
                                {"MHD_FAKE_LOG", (dir / "hardware.csv").string()},
                                {"MHD_FAKE_FAULT", fake.fault},
                                {"MHD_FAKE_FAULT_AFTER_S", std::to_string(fake.fault_after_s)},
                                {"MHD_FAKE_MAX_FORCE_N", fake.max_force_N.empty() ? b.max_force_N : fake.max_force_N},
                                {"MHD_FAKE_WORKSPACE_MM", fake.workspace_mm},
                                {"MHD_FAKE_MODEL", fake.model}}});
}

std::vector<CommandLogRow> log_of(const fs::path& dir) {
  return fs::exists(dir / "hardware.csv") ? read_command_log(dir / "hardware.csv") : std::vector<CommandLogRow>{};
}

std::vector<CommandLogRow> rows_of(const fs::path& dir, const std::string& event) {
  std::vector<CommandLogRow> out;
  for (const CommandLogRow& r : log_of(dir)) {
    if (r.event == event) out.push_back(r);
  }
  return out;
}

double magnitude(const CommandLogRow& r) {
  return std::sqrt(r.values[0] * r.values[0] + r.values[1] * r.values[1] + r.values[2] * r.values[2]);
}

double largest_force(const fs::path& dir) {
  double largest = 0.0;
  for (const CommandLogRow& r : rows_of(dir, "force")) largest = std::max(largest, magnitude(r));
  return largest;
}

/// The last force the motors gave: their last force row, or the watchdog's zero after it.
void expect_last_force_zero(const fs::path& dir, const std::string& output) {
  const auto all = log_of(dir);
  const auto last = std::find_if(all.rbegin(), all.rend(), [](const CommandLogRow& r) {
    return r.event == "force" || r.event == "timeout";
  });
  ASSERT_NE(last, all.rend()) << output;
  EXPECT_TRUE(last->is_zero()) << last->event << " " << magnitude(*last) << " N\n" << output;
}

/// The motors' view of a clean end: they pushed (contact), their last force is zero, force
/// output went off after the last non-zero force, and no force above the device's maximum
/// ever reached the driver.
void expect_clean_hardware_end(const fs::path& dir, const std::string& output, double contact_N = 0.5) {
  const auto all = log_of(dir);
  EXPECT_GT(largest_force(dir), contact_N) << "no contact: " << output;
  expect_last_force_zero(dir, output);
  const auto last_push = std::find_if(all.rbegin(), all.rend(), [](const CommandLogRow& r) {
    return r.event == "force" && !r.is_zero();
  });
  const auto off = std::find_if(all.rbegin(), all.rend(), [](const CommandLogRow& r) { return r.event == "force_off"; });
  ASSERT_NE(off, all.rend()) << "force output never switched off: " << output;
  EXPECT_LT(off, last_push) << "force output went off before the last push";
  EXPECT_TRUE(rows_of(dir, "over_limit").empty()) << output;
}

/// No non-zero force reached the motors more than `after_s` after force output went on.
void expect_no_force_after(const fs::path& dir, double after_s) {
  const auto on = rows_of(dir, "force_on");
  ASSERT_FALSE(on.empty());
  for (const CommandLogRow& r : rows_of(dir, "force")) {
    if (r.t_s > on.front().t_s + after_s) {
      EXPECT_TRUE(r.is_zero()) << "force " << magnitude(r) << " N at " << r.t_s - on.front().t_s << " s";
    }
  }
}

class VendorDevice : public ::testing::TestWithParam<const Backend*> {
 protected:
  const Backend& b() const { return *GetParam(); }
};

const auto kBackends = ::testing::Values(&kOpenHaptics, &kForceDimension);
const auto kBackendName = [](const auto& param_info) { return name_of(*param_info.param); };

// ---- every end of a run ---------------------------------------------------------------

struct StopCase {
  int signal;
  int status;
  const char* name;
};

class VendorDeviceStop : public ::testing::TestWithParam<std::tuple<const Backend*, StopCase>> {};

TEST_P(VendorDeviceStop, ContactThenTheSignalLeavesZeroForceWithOutputOff) {
  const Backend& b = *std::get<0>(GetParam());
  const StopCase c = std::get<1>(GetParam());
  const fs::path dir = fresh_dir(b, c.name);
  write_scene(dir, b, "vendor_desk.xml");
  MhdRunProcess mhd = run(b, dir, 30.0);
  ASSERT_TRUE(mhd.wait_until_logged("hardware.csv", 1500, "force")) << mhd.output();  // pressed into the box
  mhd.signal(c.signal);
  EXPECT_EQ(exit_status(mhd), c.status) << mhd.output();
  EXPECT_NE(mhd.output().find(std::string("stopped by ") + c.name), std::string::npos) << mhd.output();
  expect_clean_hardware_end(dir, mhd.output());
}

INSTANTIATE_TEST_SUITE_P(Hardware, VendorDeviceStop,
                         ::testing::Combine(kBackends, ::testing::Values(StopCase{SIGINT, 0, "SIGINT"},
                                                                         StopCase{SIGTERM, 0, "SIGTERM"},
                                                                         StopCase{SIGHUP, 128 + SIGHUP, "SIGHUP"})),
                         [](const auto& param_info) {
                           return name_of(*std::get<0>(param_info.param)) + "_" + std::get<1>(param_info.param).name;
                         });

TEST_P(VendorDevice, ARunToItsDurationTouchesTheBoxAndEndsClean) {
  const fs::path dir = fresh_dir(b(), "duration");
  write_scene(dir, b(), "vendor_desk.xml");
  MhdRunProcess mhd = run(b(), dir, 2.0);
  EXPECT_EQ(exit_status(mhd), 0) << mhd.output();
  // The fake's hand went 30 mm into the box: the proxy held it with more than 1 N.
  expect_clean_hardware_end(dir, mhd.output(), 1.0);
}

TEST_P(VendorDevice, AnotherPluginCrashingLeavesZeroForce) {
  const fs::path dir = fresh_dir(b(), "crash");
  write_scene(dir, b(), "vendor_desk.xml",
              {{"<!--EXTRA-->", "<plugin kind=\"display\" name=\"fi_crash\"><param name=\"crash\" value=\"abort\"/>"
                                "<param name=\"crash_on_call\" value=\"80\"/></plugin>"}});
  MhdRunProcess mhd = run(b(), dir, 30.0);
  EXPECT_EQ(exit_status(mhd), kExitLastGasp) << mhd.output();
  EXPECT_NE(mhd.output().find("last gasp: zero torque sent"), std::string::npos) << mhd.output();
  EXPECT_GT(largest_force(dir), 0.5) << "no contact before the crash: " << mhd.output();
  expect_last_force_zero(dir, mhd.output());
}

TEST_P(VendorDevice, AHungTrackerCallEndsTheRunByTheWatchdogWithZeroForce) {
  const fs::path dir = fresh_dir(b(), "watchdog");
  write_scene(dir, b(), "vendor_mobile.xml",
              {{"<!--TRACKER_FAULT-->", "<param name=\"fault\" value=\"hang\"/><param name=\"fault_call\" "
                                        "value=\"tracker_read\"/><param name=\"fault_after_s\" value=\"1\"/>"}});
  MhdRunProcess mhd = run(b(), dir, 30.0, mobile(b()));
  EXPECT_EQ(exit_status(mhd, std::chrono::seconds(30)), kExitFault) << mhd.output();
  EXPECT_NE(mhd.output().find("tracker_read has not returned"), std::string::npos) << mhd.output();
  EXPECT_NE(mhd.output().find("safe state: zero force sent"), std::string::npos) << mhd.output();
  // The stuck thread keeps every plugin loaded and open (nothing may unload code a thread
  // is in), so force output may stay on until the process ends; the motors give zero.
  ASSERT_FALSE(rows_of(dir, "force").empty()) << mhd.output();
  expect_last_force_zero(dir, mhd.output());
}

TEST_P(VendorDevice, AFrozenProcessLetsTheDevicesOwnWatchdogZeroTheForce) {
  const fs::path dir = fresh_dir(b(), "frozen");
  write_scene(dir, b(), "vendor_desk.xml");
  MhdRunProcess mhd = run(b(), dir, 30.0);
  ASSERT_TRUE(mhd.wait_until_logged("hardware.csv", 1000, "force")) << mhd.output();
  mhd.signal(SIGSTOP);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  mhd.signal(SIGCONT);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  mhd.signal(SIGINT);
  // The run rides through, or ends by the device's own cause; or, when the freeze caught a
  // device call under way, the host's call watchdog counts the freeze and ends the run.
  const int status = exit_status(mhd);
  const bool as_the_device_says =
      status == b().frozen_status && mhd.output().find(b().frozen_says) != std::string::npos;
  const bool by_the_call_watchdog =
      status == kExitFault && mhd.output().find("has not returned after") != std::string::npos;
  EXPECT_TRUE(as_the_device_says || by_the_call_watchdog) << "status " << status << "\n" << mhd.output();
  const auto all = log_of(dir);
  // The freeze's timeout: a row whose neighbours are more than 0.3 s apart.
  const auto timeout = std::find_if(all.begin(), all.end(), [&](const CommandLogRow& r) {
    const auto i = static_cast<std::size_t>(&r - all.data());
    return r.event == "timeout" && i > 0 && i + 1 < all.size() && all[i + 1].t_s - all[i - 1].t_s > 0.3;
  });
  ASSERT_NE(timeout, all.end()) << "the device's watchdog never fired: " << mhd.output();
  EXPECT_TRUE(timeout->is_zero());
  expect_clean_hardware_end(dir, mhd.output());
}

// ---- what is missing or broken before the run ----------------------------------------

TEST_P(VendorDevice, AMissingRuntimeIsOneLineNamingTheLibraryAndNothingMoves) {
  const fs::path dir = fresh_dir(b(), "missing");
  write_scene(dir, b(), "vendor_mobile.xml");
  Fake missing = mobile(b());
  missing.installed = false;
  MhdRunProcess mhd = run(b(), dir, 5.0, missing);
  EXPECT_EQ(exit_status(mhd), 1) << mhd.output();
  const std::string out = mhd.output();
  EXPECT_NE(out.find(std::string("cannot load ") + b().runtime + " '" + b().library + "'"), std::string::npos) << out;
  EXPECT_NE(out.find(b().install), std::string::npos) << out;
  EXPECT_NE(out.find("(docs/hardware.md)\n"), std::string::npos) << "the hint was cut: " << out;
  std::istringstream lines(out);
  int naming = 0;
  for (std::string line; std::getline(lines, line);) naming += line.find(b().library) != std::string::npos ? 1 : 0;
  EXPECT_EQ(naming, 1) << out;
  EXPECT_TRUE(log_of(dir).empty());
  // The base was never driven.
  if (fs::exists(dir / "base.csv")) {
    for (const CommandLogRow& r : read_command_log(dir / "base.csv")) EXPECT_TRUE(r.is_zero()) << r.event;
  }
}

TEST_P(VendorDevice, AnUnpluggedDeviceIsNamedAndNoForceIsGiven) {
  const fs::path dir = fresh_dir(b(), "unplugged");
  write_scene(dir, b(), "vendor_desk.xml");
  MhdRunProcess mhd = run(b(), dir, 5.0, Fake{.fault = "unplugged"});
  EXPECT_EQ(exit_status(mhd), 1) << mhd.output();
  EXPECT_NE(mhd.output().find(b().unplugged), std::string::npos) << mhd.output();
  EXPECT_TRUE(rows_of(dir, "force_on").empty()) << mhd.output();
  EXPECT_EQ(largest_force(dir), 0.0);
}

TEST_P(VendorDevice, AnErrorOnEveryCallGivesNoForce) {
  const fs::path dir = fresh_dir(b(), "error_every_call");
  write_scene(dir, b(), "vendor_desk.xml");
  MhdRunProcess mhd = run(b(), dir, 5.0, Fake{.fault = "error_every_call"});
  EXPECT_EQ(exit_status(mhd), 1) << mhd.output();
  EXPECT_NE(mhd.output().find("open failed"), std::string::npos) << mhd.output();
  EXPECT_TRUE(rows_of(dir, "force_on").empty()) << mhd.output();
  EXPECT_EQ(largest_force(dir), 0.0);
}

// ---- faults mid-run --------------------------------------------------------------------

/// 1.2 s after force output went on, the hand is pressed into the box (the deepest is at
/// 1 s): the fault is named, and no force reaches the motors a frame after it.
void expect_fault_mid_contact(const Backend& b, const std::string& fault, const std::string& says) {
  const fs::path dir = fresh_dir(b, "midrun_" + fault);
  write_scene(dir, b, "vendor_desk.xml");
  MhdRunProcess mhd = run(b, dir, 30.0, Fake{.fault = fault, .fault_after_s = 1.2});
  EXPECT_EQ(exit_status(mhd), kExitFault) << mhd.output();
  EXPECT_NE(mhd.output().find(says), std::string::npos) << mhd.output();
  EXPECT_GT(largest_force(dir), 0.5) << "no contact before the fault: " << mhd.output();
  expect_no_force_after(dir, 1.2 + 0.003);
  expect_last_force_zero(dir, mhd.output());
}

TEST_P(VendorDevice, ALostLinkMidContactIsNamedAndNoForceFollows) {
  expect_fault_mid_contact(b(), "comm_error", b().comm_error);
}

TEST_P(VendorDevice, NonFinitePositionsMidContactAreNamedAndNoForceFollows) {
  expect_fault_mid_contact(b(), "nan_position", "non-finite tool position");
}

// ---- a device weaker than the scene assumes -------------------------------------------

TEST_P(VendorDevice, AWeakerDeviceNeverReceivesMoreThanItsMaximum) {
  const fs::path dir = fresh_dir(b(), "weak");
  const bool by_parameter = *b().force_limit != '\0';
  write_scene(dir, b(), "vendor_desk.xml", {},
              by_parameter ? std::string("<param name=\"") + b().force_limit + "\" value=\"0.4\"/>" : "");
  MhdRunProcess mhd = run(b(), dir, 2.0, Fake{.max_force_N = by_parameter ? "" : "0.4"});
  EXPECT_EQ(exit_status(mhd), 0) << mhd.output();
  expect_clean_hardware_end(dir, mhd.output(), 0.3);
  EXPECT_LE(largest_force(dir), 0.4 + 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Hardware, VendorDevice, kBackends, kBackendName);

// ---- OpenHaptics only: its servo loop, motor temperatures, calibration, workspace ---------

TEST(OpenHaptics, AStalledServoLoopIsNamedAndTheDevicesWatchdogZeroesTheForce) {
  expect_fault_mid_contact(kOpenHaptics, "servo_stall", "servo loop has run no frame for");
}

TEST(OpenHaptics, WarmMotorsEndTheRunWithNoForceAfter) {
  expect_fault_mid_contact(kOpenHaptics, "warm_motors", "a motor reached temperature 0.95");
}

TEST(OpenHaptics, ACalibrationThatNeedsAHandIsRefusedBeforeForceOutput) {
  const fs::path dir = fresh_dir(kOpenHaptics, "manual_calibration");
  write_scene(dir, kOpenHaptics, "vendor_desk.xml");
  MhdRunProcess mhd = run(kOpenHaptics, dir, 5.0, Fake{.fault = "needs_manual_calibration"});
  EXPECT_EQ(exit_status(mhd), kExitFault) << mhd.output();
  EXPECT_NE(mhd.output().find("start failed: the device 'Touch (fake libHD)' needs calibrating by hand"),
            std::string::npos)
      << mhd.output();
  EXPECT_TRUE(rows_of(dir, "force_on").empty()) << mhd.output();
  EXPECT_EQ(largest_force(dir), 0.0);
}

TEST(OpenHaptics, ACalibrationTheDeviceCanUpdateIsUpdatedBeforeForceOutput) {
  const fs::path dir = fresh_dir(kOpenHaptics, "needs_update");
  write_scene(dir, kOpenHaptics, "vendor_desk.xml");
  MhdRunProcess mhd = run(kOpenHaptics, dir, 2.0, Fake{.fault = "needs_update"});
  EXPECT_EQ(exit_status(mhd), 0) << mhd.output();
  const auto calibrated = rows_of(dir, "calibrated");
  const auto on = rows_of(dir, "force_on");
  ASSERT_EQ(calibrated.size(), 1u) << mhd.output();
  ASSERT_EQ(on.size(), 1u) << mhd.output();
  EXPECT_LT(calibrated.front().t_s, on.front().t_s);
  expect_clean_hardware_end(dir, mhd.output());
}

TEST(OpenHaptics, ACalibrationUpdateIsRefusedWhenTheSceneSaysSo) {
  const fs::path dir = fresh_dir(kOpenHaptics, "refuse_update");
  write_scene(dir, kOpenHaptics, "vendor_desk.xml", {}, "<param name=\"calibration\" value=\"refuse\"/>");
  MhdRunProcess mhd = run(kOpenHaptics, dir, 2.0, Fake{.fault = "needs_update"});
  EXPECT_EQ(exit_status(mhd), kExitFault) << mhd.output();
  EXPECT_NE(mhd.output().find("needs a calibration update"), std::string::npos) << mhd.output();
  EXPECT_TRUE(rows_of(dir, "force_on").empty());
}

TEST(OpenHaptics, AToolFarOutsideTheReportedWorkspaceEndsTheRunWithoutForce) {
  const fs::path dir = fresh_dir(kOpenHaptics, "workspace");
  write_scene(dir, kOpenHaptics, "vendor_desk.xml");
  MhdRunProcess mhd = run(kOpenHaptics, dir, 5.0, Fake{.workspace_mm = "-80 500 -35 80 600 35"});
  EXPECT_NE(exit_status(mhd), 0) << mhd.output();
  EXPECT_NE(mhd.output().find("outside the device's workspace"), std::string::npos) << mhd.output();
  EXPECT_EQ(largest_force(dir), 0.0);
}

// ---- mhd devices ------------------------------------------------------------------------

/// `mhd devices` with LD_LIBRARY_PATH = `library_path` and the fakes' `fault`; its output.
std::string devices_output(const fs::path& dir, const std::string& library_path, const std::string& fault,
                           int& status) {
  MhdRunProcess mhd({.argv = {MHD_CLI, "devices", "--plugin-path", MHD_SIM_PLUGIN_DIR},
                     .dir = dir,
                     .env = {{"LD_LIBRARY_PATH", library_path},
                             {"MHD_FAKE_LOG", (dir / "hardware.csv").string()},
                             {"MHD_FAKE_FAULT", fault}}});
  status = exit_status(mhd);
  return mhd.output();
}

TEST(MhdDevices, SaysWhichRuntimeAnswersWhichIsMissingAndTheSnippetForEach) {
  const fs::path dir = fresh_dir(kOpenHaptics, "devices");
  int status = -1;
  const std::string out = devices_output(dir, kOpenHaptics.fake_dir, "none", status);
  EXPECT_EQ(status, 0) << out;
  EXPECT_NE(out.find("  found: 3.3 N, 1260 N/m, 6 in / 3 out DOF, workspace x [-0.08, 0.08] y [-0.06, 0.06] "
                     "z [-0.035, 0.035] m\n  <plugin kind=\"device\" name=\"openhaptics\"/>"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("  no device: open failed: cannot load the Force Dimension SDK 'libdhd.so'"), std::string::npos)
      << out;
  EXPECT_NE(out.find("(docs/hardware.md)\n  <plugin kind=\"device\" name=\"forcedimension\"/>"), std::string::npos)
      << out;
  // Asked, never driven: the device was opened and released, and no force went out.
  EXPECT_FALSE(rows_of(dir, "init").empty()) << out;
  EXPECT_TRUE(rows_of(dir, "force_on").empty()) << out;
  EXPECT_TRUE(rows_of(dir, "scheduler_start").empty()) << out;
}

TEST(MhdDevices, AnUnpluggedDeviceIsNamedWithItsCause) {
  const fs::path dir = fresh_dir(kForceDimension, "devices_unplugged");
  int status = -1;
  const std::string out = devices_output(dir, kForceDimension.fake_dir, "unplugged", status);
  EXPECT_EQ(status, 0) << out;
  EXPECT_NE(out.find("  no device: open failed: dhdOpen: DHD_ERROR_NO_DEVICE_FOUND (5)"), std::string::npos) << out;
}

}  // namespace
