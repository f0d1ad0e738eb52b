// Every end of `mhd run` leaves zero torque and a stopped base, seen from the hardware's
// side: the simulated device's and base's command logs (docs/haptic_server.md, "How a run
// ends"). Real processes: the stop signals, a closed stdout, a plugin that crashes in each
// way (tests/fault_injection/plugins/fi_crash.cpp), and a frozen process, whose
// simulated hardware's command watchdog fires.
#include "command_log_file.h"
#include "support/mhd_run_process.h"
#include "support/scratch_dir.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;
using mhd::test::CommandLogRow;
using mhd::test::read_command_log;

fs::path fresh_dir(const std::string& name) { return mhd::test::scratch_dir("run_end", name); }

/// tests/data/fault_injection/<source> (safe_end.xml, the mobile rig, or desk_safe_end.xml, a
/// desktop one) in `dir`, with `extra_plugin` in its <plugins>.
fs::path write_scene(const fs::path& dir, const std::string& extra_plugin, const std::string& source = "safe_end.xml") {
  const fs::path file = dir / "scene.xml";
  std::ofstream(file) << mhd::test::fill_scene_template(fs::path(MHD_SOURCE_DIR) / "tests/data/fault_injection" / source,
                                                        {{"<!--CRASH-->", extra_plugin}});
  return file;
}

/// `mhd run` on the scene in `dir` for `duration_s`; stdout and stderr into output.txt,
/// or stdout into a pipe whose reading end is already closed.
class MhdRun : public mhd::test::MhdRunProcess {
 public:
  MhdRun(const fs::path& dir, double duration_s, bool stdout_to_closed_pipe = false)
      : MhdRunProcess({.argv = {MHD_CLI, "run", (dir / "scene.xml").string(), "--duration", std::to_string(duration_s),
                                "-q", "--plugin-path", MHD_FAULT_INJECTION_PLUGIN_DIR, "--plugin-path",
                                MHD_SIM_PLUGIN_DIR},
                       .dir = dir,
                       .stdout_to_closed_pipe = stdout_to_closed_pipe}) {}

  /// Waits (generously) until the device has logged `rows` rows, i.e. the run is under way.
  void wait_until_running(std::size_t rows = 300) {
    if (!wait_until_logged("device.csv", rows)) FAIL() << "mhd run did not get going: " << output();
  }
};

std::vector<CommandLogRow> commands_in(const std::vector<CommandLogRow>& rows) {
  std::vector<CommandLogRow> out;
  for (const CommandLogRow& r : rows) {
    if (r.event == "command") out.push_back(r);
  }
  return out;
}

/// The hardware's view of a safe end: the last device command is zero torque, the last base
/// command a zero twist, and the base had been driven (so the stop is a real one).
void expect_safe_end(const fs::path& dir, const std::string& output) {
  const auto device = commands_in(read_command_log(dir / "device.csv"));
  const auto base = commands_in(read_command_log(dir / "base.csv"));
  ASSERT_FALSE(device.empty()) << output;
  ASSERT_FALSE(base.empty()) << output;
  EXPECT_TRUE(device.back().is_zero()) << "last torques " << device.back().values[0] << " at " << device.back().t_s
                                       << "\n" << output;
  EXPECT_TRUE(base.back().is_zero()) << "last twist " << base.back().values[0] << " at " << base.back().t_s << "\n"
                                     << output;
  EXPECT_TRUE(std::any_of(base.begin(), base.end(), [](const CommandLogRow& r) { return !r.is_zero(); }))
      << "the planner never drove the base: " << output;
}

// ---- stop signals ----------------------------------------------------------------------

struct StopSignalCase {
  int signal;
  int exit_status;
  const char* name;
};

class StopSignal : public ::testing::TestWithParam<StopSignalCase> {};

TEST_P(StopSignal, EndsTheRunThroughTheSafeStop) {
  const StopSignalCase c = GetParam();
  const fs::path dir = fresh_dir(c.name);
  write_scene(dir, "");
  MhdRun run(dir, 30.0);
  run.wait_until_running();
  run.signal(c.signal);
  const auto status = run.wait_for(std::chrono::seconds(10));
  ASSERT_TRUE(status) << "still running after " << c.name;
  ASSERT_TRUE(WIFEXITED(*status)) << run.output();
  EXPECT_EQ(WEXITSTATUS(*status), c.exit_status) << run.output();
  EXPECT_NE(run.output().find(std::string("stopped by ") + c.name), std::string::npos) << run.output();
  EXPECT_NE(run.output().find("safe state: zero force sent, base stopped"), std::string::npos) << run.output();
  expect_safe_end(dir, run.output());
}

INSTANTIATE_TEST_SUITE_P(RunEnd, StopSignal,
                         ::testing::Values(StopSignalCase{SIGINT, 0, "SIGINT"}, StopSignalCase{SIGTERM, 0, "SIGTERM"},
                                           StopSignalCase{SIGHUP, 128 + SIGHUP, "SIGHUP"},
                                           StopSignalCase{SIGQUIT, 128 + SIGQUIT, "SIGQUIT"}),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(RunEnd, IgnoredSignalsAndAClosedStdoutNeverEndARun) {
  const fs::path dir = fresh_dir("closed_stdout");
  write_scene(dir, "");
  MhdRun run(dir, 1.5, /*stdout_to_closed_pipe=*/true);
  run.wait_until_running();
  run.signal(SIGPIPE);
  run.signal(SIGUSR1);
  run.signal(SIGUSR2);
  const auto status = run.wait_for(std::chrono::seconds(20));
  ASSERT_TRUE(status);
  ASSERT_TRUE(WIFEXITED(*status)) << "ended by signal " << WTERMSIG(*status) << ": " << run.output();
  EXPECT_EQ(WEXITSTATUS(*status), 0) << run.output();
  // It ran to its duration: the device's last row is about 1.5 s after its first.
  const auto device = read_command_log(dir / "device.csv");
  ASSERT_GE(device.size(), 2u);
  EXPECT_GT(device.back().t_s - device.front().t_s, 1.4) << run.output();
  expect_safe_end(dir, run.output());
}

// ---- a desktop rig: the device alone --------------------------------------------------

/// The device's view of a safe end with no base: it was pushed (the hand touched the box)
/// and its last command is zero force.
void expect_desk_safe_end(const fs::path& dir, const std::string& output) {
  const auto device = commands_in(read_command_log(dir / "device.csv"));
  ASSERT_FALSE(device.empty()) << output;
  EXPECT_TRUE(device.back().is_zero()) << "last force " << device.back().values[0] << " at " << device.back().t_s
                                       << "\n" << output;
  EXPECT_TRUE(std::any_of(device.begin(), device.end(), [](const CommandLogRow& r) { return !r.is_zero(); }))
      << "the hand never touched the box: " << output;
  for (const char* mobile_only : {"base stop", "base:", "tracker:", "start-up"}) {
    EXPECT_EQ(output.find(mobile_only), std::string::npos) << "a desktop rig has no '" << mobile_only << "': " << output;
  }
}

TEST(RunEnd, ADesktopRunEndedBySigintLeavesZeroForce) {
  const fs::path dir = fresh_dir("desk_sigint");
  write_scene(dir, "", "desk_safe_end.xml");
  MhdRun run(dir, 30.0);
  run.wait_until_running(1500);  // long enough to have touched the box
  run.signal(SIGINT);
  const auto status = run.wait_for(std::chrono::seconds(10));
  ASSERT_TRUE(status) << "still running after SIGINT";
  ASSERT_TRUE(WIFEXITED(*status)) << run.output();
  EXPECT_EQ(WEXITSTATUS(*status), 0) << run.output();
  EXPECT_NE(run.output().find("stopped by SIGINT"), std::string::npos) << run.output();
  EXPECT_NE(run.output().find("safe state: zero force sent\n"), std::string::npos) << run.output();
  expect_desk_safe_end(dir, run.output());
}

TEST(RunEnd, ADesktopRunEndedByItsDurationLeavesZeroForce) {
  const fs::path dir = fresh_dir("desk_duration");
  write_scene(dir, "", "desk_safe_end.xml");
  MhdRun run(dir, 2.0);
  const auto status = run.wait_for(std::chrono::seconds(20));
  ASSERT_TRUE(status) << "still running: " << run.output();
  ASSERT_TRUE(WIFEXITED(*status)) << run.output();
  EXPECT_EQ(WEXITSTATUS(*status), 0) << run.output();
  EXPECT_NE(run.output().find("rig: desktop"), std::string::npos) << run.output();
  EXPECT_NE(run.output().find("safe state: zero force sent\n"), std::string::npos) << run.output();
  expect_desk_safe_end(dir, run.output());
}

TEST(RunEnd, ADesktopRunWhosePluginCrashesLeavesZeroForce) {
  const fs::path dir = fresh_dir("desk_crash");
  write_scene(dir, "<plugin kind=\"display\" name=\"fi_crash\"><param name=\"crash\" value=\"abort\"/></plugin>",
              "desk_safe_end.xml");
  MhdRun run(dir, 30.0);
  const auto status = run.wait_for(std::chrono::seconds(20));
  ASSERT_TRUE(status) << "still running: " << run.output();
  ASSERT_TRUE(WIFEXITED(*status)) << "ended by signal " << WTERMSIG(*status) << ": " << run.output();
  EXPECT_EQ(WEXITSTATUS(*status), 4) << run.output();
  EXPECT_NE(run.output().find("mhd run: last gasp: zero torque sent\n"), std::string::npos) << run.output();
  const auto device = commands_in(read_command_log(dir / "device.csv"));
  ASSERT_FALSE(device.empty()) << run.output();
  EXPECT_TRUE(device.back().is_zero()) << run.output();
}

// ---- crashing plugins ------------------------------------------------------------------

struct CrashCase {
  const char* crash;
  const char* cause;  ///< in the message
};

class PluginCrash : public ::testing::TestWithParam<CrashCase> {};

TEST_P(PluginCrash, TheLastGaspSendsZerosAndNamesThePlugin) {
  const CrashCase c = GetParam();
#if defined(__SANITIZE_ADDRESS__)
  // Under ASan+UBSan the sanitizers own these: ASan's SIGSEGV handler and UBSan's
  // division-by-zero check end the process before our last gasp sees the signal. The
  // release suite runs both cases.
  if (std::string_view(c.crash) == "segfault" || std::string_view(c.crash) == "fpe") {
    GTEST_SKIP() << "the sanitizers handle " << c.crash << " themselves";
  }
#endif
  const fs::path dir = fresh_dir(c.crash);
  write_scene(dir, std::string("<plugin kind=\"display\" name=\"fi_crash\"><param name=\"crash\" value=\"") + c.crash +
                       "\"/></plugin>");
  MhdRun run(dir, 30.0);
  const auto status = run.wait_for(std::chrono::seconds(20));
  ASSERT_TRUE(status) << "still running: " << run.output();
  ASSERT_TRUE(WIFEXITED(*status)) << "ended by signal " << WTERMSIG(*status) << ": " << run.output();
  EXPECT_EQ(WEXITSTATUS(*status), 4) << run.output();
  EXPECT_NE(run.output().find("mhd run: error: plugin 'fi_crash' (" + (dir / "scene.xml").string() + ":24) in "
                              "display_write: " + c.cause),
            std::string::npos)
      << run.output();
  EXPECT_NE(run.output().find("mhd run: last gasp: zero torque sent, base stop sent"), std::string::npos)
      << run.output();
  expect_safe_end(dir, run.output());
}

INSTANTIATE_TEST_SUITE_P(
    RunEnd, PluginCrash,
    ::testing::Values(CrashCase{"segfault", "segmentation fault (SIGSEGV)"}, CrashCase{"bus", "bus error (SIGBUS)"},
                      CrashCase{"fpe", "arithmetic exception (SIGFPE)"}, CrashCase{"abort", "abort (SIGABRT)"},
                      CrashCase{"throw", "uncaught exception: fi_crash: injected exception"},
                      CrashCase{"exit0", "exit() called while the server runs"}),
    [](const auto& param_info) { return std::string(param_info.param.crash); });

// ---- the hardware's own command timeout --------------------------------------------------

TEST(RunEnd, AFrozenServerLetsTheSimulatedHardwaresWatchdogsFire) {
  // No process survives kill -9 to log anything, so the server is frozen instead (SIGSTOP):
  // its commands stop, and the simulated device and base log their watchdogs firing,
  // command_timeout_s (0.02 s, 0.2 s) after the last command, with zero acting from then on.
  const fs::path dir = fresh_dir("frozen");
  write_scene(dir, "");
  MhdRun run(dir, 30.0);
  run.wait_until_running();
  run.signal(SIGSTOP);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  run.signal(SIGCONT);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  run.signal(SIGINT);
  ASSERT_TRUE(run.wait_for(std::chrono::seconds(10)));
  for (const auto& [file, timeout_s] : {std::pair{"device.csv", 0.02}, std::pair{"base.csv", 0.2}}) {
    const auto rows = read_command_log(dir / file);
    // The freeze's timeout: the one the next command follows only after the freeze. (On a
    // loaded machine the watchdog may also fire at a scheduling hiccup before it, rightly.)
    const auto timeout = std::find_if(rows.begin(), rows.end(), [&](const CommandLogRow& r) {
      const auto i = static_cast<std::size_t>(&r - rows.data());
      return r.event == "timeout" && i > 0 && i + 1 < rows.size() && rows[i + 1].t_s - rows[i - 1].t_s > 0.3;
    });
    ASSERT_NE(timeout, rows.end()) << file << ": no timeout row during the freeze; " << run.output();
    EXPECT_TRUE(timeout->is_zero());
    const auto last_command = std::prev(timeout);
    ASSERT_EQ(last_command->event, "command") << file;
    EXPECT_NEAR(timeout->t_s - last_command->t_s, timeout_s, 1e-5) << file;
    // The next command came only after the freeze (about 0.5 s later).
    const auto next = std::next(timeout);
    ASSERT_NE(next, rows.end()) << file;
    EXPECT_GT(next->t_s - last_command->t_s, 0.3) << file;
  }
  expect_safe_end(dir, run.output());
}

}  // namespace
