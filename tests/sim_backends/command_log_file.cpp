#include "command_log_file.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace mhd::test {

std::vector<CommandLogRow> read_command_log(const std::filesystem::path& file, std::string* header) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::string line;
  std::getline(in, line);
  if (header != nullptr) *header = line;
  std::vector<CommandLogRow> rows;
  for (int number = 2; std::getline(in, line); ++number) {
    CommandLogRow row;
    char event[32] = {};
    const int fields = std::sscanf(line.c_str(), "%lf,%31[a-z_],%lf,%lf,%lf,%lf", &row.t_s, event, &row.values[0],
                                   &row.values[1], &row.values[2], &row.values[3]);
    if (fields != 5 && fields != 6) {
      throw std::runtime_error(file.string() + ":" + std::to_string(number) + ": malformed row '" + line + "'");
    }
    row.event = event;
    rows.push_back(row);
  }
  return rows;
}

}  // namespace mhd::test
