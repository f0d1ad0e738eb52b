#include "hardware_run.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>

namespace mhd::test::hardware {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& suite, const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("mhd_" + suite + "_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

int exit_status(MhdRunProcess& process, std::chrono::seconds timeout) {
  const auto status = process.wait_for(timeout);
  if (!status) return -1;
  if (!WIFEXITED(*status)) return 1000 + WTERMSIG(*status);
  return WEXITSTATUS(*status);
}

std::vector<CommandLogRow> log_of(const fs::path& file) {
  return fs::exists(file) ? read_command_log(file) : std::vector<CommandLogRow>{};
}

std::vector<CommandLogRow> rows_of(const fs::path& file, const std::string& event) {
  std::vector<CommandLogRow> out;
  for (const CommandLogRow& r : log_of(file)) {
    if (r.event == event) out.push_back(r);
  }
  return out;
}

void expect_last_command_zero(const fs::path& file, const std::string& output) {
  const auto commands = rows_of(file, "command");
  ASSERT_FALSE(commands.empty()) << file << " has no command\n" << output;
  const CommandLogRow& last = commands.back();
  EXPECT_TRUE(last.is_zero()) << file << " last command " << last.values[0] << " " << last.values[1] << " "
                              << last.values[2] << "\n"
                              << output;
}

int stale_ticks(const std::string& output) {
  int stale = -1;
  const std::size_t at = output.find("start-up, ");
  if (at == std::string::npos || std::sscanf(output.c_str() + at, "start-up, %d stale", &stale) != 1) return -1;
  return stale;
}

}  // namespace mhd::test::hardware
