#include "recording/csv_recording_reader.h"

#include "recording/csv_recording.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <filesystem>
#include <system_error>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mhd {
namespace {

/// A recording's line is a few hundred bytes; anything this long is not one.
constexpr std::size_t kMaxLineBytes = 64 * 1024;
constexpr std::size_t kReadBlockBytes = 1 << 20;

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> cells;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= line.size(); ++i) {
    if (i == line.size() || line[i] == ',') {
      cells.push_back(line.substr(start, i - start));
      start = i + 1;
    }
  }
  return cells;
}

bool parse_number(std::string_view text, double& out) {
  if (text == "nan" || text == "-nan") {
    out = std::nan("");
    return true;
  }
  if (text == "inf" || text == "-inf") {
    out = text[0] == '-' ? -HUGE_VAL : HUGE_VAL;
    return true;
  }
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size();
}

/// A diagnostic at file:line (built member by member: GCC 12 misreads the nested braces).
Diagnostic at(const std::string& file, int line, std::string message) {
  Diagnostic d;
  d.where.file = file;
  d.where.line = line;
  d.message = std::move(message);
  return d;
}

}  // namespace

Result<std::vector<RecordingRow>> read_recording(const std::filesystem::path& file) {
  const std::string name = file.string();
  // Never opened unless a regular file: a FIFO would block, a device never end.
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(file, ec);
  if (ec || !std::filesystem::exists(status)) return at(name, 0, "cannot read the recording: file not found");
  if (!std::filesystem::is_regular_file(status)) {
    return at(name, 0, "cannot read the recording: not a regular file (a device, a FIFO or a folder)");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) return at(name, 0, "cannot read the recording");
  std::vector<RecordingRow> rows;
  Diagnostics errors;

  std::map<std::string, std::size_t, std::less<>> column;
  std::vector<std::string_view> expected = split(recording_csv_header());
  // Optional: recordings from before the lift, or before shared objects, lack them.
  for (const std::string_view optional : {"lift_m", "shared_x_m", "shared_y_m", "shared_z_m"}) {
    std::erase(expected, optional);
  }
  // Read a block at a time, each line within kMaxLineBytes: memory stays bounded by the
  // rows, whatever the file holds.
  std::string text;
  std::size_t line_start = 0;
  int line_number = 0;
  std::vector<char> block(kReadBlockBytes);
  for (;;) {
    std::size_t newline = text.find('\n', line_start);
    if (newline == std::string::npos) {
      if (text.size() - line_start > kMaxLineBytes) {
        return at(name, line_number + 1,
                  "a line longer than " + std::to_string(kMaxLineBytes) + " bytes: not a recording");
      }
      text.erase(0, line_start);
      line_start = 0;
      in.read(block.data(), static_cast<std::streamsize>(block.size()));
      const auto got = static_cast<std::size_t>(in.gcount());
      if (got == 0) break;  // the end; a line cut short by a crash is not read
      text.append(block.data(), got);
      continue;
    }
    const std::string_view line(text.data() + line_start, newline - line_start);
    line_start = newline + 1;
    ++line_number;
    const std::vector<std::string_view> cells = split(line);
    if (line_number == 1) {
      for (std::size_t i = 0; i < cells.size(); ++i) {
        // A name given twice would leave fewer names than fields, and a row is checked
        // against the names: refuse it here.
        if (const auto [it, added] = column.emplace(std::string(cells[i]), i); !added) {
          errors.push_back(at(name, 1, "column '" + std::string(cells[i]) + "' named twice (fields " +
                                           std::to_string(it->second + 1) + " and " + std::to_string(i + 1) + ")"));
          return errors;
        }
      }
      for (const std::string_view name_expected : expected) {
        if (column.find(name_expected) == column.end()) {
          errors.push_back(at(name, 1, "missing column '" + std::string(name_expected) + "'"));
        }
      }
      if (!errors.empty()) return errors;
      continue;
    }
    if (cells.size() != column.size()) {
      errors.push_back(at(name, line_number, "expected " + std::to_string(column.size()) + " fields, found " +
                                                          std::to_string(cells.size())));
      return errors;
    }
    RecordingRow row;
    bool ok = true;
    const auto get = [&](std::string_view col, double& value) {
      if (!ok) return;
      const std::string_view cell = cells[column.find(col)->second];
      if (!parse_number(cell, value)) {
        errors.push_back(
            at(name, line_number, "column '" + std::string(col) + "' is not a number: '" + std::string(cell) + "'"));
        ok = false;
      }
    };
    const auto get3 = [&](const char* prefix, const char* suffix, std::array<double, 3>& v) {
      const char* axes[3] = {"x", "y", "z"};
      for (int i = 0; i < 3; ++i) get(std::string(prefix) + axes[i] + suffix, v[static_cast<std::size_t>(i)]);
    };
    get("t_s", row.t_s);
    get("dt_s", row.dt_s);
    get("tool_D_x_m", row.p_D_tool_m[0]);
    get("tool_D_y_m", row.p_D_tool_m[1]);
    get("tool_D_z_m", row.p_D_tool_m[2]);
    get3("hip_", "_m", row.p_W_hip);
    get3("proxy_", "_m", row.proxy_W_m);
    get3("force_", "_N", row.force_W_N);
    get3("cmd_force_", "_N", row.cmd_force_W_N);
    get("force_D_x_N", row.force_D_N[0]);
    get("force_D_y_N", row.force_D_N[1]);
    get("force_D_z_N", row.force_D_N[2]);
    get("base_x_m", row.base_x_m);
    get("base_z_m", row.base_z_m);
    get("base_heading_rad", row.base_heading_rad);
    // Recordings from before the lift have no lift column: their arm stood at 0.
    if (column.find("lift_m") != column.end()) get("lift_m", row.lift_m);
    // Likewise the shared object's columns (all three or none is used).
    if (column.count("shared_x_m") != 0 && column.count("shared_y_m") != 0 && column.count("shared_z_m") != 0) {
      get3("shared_", "_m", row.p_W_shared_m);
    }
    get("user_x_m", row.user_x_m);
    get("user_z_m", row.user_z_m);
    get("user_heading_rad", row.user_heading_rad);
    get("tracker_age_s", row.tracker_age_s);
    get("safety_gain", row.safety_gain);
    double contact = 0.0, contact_object = -1.0;
    get("contact", contact);
    get("contact_object", contact_object);
    if (!ok) {
      return errors;
    }
    row.contact = contact != 0.0 ? 1 : 0;
    row.contact_object = static_cast<std::int32_t>(contact_object);
    rows.push_back(row);
  }
  if (line_number == 0) return at(name, 0, "the recording has no header line");
  return rows;
}

}  // namespace mhd
