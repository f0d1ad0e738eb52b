#pragma once
// Shared by the fault-injection suite's test plugins (tests/fault_injection/plugins, SDK
// classes over mhd/plugin_sdk.hpp): a preallocated log written to a file at close, so a
// test checks every command the "hardware" received, with its time, from the hardware's
// side; and a fault that strikes on cue, marked in that log.

#include <mhd/plugin_sdk.hpp>

#include <array>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace probe {

/// Rows of four numbers (time and three values), kept in memory and written at close as
/// "%.9f %.17g %.17g %.17g" lines. Reserved at open: logging never allocates.
class Log {
 public:
  void open(std::string path, std::size_t capacity) {
    path_ = std::move(path);
    if (!path_.empty()) rows_.reserve(capacity);
  }
  void add(double t_s, double a, double b, double c) noexcept {
    if (path_.empty() || rows_.size() == rows_.capacity()) return;  // full: the rest is not kept
    rows_.push_back({t_s, a, b, c});
  }
  void write() const {
    if (path_.empty()) return;
    if (std::FILE* f = std::fopen(path_.c_str(), "w")) {
      for (const Row& r : rows_) std::fprintf(f, "%.9f %.17g %.17g %.17g\n", r.t, r.a, r.b, r.c);
      std::fclose(f);
    }
  }

 private:
  struct Row {
    double t, a, b, c;
  };
  std::string path_;
  std::vector<Row> rows_;
};

/// Which call fails.
enum class FaultOn { Read, Write };

/// The parameters of FaultOnCue.
inline constexpr std::array kFaultParams{
    mhd::sdk::choice("fault", "none|nan|error|deactivate", "none",
                     "what the plugin does once the fault strikes (nan: on read only)"),
    mhd::sdk::number("fault_after_s", "s", nullptr, "when the fault strikes, after start (absent: never)"),
    mhd::sdk::choice("fault_on", "read|write", "read", "which call fails"),
    mhd::sdk::text("command_log", nullptr,
                   "where close() writes every command, and a row 't_s nan nan nan' when the fault strikes"),
};

/// A fault that strikes fault_after_s after start, on reads or on writes, and the log of
/// commands it marks. The destructor writes the log.
class FaultOnCue {
 public:
  FaultOnCue(const mhd::sdk::Params& params, std::size_t log_capacity)
      : fault_(params.text("fault")),
        fault_after_s_(params.optional_number("fault_after_s").value_or(std::numeric_limits<double>::infinity())),
        fault_on_(params.text("fault_on") == "write" ? FaultOn::Write : FaultOn::Read) {
    commands.open(params.optional_text("command_log").value_or(""), log_capacity);
  }
  FaultOnCue(const FaultOnCue&) = delete;
  FaultOnCue& operator=(const FaultOnCue&) = delete;
  ~FaultOnCue() { commands.write(); }

  void start(double t_s) { t_start_s_ = t_s; }

  /// What `call` at t_s returns: MHD_OK (with `nan_out` set when a read must report NaN),
  /// MHD_DEACTIVATE, or, for fault=error, throws error_message (the SDK's MHD_ERROR). The
  /// first time the fault strikes, a row "t_s nan nan nan" goes into the command log, so
  /// a test knows when it struck.
  mhd_status on(FaultOn call, double t_s, const char* error_message, bool& nan_out) {
    nan_out = false;
    if (call != fault_on_ || fault_ == "none" || t_s - t_start_s_ < fault_after_s_) return MHD_OK;
    if (!marked_) {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      commands.add(t_s, nan, nan, nan);
      marked_ = true;
    }
    if (fault_ == "error") throw std::runtime_error(error_message);
    if (fault_ == "deactivate") return MHD_DEACTIVATE;
    nan_out = call == FaultOn::Read;
    return MHD_OK;
  }

  Log commands;

 private:
  std::string fault_;
  double fault_after_s_;
  FaultOn fault_on_;
  double t_start_s_ = 0.0;
  bool marked_ = false;
};

}  // namespace probe
