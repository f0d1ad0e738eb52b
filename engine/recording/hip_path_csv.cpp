#include "recording/hip_path_csv.h"

#include "scene_xml/number_parser.h"

#include <fmt/core.h>

#include <utility>

namespace mhd {
namespace {

std::string expected_header() {
  return fmt::format("{},{},{},{}", kHipPathColumns[0], kHipPathColumns[1], kHipPathColumns[2], kHipPathColumns[3]);
}

/// The fields of a line, split_fields on ','; at most kHipPathColumns.size() + 1 are kept (one
/// more is enough to say "extra"). `count` is how many there were in all.
struct Fields {
  std::array<std::string_view, kHipPathColumns.size() + 1> text{};
  std::size_t count = 0;
};

Fields split_fields(std::string_view line) {
  Fields f;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::string_view field = line.substr(start, comma == std::string_view::npos ? std::string_view::npos
                                                                                      : comma - start);
    if (f.count < f.text.size()) f.text[f.count] = scene_xml::trim_xml_space(field);
    ++f.count;
    if (comma == std::string_view::npos) return f;
    start = comma + 1;
  }
}

}  // namespace

HipPathCsvReader::HipPathCsvReader(const std::filesystem::path& file) : name_(file.string()) {
  file_.open(file, std::ios::binary);
  if (!file_) {
    std::error_code ec;
    fail(0, std::filesystem::exists(file, ec) ? "cannot read the HIP path file" : "HIP path file not found");
    return;
  }
  in_ = &file_;
  read_header();
}

HipPathCsvReader::HipPathCsvReader(std::istream& in, std::string name) : in_(&in), name_(std::move(name)) {
  read_header();
}

void HipPathCsvReader::fail(int line, std::string message) {
  Diagnostic d;
  d.where.file = name_;
  d.where.line = line;
  d.message = std::move(message);
  error_ = std::move(d);
}

HipPathCsvReader::LineRead HipPathCsvReader::read_line() {
  in_->getline(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  const std::streamsize extracted = in_->gcount();
  if (in_->bad()) return LineRead::End;  // reported by next()
  if (in_->fail()) {
    if (extracted == 0) return LineRead::End;
    return LineRead::TooLong;  // the buffer filled before the newline
  }
  ++line_number_;
  // gcount() counts the newline when one was extracted (not at the end of the file).
  auto length = static_cast<std::size_t>(extracted);
  if (!in_->eof() && length > 0) --length;
  std::string_view line(buffer_.data(), length);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);  // CRLF
  line_ = line;
  return LineRead::Line;
}

void HipPathCsvReader::read_header() {
  const LineRead read = read_line();
  if (read == LineRead::TooLong) {
    fail(1, fmt::format("the header line is longer than {} bytes (the header must be {})", kHipPathMaxLineBytes,
                        expected_header()));
    return;
  }
  if (read == LineRead::End) {
    fail(1, in_->bad() ? std::string("cannot read the HIP path file")
                       : fmt::format("the file is empty (the header must be {})", expected_header()));
    return;
  }
  const Fields f = split_fields(line_);
  for (std::size_t k = 0; k < kHipPathColumns.size(); ++k) {
    if (k >= f.count) {
      fail(1, fmt::format("missing column '{}' (the header must be {})", kHipPathColumns[k], expected_header()));
      return;
    }
    if (f.text[k] != kHipPathColumns[k]) {
      fail(1, fmt::format("column {} is '{}', expected '{}' (the header must be {})", k + 1, f.text[k],
                          kHipPathColumns[k], expected_header()));
      return;
    }
  }
  if (f.count > kHipPathColumns.size()) {
    fail(1, fmt::format("extra column {} '{}' (the header must be {})", kHipPathColumns.size() + 1,
                        f.text[kHipPathColumns.size()], expected_header()));
  }
}

std::optional<HipPathSample> HipPathCsvReader::next() {
  if (error_) return std::nullopt;
  const LineRead read = read_line();
  if (read == LineRead::TooLong) {
    fail(line_number_ + 1, fmt::format("line longer than {} bytes", kHipPathMaxLineBytes));
    return std::nullopt;
  }
  if (read == LineRead::End) {
    if (in_->bad()) {
      fail(line_number_ + 1, "cannot read the HIP path file");
    } else if (rows_ == 0) {
      fail(line_number_ + 1, fmt::format("no rows after the header (one row of {} per tick)", expected_header()));
    }
    return std::nullopt;
  }
  const int line = line_number_;
  if (line_.empty()) {
    fail(line, fmt::format("empty line (each row must be {})", expected_header()));
    return std::nullopt;
  }
  const Fields f = split_fields(line_);
  if (f.count < kHipPathColumns.size()) {
    fail(line, fmt::format("missing column '{}' (found {} fields, expected {}: {})", kHipPathColumns[f.count], f.count,
                           kHipPathColumns.size(), expected_header()));
    return std::nullopt;
  }
  if (f.count > kHipPathColumns.size()) {
    fail(line, fmt::format("extra field {} '{}' (found {} fields, expected {}: {})", kHipPathColumns.size() + 1,
                           f.text[kHipPathColumns.size()], f.count, kHipPathColumns.size(), expected_header()));
    return std::nullopt;
  }
  std::array<double, kHipPathColumns.size()> v{};
  for (std::size_t k = 0; k < kHipPathColumns.size(); ++k) {
    const scene_xml::ParsedDouble parsed = scene_xml::parse_double(f.text[k]);
    switch (parsed.status) {
      case scene_xml::NumberStatus::Ok:
        v[k] = parsed.value;
        continue;
      case scene_xml::NumberStatus::NonFinite:
        fail(line, fmt::format("column '{}' is not finite ({})", kHipPathColumns[k], f.text[k]));
        return std::nullopt;
      case scene_xml::NumberStatus::OutOfRange:
        fail(line, fmt::format("column '{}': '{}' is out of range", kHipPathColumns[k], f.text[k]));
        return std::nullopt;
      case scene_xml::NumberStatus::Invalid:
        fail(line, fmt::format("column '{}': '{}' is not a number", kHipPathColumns[k], f.text[k]));
        return std::nullopt;
    }
  }
  if (rows_ > 0 && !(v[0] > last_t_s_)) {
    fail(line, fmt::format("column '{}': {} is not after the previous row's {} (time must increase)",
                           kHipPathColumns[0], f.text[0], last_t_s_));
    return std::nullopt;
  }
  ++rows_;
  last_t_s_ = v[0];
  HipPathSample sample;
  sample.t_s = v[0];
  sample.p_W_hip_m = Eigen::Vector3d(v[1], v[2], v[3]);
  sample.line = line;
  return sample;
}

}  // namespace mhd
