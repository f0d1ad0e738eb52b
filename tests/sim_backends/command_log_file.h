#pragma once
// Reading the command log a simulated backend writes (libs/sim_common/command_log.h):
// the rows of "t_s,event,a,b,c" after the header.

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace mhd::test {

struct CommandLogRow {
  double t_s = 0.0;
  std::string event;  ///< start, command, timeout, stop, dropped
  std::array<double, 4> values{};  ///< three, or four for a base's log (its lift speed last)
  [[nodiscard]] bool is_zero() const {
    return values[0] == 0.0 && values[1] == 0.0 && values[2] == 0.0 && values[3] == 0.0;
  }
};

/// Every row; `header` receives the first line. A malformed row throws std::runtime_error
/// naming the file and line.
std::vector<CommandLogRow> read_command_log(const std::filesystem::path& file, std::string* header = nullptr);

}  // namespace mhd::test
