#pragma once
// Writes a recording as CSV (header below, one row per haptic tick), for plots, replay and
// analysis. The file is flushed at least every flush_interval_s of recorded time, so a
// killed process leaves a readable file up to its last flush; a partial last line is the
// only damage. Not for the real-time thread: the server feeds it from its recorder thread.
//
// Columns: t_s, dt_s, tool_D_{x,y,z}_m (the device frame), hip_{x,y,z}_m, proxy_{x,y,z}_m, force_{x,y,z}_N,
// cmd_force_{x,y,z}_N, force_D_{x,y,z}_N (what the device got, its frame), base_x_m, base_z_m, base_heading_rad, user_x_m,
// user_z_m, user_heading_rad, tracker_age_s, safety_gain, contact, contact_object, lift_m;
// and, in a recording of a rig that shares objects, shared_{x,y,z}_m (the first shared
// object's origin as the rig rendered it).
// Numbers are written in the shortest form that reads back to the same double, so a
// replay (recording_replay.h) feeds the engine exactly the recorded inputs.

#include "recording/recording_row.h"

#include <cstdio>
#include <filesystem>
#include <string_view>

namespace mhd {

/// The header line, without its newline.
[[nodiscard]] std::string_view recording_csv_header() noexcept;
/// The columns a recording of a rig that shares objects adds at the end.
[[nodiscard]] std::string_view recording_csv_shared_columns() noexcept;

class CsvRecording {
 public:
  /// Creates (truncates) `path` and writes the header, with the shared object's columns
  /// when `shared_columns`; throws std::runtime_error naming the file and the reason when
  /// it cannot.
  CsvRecording(const std::filesystem::path& path, double flush_interval_s, bool shared_columns = false);
  ~CsvRecording();
  CsvRecording(const CsvRecording&) = delete;
  CsvRecording& operator=(const CsvRecording&) = delete;

  /// Appends a row; throws std::runtime_error when the write fails (disk full).
  void write(const RecordingRow& row);
  /// Pushes everything written so far to the file.
  void flush();

  [[nodiscard]] std::uint64_t rows() const noexcept { return rows_; }
  [[nodiscard]] const std::filesystem::path& path() const noexcept { return path_; }

 private:
  std::filesystem::path path_;
  std::FILE* file_ = nullptr;
  double flush_interval_s_;
  bool shared_columns_;
  double last_flush_t_s_ = 0.0;
  std::uint64_t rows_ = 0;
};

}  // namespace mhd
