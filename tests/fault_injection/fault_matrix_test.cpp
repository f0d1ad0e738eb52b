// The fault matrix: `mhd run` on the simulated rig with one backend wrapped by fi_wrap
// (tests/fault_injection/plugins/fi_wrap.cpp), which dies, stalls or lies in one way at one
// of its calls 0.5 s into the run. Each cell is judged from the hardware's side, the
// simulated device's and base's command logs, and by the exit status. The cells no
// process can protect itself in (docs/reliability/fault_injection.md, "The fault
// matrix") are stated as such: the hardware's own command timeout covers them.
#include "command_log_file.h"
#include "support/mhd_run_process.h"
#include "support/scratch_dir.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <thread>
#include <tuple>
#include <vector>

namespace {

namespace fs = std::filesystem;
using mhd::test::CommandLogRow;
using mhd::test::read_command_log;
using Clock = std::chrono::steady_clock;

constexpr std::array kFaults{"segv",  "bus",        "fpe",   "ill",   "abort",     "stack_overflow", "pthread_exit",
                             "exit0", "exit3",      "quick_exit", "_exit", "throw", "hang",      "spin",
                             "stall_0.1", "stall_0.5", "stall_2", "nan", "huge", "frozen_timestamp"};
constexpr std::array kCalls{"device_read", "device_write", "tracker_read", "base_read", "base_write"};

/// What a cell must show.
enum class Expect {
  SafeFault,    ///< zero force and zero twist last, exit status non-zero (not a signal)
  SafeEither,   ///< zero force and zero twist last; the run ends by the fault or rides through it
  BaseSafeOnly, ///< the thread is stuck in the device for good: the base is stopped, the device's own timeout zeroes it
  DeviceSafeOnly,  ///< stuck in the base for good: zero force, the base's own timeout stops it
  OutOfProcess,    ///< nothing runs after _exit: the hardware's command timeout is the guard
  NotApplicable,   ///< a value fault in a write: the host, not the plugin, makes the values
};

bool is_write(std::string_view call) { return call == "device_write" || call == "base_write"; }
bool in_device(std::string_view call) { return call.substr(0, 6) == "device"; }
bool in_base(std::string_view call) { return call.substr(0, 4) == "base"; }

Expect expect(std::string_view fault, std::string_view call) {
  if ((fault == "nan" || fault == "huge" || fault == "frozen_timestamp") && is_write(call)) return Expect::NotApplicable;
  if (fault == "_exit") return Expect::OutOfProcess;
  if (fault == "hang" || fault == "spin") {
    if (in_device(call)) return Expect::BaseSafeOnly;
    if (in_base(call)) return Expect::DeviceSafeOnly;
    return Expect::SafeFault;
  }
  // Below the call timeout, or a value the engine copes with: either end is right.
  if (fault == "stall_0.1" || fault == "frozen_timestamp") return Expect::SafeEither;
  return Expect::SafeFault;
}

fs::path fresh_dir(const std::string& name) { return mhd::test::scratch_dir("fault_matrix", name); }

/// tests/data/fault_injection/safe_end.xml with its three backends wrapped, the one that
/// owns `call` failing.
void write_scene(const fs::path& dir, const std::string& fault, const std::string& call) {
  const std::string cue = "<param name=\"fault\" value=\"" + fault + "\"/><param name=\"fault_call\" value=\"" + call +
                          "\"/>";
  const auto wrap = [&](const char* kind, const char* plugin, const char* wrapper, bool fails) {
    return std::pair{std::string("<plugin kind=\"") + kind + "\" name=\"" + plugin + "\">",
                     std::string("<plugin kind=\"") + kind + "\" name=\"" + wrapper + "\">" + (fails ? cue : "")};
  };
  std::ofstream(dir / "scene.xml") << mhd::test::fill_scene_template(
      fs::path(MHD_SOURCE_DIR) / "tests/data/fault_injection/safe_end.xml",
      {wrap("device", "sim_phantom", "fi_phantom", in_device(call)),
       wrap("tracker", "sim_is900", "fi_is900", call == "tracker_read"),
       wrap("base", "sim_omni3", "fi_omni3", in_base(call))});
}

struct Ended {
  int status = 0;
  std::string output;
};

/// `mhd run` on dir/scene.xml for 2 s; nullopt if it has not ended 15 s later.
std::optional<Ended> run_mhd(const fs::path& dir) {
  const std::vector<std::string> argv = {MHD_CLI, "run", (dir / "scene.xml").string(), "--duration", "2", "-q",
                                         "--plugin-path", MHD_FAULT_INJECTION_PLUGIN_DIR, "--plugin-path",
                                         MHD_SIM_PLUGIN_DIR};
  const pid_t pid = ::fork();
  if (pid < 0) return std::nullopt;
  if (pid == 0) {
    const int fd = ::open((dir / "output.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 1);
    ::dup2(fd, 2);
    ::close(fd);
    if (::chdir(dir.c_str()) != 0) ::_exit(126);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  std::optional<int> status;
  const auto give_up = Clock::now() + std::chrono::seconds(15);
  while (!status && Clock::now() < give_up) {
    int s = 0;
    if (::waitpid(pid, &s, WNOHANG) == pid) status = s;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (!status) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    return std::nullopt;
  }
  std::ifstream in(dir / "output.txt");
  std::stringstream out;
  out << in.rdbuf();
  return Ended{*status, out.str()};
}

/// When fi_wrap says its fault struck, on the host's clock (nullopt: it never struck).
std::optional<double> strike_time_s(const std::string& output) {
  constexpr std::string_view kAt = " at host time ";
  const auto line = output.find("fi_wrap: ");
  if (line == std::string::npos) return std::nullopt;
  const auto at = output.find(kAt, line);
  if (at == std::string::npos) return std::nullopt;
  return std::strtod(output.c_str() + at + kAt.size(), nullptr);
}

/// The device's commands from its first gap of more than 0.1 s that ends after the strike
/// (the host stalled in the failing call, or ended the run during one): none of them may
/// carry force. A gap before the strike is the machine's own (a loaded machine stalls a
/// run now and then), and the commands after it rightly carry force.
std::vector<CommandLogRow> device_commands_after_a_gap(const fs::path& log, double strike_t_s) {
  std::vector<CommandLogRow> commands;
  for (const CommandLogRow& r : read_command_log(log)) {
    if (r.event == "command") commands.push_back(r);
  }
  for (std::size_t i = 1; i < commands.size(); ++i) {
    if (commands[i].t_s > strike_t_s && commands[i].t_s - commands[i - 1].t_s > 0.1) {
      return {commands.begin() + static_cast<std::ptrdiff_t>(i), commands.end()};
    }
  }
  return {};
}

/// The last command the hardware received (nullopt: none).
std::optional<CommandLogRow> last_command(const fs::path& log) {
  std::optional<CommandLogRow> last;
  for (const CommandLogRow& r : read_command_log(log)) {
    if (r.event == "command") last = r;
  }
  return last;
}

class FaultMatrix : public ::testing::TestWithParam<std::tuple<const char*, const char*>> {};

TEST_P(FaultMatrix, EndsWithTheHardwareSafeAndSaysSo) {
  const std::string fault = std::get<0>(GetParam());
  const std::string call = std::get<1>(GetParam());
  const Expect e = expect(fault, call);
  if (e == Expect::NotApplicable) GTEST_SKIP() << "the host writes the values of " << call;
#if defined(__SANITIZE_ADDRESS__)
  // The sanitizers own these signals (their handlers end the process first) and
  // stack-overflow; the release suite runs them.
  if (fault == "segv" || fault == "fpe" || fault == "stack_overflow") {
    GTEST_SKIP() << "the sanitizers handle " << fault << " themselves";
  }
#endif
  const fs::path dir = fresh_dir(fault + "_" + call);
  write_scene(dir, fault, call);
  const std::optional<Ended> ended = run_mhd(dir);
  ASSERT_TRUE(ended) << "mhd run still running 13 s after its end";
  const std::string& output = ended->output;
  const std::optional<CommandLogRow> device = last_command(dir / "device.csv");
  const std::optional<CommandLogRow> base = last_command(dir / "base.csv");
  ASSERT_TRUE(device) << output;
  ASSERT_TRUE(base) << output;
  const bool device_safe = device->is_zero();
  const bool base_safe = base->is_zero();
  const bool exited = WIFEXITED(ended->status);
  const int code = exited ? WEXITSTATUS(ended->status) : -1;
  const std::string seen = "exit " + (exited ? std::to_string(code) : "by signal " + std::to_string(WTERMSIG(ended->status))) +
                           ", last force x " + std::to_string(device->values[0]) + ", last vx " +
                           std::to_string(base->values[0]) + "\n" + output;
  // The cell as docs/reliability/fault_injection.md tabulates it.
  const auto error_at = output.find("error: ");
  const std::string said =
      error_at == std::string::npos ? "(no error)" : output.substr(error_at + 7, output.find('\n', error_at) - error_at - 7);
  std::printf("cell | %s | %s | %s | %s | %s | %s\n", fault.c_str(), call.c_str(),
              exited ? std::to_string(code).c_str() : ("signal " + std::to_string(WTERMSIG(ended->status))).c_str(),
              device_safe ? "zero" : "FORCE", base_safe ? "zero" : "MOVING", said.c_str());
  switch (e) {
    case Expect::SafeFault:
      EXPECT_TRUE(device_safe) << seen;
      EXPECT_TRUE(base_safe) << seen;
      EXPECT_TRUE(exited && code != 0) << seen;
      ASSERT_TRUE(strike_time_s(output)) << "the fault never struck\n" << seen;
      for (const CommandLogRow& r : device_commands_after_a_gap(dir / "device.csv", *strike_time_s(output))) {
        EXPECT_TRUE(r.is_zero()) << "force " << r.values[0] << " at " << r.t_s << " s, after the run ended\n" << seen;
      }
      break;
    case Expect::SafeEither:
      EXPECT_TRUE(device_safe) << seen;
      EXPECT_TRUE(base_safe) << seen;
      EXPECT_TRUE(exited) << seen;
      break;
    case Expect::BaseSafeOnly:
      EXPECT_TRUE(base_safe) << seen;
      EXPECT_TRUE(exited && code != 0) << seen;
      break;
    case Expect::DeviceSafeOnly:
      EXPECT_TRUE(device_safe) << seen;
      EXPECT_TRUE(exited && code != 0) << seen;
      break;
    case Expect::OutOfProcess:
      // Nothing in the process runs after _exit; what the hardware has is its last command
      // and its own timeout.
      EXPECT_TRUE(exited) << seen;
      break;
    case Expect::NotApplicable: break;
  }
}

INSTANTIATE_TEST_SUITE_P(Cells, FaultMatrix, ::testing::Combine(::testing::ValuesIn(kFaults), ::testing::ValuesIn(kCalls)),
                         [](const auto& cell) {
                           std::string name = std::string(std::get<0>(cell.param)) + "_in_" + std::get<1>(cell.param);
                           std::replace(name.begin(), name.end(), '.', 'p');
                           return name;
                         });

}  // namespace
