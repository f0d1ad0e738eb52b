// Keep-out on fresh data only, seen from the hardware's side: `mhd run`
// on tests/data/fault_injection/head_dropout.xml, where sim_is900 stops measuring the head
// 3 s after its start for 1.5 s. In sim_omni3's command log every base command is zero
// from 100 ms after the head data went stale (the tracker timeout after the dropout start)
// to the dropout's end, and the base moves again after it.
#include "command_log_file.h"
#include "support/scratch_dir.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using mhd::test::CommandLogRow;
using mhd::test::read_command_log;

constexpr double kDropoutStart_s = 3.0, kDropoutDuration_s = 1.5;
constexpr double kTrackerTimeout_s = 0.05;  // <server> default: the base sensor's, and now the head's

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(HeadDropout, TheBaseStopsWithin100msOfStaleHeadDataAndMovesAgainAfter) {
  const fs::path dir = mhd::test::scratch_dir("head_dropout", "run");
  const std::string command = "cd '" + dir.string() + "' && '" + MHD_CLI + "' run '" + MHD_SOURCE_DIR +
                              "/tests/data/fault_injection/head_dropout.xml' --duration 6.5 --plugin-path '" +
                              MHD_SIM_PLUGIN_DIR + "' > output.txt 2>&1";
  const int status = std::system(command.c_str());
  const std::string output = read_text(dir / "output.txt");
  ASSERT_EQ(status, 0) << output;

  const std::vector<CommandLogRow> rows = read_command_log(dir / "base.csv");
  // The tracker starts before the base (plugins start in scene order, the device last), so
  // the base's start is at or after the dropout clock's zero.
  const auto start = std::find_if(rows.begin(), rows.end(), [](const CommandLogRow& r) { return r.event == "start"; });
  ASSERT_NE(start, rows.end()) << output;
  const double t0_s = start->t_s;
  const double stale_s = t0_s + kDropoutStart_s + kTrackerTimeout_s;
  const double fresh_again_s = t0_s + kDropoutStart_s + kDropoutDuration_s;

  std::size_t moving_before = 0, moving_stale = 0, zero_stale = 0, moving_after = 0;
  double first_moving_stale_s = 0.0;
  for (const CommandLogRow& r : rows) {
    if (r.event != "command") continue;
    if (r.t_s < t0_s + kDropoutStart_s && !r.is_zero()) ++moving_before;
    if (r.t_s >= stale_s + 0.1 && r.t_s < fresh_again_s) {
      if (r.is_zero()) {
        ++zero_stale;
      } else if (moving_stale++ == 0) {
        first_moving_stale_s = r.t_s - t0_s;
      }
    }
    if (r.t_s >= fresh_again_s && !r.is_zero()) ++moving_after;
  }
  EXPECT_GT(moving_before, 0u) << "the base never followed before the dropout\n" << output;
  EXPECT_EQ(moving_stale, 0u) << "a moving command " << first_moving_stale_s << " s after start\n" << output;
  EXPECT_GT(zero_stale, 5u) << output;  // the watchdog keeps being fed with zeros
  EXPECT_GT(moving_after, 0u) << "the base never moved again after the dropout\n" << output;
  // The report counts the stop (the start, before any head sample, may add one).
  const std::size_t at = output.find("base stops by cause: ");
  ASSERT_NE(at, std::string::npos) << output;
  EXPECT_GE(std::stoi(output.substr(at + 21)), 1) << output;
}

}  // namespace
