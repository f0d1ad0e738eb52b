#include "replay_csv.h"

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <string_view>

namespace mhd::tracker_replay {
namespace {

constexpr std::array<const char*, 10> kColumns = {"timestamp_s", "sensor_id", "sequence", "px", "py",
                                                  "pz",          "qw",        "qx",       "qy", "qz"};

std::string_view trim(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> cells;
  for (;;) {
    const std::size_t comma = line.find(',');
    cells.push_back(trim(line.substr(0, comma)));
    if (comma == std::string_view::npos) return cells;
    line.remove_prefix(comma + 1);
  }
}

/// Parses one row; throws ReplayError prefixed with "name:line: ".
class RowParser {
 public:
  RowParser(const std::string& name, int line) : where_(name + ":" + std::to_string(line) + ": ") {}

  [[noreturn]] void fail(const std::string& message) const { throw ReplayError(where_ + message); }

  double real(std::string_view cell, const char* column) const {
    double v = 0.0;
    const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
    if (cell.empty() || ec != std::errc{} || end != cell.data() + cell.size()) {
      fail("column '" + std::string(column) + "' is not a number: '" + std::string(cell) + "'");
    }
    if (!std::isfinite(v)) fail("column '" + std::string(column) + "' is not finite: '" + std::string(cell) + "'");
    return v;
  }

  std::uint64_t integer(std::string_view cell, const char* column, std::uint64_t max_value) const {
    std::uint64_t v = 0;
    const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
    if (cell.empty() || ec != std::errc{} || end != cell.data() + cell.size() || v > max_value) {
      fail("column '" + std::string(column) + "' must be an integer from 0 to " + std::to_string(max_value) + ", got '" +
           std::string(cell) + "'");
    }
    return v;
  }

 private:
  std::string where_;
};

struct PreviousTime {
  int line = 0;
  std::string text;  ///< as written, for messages
};

struct PreviousSequence {
  int line = 0;
  std::uint64_t sequence = 0;
};

}  // namespace

std::vector<mhd_tracker_sample> parse_replay_csv(std::istream& in, const std::string& name) {
  std::string raw;
  int line = 0;
  // The header: the first non-blank line.
  std::string_view header;
  while (std::getline(in, raw)) {
    ++line;
    header = trim(raw);
    if (!header.empty()) break;
  }
  if (header.empty()) throw ReplayError(name + ": empty file, expected the header '" + kReplayHeader + "'");
  {
    const auto names = split(header);
    bool ok = names.size() == kColumns.size();
    for (std::size_t i = 0; ok && i < names.size(); ++i) ok = names[i] == kColumns[i];
    if (!ok) {
      throw ReplayError(name + ":" + std::to_string(line) + ": expected the header '" + kReplayHeader + "', got '" +
                        std::string(header) + "'");
    }
  }

  std::vector<mhd_tracker_sample> samples;
  std::optional<PreviousTime> previous_time;
  std::map<std::uint32_t, PreviousSequence> previous_sequence;
  while (std::getline(in, raw)) {
    ++line;
    const std::string_view text = trim(raw);
    if (text.empty()) continue;
    const RowParser row(name, line);
    const auto cells = split(text);
    if (cells.size() != kColumns.size()) {
      row.fail("expected " + std::to_string(kColumns.size()) + " columns (" + kReplayHeader + "), got " +
               std::to_string(cells.size()));
    }
    mhd_tracker_sample s{};
    s.timestamp_s = row.real(cells[0], kColumns[0]);
    s.sensor_id = static_cast<std::uint32_t>(row.integer(cells[1], kColumns[1], UINT32_MAX));
    s.sequence = row.integer(cells[2], kColumns[2], UINT64_MAX);
    for (std::size_t i = 0; i < 3; ++i) s.p_T_m[i] = row.real(cells[3 + i], kColumns[3 + i]);
    for (std::size_t i = 0; i < 4; ++i) s.q_T_wxyz[i] = row.real(cells[6 + i], kColumns[6 + i]);

    if (previous_time && s.timestamp_s < samples.back().timestamp_s) {
      row.fail("timestamp_s " + std::string(cells[0]) + " is earlier than line " + std::to_string(previous_time->line) +
               "'s " + previous_time->text);
    }
    previous_time = PreviousTime{line, std::string(cells[0])};

    const auto seen = previous_sequence.find(s.sensor_id);
    if (seen != previous_sequence.end() && s.sequence <= seen->second.sequence) {
      row.fail("sequence " + std::to_string(s.sequence) + " of sensor " + std::to_string(s.sensor_id) +
               " does not increase (line " + std::to_string(seen->second.line) + " has " +
               std::to_string(seen->second.sequence) + ")");
    }
    previous_sequence[s.sensor_id] = PreviousSequence{line, s.sequence};

    const double norm = std::sqrt(s.q_T_wxyz[0] * s.q_T_wxyz[0] + s.q_T_wxyz[1] * s.q_T_wxyz[1] +
                                  s.q_T_wxyz[2] * s.q_T_wxyz[2] + s.q_T_wxyz[3] * s.q_T_wxyz[3]);
    if (std::abs(norm - 1.0) > 1e-3) row.fail("quaternion qw,qx,qy,qz has norm " + std::to_string(norm) + ", expected 1");
    for (double& q : s.q_T_wxyz) q /= norm;
    samples.push_back(s);
  }
  if (samples.empty()) throw ReplayError(name + ": no samples after the header");
  return samples;
}

std::vector<mhd_tracker_sample> read_replay_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!std::filesystem::is_regular_file(file) || !in) throw ReplayError(file.string() + ": cannot open the replay file");
  return parse_replay_csv(in, file.string());
}

}  // namespace mhd::tracker_replay
