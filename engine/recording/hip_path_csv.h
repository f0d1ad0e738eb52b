#pragma once
// A HIP path: the haptic interface point in the world frame, one row per tick, as
// `mhd proxy-replay` reads it (docs/proxy_replay.md). The header is exactly
//   t_s,x_m,y_m,z_m
// and every row has four finite numbers with t_s increasing. The file is read one line at a
// time into a fixed buffer, so memory stays bounded whatever the file holds. Every problem
// is a Diagnostic at file:line naming the column.

#include "diagnostics/diagnostic.h"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <istream>
#include <optional>
#include <string>
#include <string_view>

namespace mhd {

inline constexpr std::array<std::string_view, 4> kHipPathColumns = {"t_s", "x_m", "y_m", "z_m"};
/// Longest line accepted, its newline excluded (the '\r' of a CRLF counts); four
/// round-trip doubles need under 100 bytes.
inline constexpr std::size_t kHipPathMaxLineBytes = 1024;

struct HipPathSample {
  double t_s = 0.0;
  Eigen::Vector3d p_W_hip_m = Eigen::Vector3d::Zero();
  int line = 0;  ///< 1-based line of the file it came from
};

class HipPathCsvReader {
 public:
  /// Opens `file` and reads its header; a problem is in error() at once.
  explicit HipPathCsvReader(const std::filesystem::path& file);
  /// Reads from `in` (which must outlive the reader); `name` stands for the file in messages.
  HipPathCsvReader(std::istream& in, std::string name);
  HipPathCsvReader(const HipPathCsvReader&) = delete;  // holds a pointer to its own stream
  HipPathCsvReader& operator=(const HipPathCsvReader&) = delete;

  /// The next row, or nullopt at the end of the file or on the first problem (error()).
  /// A header with no rows after it is a problem.
  [[nodiscard]] std::optional<HipPathSample> next();

  /// The first problem met; reading stops there.
  [[nodiscard]] const std::optional<Diagnostic>& error() const noexcept { return error_; }

 private:
  enum class LineRead { Line, End, TooLong };
  LineRead read_line();
  void fail(int line, std::string message);
  void read_header();

  std::ifstream file_;
  std::istream* in_ = nullptr;
  std::string name_;
  std::array<char, kHipPathMaxLineBytes + 1> buffer_{};  ///< a line and its terminating '\0'
  std::string_view line_;
  int line_number_ = 0;
  int rows_ = 0;
  double last_t_s_ = 0.0;
  std::optional<Diagnostic> error_;
};

}  // namespace mhd
