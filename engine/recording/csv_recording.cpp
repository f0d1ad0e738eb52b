#include "recording/csv_recording.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <iterator>
#include <stdexcept>

namespace mhd {

std::string_view recording_csv_header() noexcept {
  return "t_s,dt_s,tool_D_x_m,tool_D_y_m,tool_D_z_m,hip_x_m,hip_y_m,hip_z_m,proxy_x_m,proxy_y_m,proxy_z_m,"
         "force_x_N,force_y_N,force_z_N,cmd_force_x_N,cmd_force_y_N,cmd_force_z_N,"
         "force_D_x_N,force_D_y_N,force_D_z_N,base_x_m,base_z_m,base_heading_rad,"
         "user_x_m,user_z_m,user_heading_rad,tracker_age_s,safety_gain,contact,contact_object,lift_m";
}

std::string_view recording_csv_shared_columns() noexcept { return "shared_x_m,shared_y_m,shared_z_m"; }

CsvRecording::CsvRecording(const std::filesystem::path& path, double flush_interval_s, bool shared_columns)
    : path_(path), flush_interval_s_(flush_interval_s), shared_columns_(shared_columns) {
  file_ = std::fopen(path.c_str(), "w");
  if (file_ == nullptr) {
    throw std::runtime_error(fmt::format("cannot write recording {}: {}", path.string(), std::strerror(errno)));
  }
  const std::string_view header = recording_csv_header();
  std::fwrite(header.data(), 1, header.size(), file_);
  if (shared_columns_) {
    const std::string_view shared = recording_csv_shared_columns();
    std::fputc(',', file_);
    std::fwrite(shared.data(), 1, shared.size(), file_);
  }
  std::fputc('\n', file_);
  flush();
}

CsvRecording::~CsvRecording() {
  if (file_ != nullptr) std::fclose(file_);
}

void CsvRecording::write(const RecordingRow& r) {
  fmt::memory_buffer line;
  auto out = std::back_inserter(line);
  // Shortest text that reads back to the same double: a replay gets the very inputs.
  fmt::format_to(out, "{},{}", r.t_s, r.dt_s);
  const auto put3 = [&](const std::array<double, 3>& v) { fmt::format_to(out, ",{},{},{}", v[0], v[1], v[2]); };
  put3(r.p_D_tool_m);
  put3(r.p_W_hip);
  put3(r.proxy_W_m);
  put3(r.force_W_N);
  put3(r.cmd_force_W_N);
  put3(r.force_D_N);
  fmt::format_to(out, ",{},{},{},{},{},{},{},{},{},{},{}", r.base_x_m, r.base_z_m,
                 r.base_heading_rad, r.user_x_m, r.user_z_m, r.user_heading_rad, r.tracker_age_s, r.safety_gain,
                 static_cast<int>(r.contact), r.contact_object, r.lift_m);
  if (shared_columns_) put3(r.p_W_shared_m);
  fmt::format_to(out, "\n");
  if (std::fwrite(line.data(), 1, line.size(), file_) != line.size()) {
    throw std::runtime_error(fmt::format("cannot write recording {}: {}", path_.string(), std::strerror(errno)));
  }
  ++rows_;
  if (r.t_s - last_flush_t_s_ >= flush_interval_s_) {
    flush();
    last_flush_t_s_ = r.t_s;
  }
}

void CsvRecording::flush() {
  if (std::fflush(file_) != 0) {
    throw std::runtime_error(fmt::format("cannot write recording {}: {}", path_.string(), std::strerror(errno)));
  }
}

}  // namespace mhd
