#include "calibration/calibration_sample.h"
#include "calibration/text_concat.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>

namespace mhd {

namespace {

using calibration_detail::concat;

constexpr std::size_t kColumnCount = kCalibrationSampleColumns.size();

std::string_view trim(std::string_view s) {
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    if (comma == std::string_view::npos) {
      fields.push_back(trim(line.substr(start)));
      return fields;
    }
    fields.push_back(trim(line.substr(start, comma - start)));
    start = comma + 1;
  }
}

/// The number in `field`, or nullopt; NaN and infinity parse (and are rejected later).
std::optional<double> parse_number(std::string_view field) {
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  if (field.empty()) return std::nullopt;
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (ec != std::errc() || ptr != field.data() + field.size()) return std::nullopt;
  return value;
}

std::string number_text(double value) {
  std::array<char, 64> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.10g", value);
  return std::string(buffer.data());
}

std::string expected_columns() {
  std::string out;
  for (const std::string_view c : kCalibrationSampleColumns) {
    if (!out.empty()) out += ",";
    out += c;
  }
  return out;
}

bool is_skipped(std::string_view line) {
  const std::string_view t = trim(line);
  return t.empty() || t.front() == '#';
}

}  // namespace

Result<std::vector<CalibrationSample>> parse_calibration_samples(std::string_view text, const std::string& file) {
  std::vector<CalibrationSample> samples;
  Diagnostics errors;
  const auto error = [&](int line, std::string message) {
    errors.push_back({SourceLocation{file, line}, std::move(message)});
  };

  std::vector<std::string_view> lines;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }

  std::size_t header_index = 0;
  while (header_index < lines.size() && is_skipped(lines[header_index])) ++header_index;
  if (header_index == lines.size()) {
    error(0, concat("no header line (expected the columns ", expected_columns(), ")"));
    return errors;
  }
  const int header_line = static_cast<int>(header_index) + 1;
  const std::vector<std::string_view> header = split_fields(lines[header_index]);

  // column[k]: the field index of kCalibrationSampleColumns[k].
  std::array<std::size_t, kColumnCount> column{};
  bool header_ok = true;
  for (std::size_t k = 0; k < kColumnCount; ++k) {
    const std::string_view wanted = kCalibrationSampleColumns[k];
    const auto first = std::find(header.begin(), header.end(), wanted);
    if (first == header.end()) {
      error(header_line, concat("missing column '", wanted, "' (a samples file needs the columns ",
                                expected_columns(), ")"));
      header_ok = false;
      continue;
    }
    if (std::find(first + 1, header.end(), wanted) != header.end()) {
      error(header_line, concat("column '", wanted, "' appears twice"));
      header_ok = false;
      continue;
    }
    column[k] = static_cast<std::size_t>(first - header.begin());
  }
  if (!header_ok) return errors;
  std::optional<std::size_t> lift_column;
  if (const auto lift = std::find(header.begin(), header.end(), kCalibrationLiftColumn); lift != header.end()) {
    if (std::find(lift + 1, header.end(), kCalibrationLiftColumn) != header.end()) {
      error(header_line, concat("column '", kCalibrationLiftColumn, "' appears twice"));
      return errors;
    }
    lift_column = static_cast<std::size_t>(lift - header.begin());
  }

  for (std::size_t i = header_index + 1; i < lines.size(); ++i) {
    if (is_skipped(lines[i])) continue;
    const int line = static_cast<int>(i) + 1;
    const std::vector<std::string_view> fields = split_fields(lines[i]);
    if (fields.size() != header.size()) {
      error(line, concat("expected ", std::to_string(header.size()), " fields (as in the header), found ",
                         std::to_string(fields.size())));
      continue;
    }
    std::array<double, kColumnCount> v{};
    bool line_ok = true;
    for (std::size_t k = 0; k < kColumnCount; ++k) {
      const std::string_view field = fields[column[k]];
      const std::optional<double> value = parse_number(field);
      if (!value) {
        error(line, concat("column '", kCalibrationSampleColumns[k], "': '", field, "' is not a number"));
        line_ok = false;
      } else if (!std::isfinite(*value)) {
        error(line, concat("column '", kCalibrationSampleColumns[k], "' is not finite (", field, ")"));
        line_ok = false;
      } else {
        v[k] = *value;
      }
    }
    double lift_m = 0.0;
    if (lift_column) {
      const std::string_view field = fields[*lift_column];
      const std::optional<double> value = parse_number(field);
      if (!value) {
        error(line, concat("column '", kCalibrationLiftColumn, "': '", field, "' is not a number"));
        line_ok = false;
      } else if (!std::isfinite(*value)) {
        error(line, concat("column '", kCalibrationLiftColumn, "' is not finite (", field, ")"));
        line_ok = false;
      } else {
        lift_m = *value;
      }
    }
    if (!line_ok) continue;
    const Eigen::Quaterniond q(v[3], v[4], v[5], v[6]);
    const double norm = q.norm();
    if (std::abs(norm - 1.0) > kQuaternionNormTolerance) {
      error(line, concat("sensor quaternion (sensor_qw, sensor_qx, sensor_qy, sensor_qz) has norm ",
                         number_text(norm), "; it must be a unit quaternion"));
      continue;
    }
    CalibrationSample sample;
    sample.X_is900_base_sensor = pose_from_xyz_quaternion(Eigen::Vector3d(v[0], v[1], v[2]), q);
    sample.q_rad = Eigen::Vector3d(v[7], v[8], v[9]);
    sample.p_W_hip_measured_m = Eigen::Vector3d(v[10], v[11], v[12]);
    sample.lift_m = lift_m;
    sample.line = line;
    samples.push_back(sample);
  }
  if (!errors.empty()) return errors;
  return samples;
}

Result<std::vector<CalibrationSample>> read_calibration_samples(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    const char* why = std::filesystem::exists(file) ? "cannot be read" : "not found";
    return Diagnostic{SourceLocation{file.string(), 0}, concat("samples file ", why)};
  }
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return parse_calibration_samples(bytes.str(), file.string());
}

std::string format_calibration_samples(const std::vector<CalibrationSample>& samples,
                                       const std::vector<std::string>& comments) {
  std::string out;
  for (const std::string& c : comments) out += concat("# ", c, "\n");
  // The lift's column only where a sample has the lift off 0: a lift-less rig's file is as before.
  const bool lifted =
      std::any_of(samples.begin(), samples.end(), [](const CalibrationSample& s) { return s.lift_m != 0.0; });
  out += expected_columns();
  if (lifted) {
    out += ',';
    out += kCalibrationLiftColumn;
  }
  out += '\n';
  for (const CalibrationSample& s : samples) {
    const Eigen::Quaterniond q(s.X_is900_base_sensor.linear());
    const Eigen::Vector3d& p = s.X_is900_base_sensor.translation();
    const std::array<double, kColumnCount> v = {p.x(),      p.y(),      p.z(),      q.w(),
                                                q.x(),      q.y(),      q.z(),      s.q_rad.x(),
                                                s.q_rad.y(), s.q_rad.z(), s.p_W_hip_measured_m.x(),
                                                s.p_W_hip_measured_m.y(), s.p_W_hip_measured_m.z()};
    for (std::size_t k = 0; k < kColumnCount; ++k) {
      if (k > 0) out += ",";
      out += number_text(v[k]);
    }
    if (lifted) {
      out += ',';
      out += number_text(s.lift_m);
    }
    out += "\n";
  }
  return out;
}

}  // namespace mhd
