#pragma once
// Shared by the haptic server's fault-injection test plugins (SDK classes, mhd/plugin_sdk.hpp):
// parameters
//   fail_after_reads=<n>   reads that succeed before the fault (default: never fail)
//   fault=nan|huge|error|deactivate|block|none   what the read returns from then on (block:
//                          the first faulty read sleeps block_s, then succeeds; huge: a
//                          finite but absurd value, 1e30, where nan would be NaN)
//   block_s=<seconds>      how long a blocking read blocks (default 1)
//   command_log=<path>     on close, the last command received is written there as
//                          "<count> <a> <b> <c>\n" (count of commands, then the values)
// so a test can check, from the plugin's side, what the host left the hardware with.

#include <mhd/plugin_sdk.hpp>

#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>

namespace fault_injection {

inline constexpr std::array kParams{
    mhd::sdk::integer("fail_after_reads", "", nullptr, "reads that succeed before the fault"),
    mhd::sdk::choice("fault", "nan|huge|error|deactivate|block|none", "none", "what the read returns from then on"),
    mhd::sdk::number("block_s", "s", "1", "how long a blocking read blocks", mhd::sdk::non_negative()),
    mhd::sdk::text("command_log", nullptr, "where close() writes the last command"),
};

/// The reads that fail on cue and the last command kept for the log; what every fault
/// plugin here is made of. The destructor writes the command log.
class FaultyHardware {
 public:
  FaultyHardware(const mhd_host& host, const mhd::sdk::Params& params)
      : host_(host),
        fail_after_reads_(params.optional_integer("fail_after_reads").value_or(std::numeric_limits<std::uint64_t>::max())),
        fault_(params.text("fault")),
        block_s_(params.number("block_s")),
        command_log_(params.optional_text("command_log").value_or("")) {}
  FaultyHardware(const FaultyHardware&) = delete;
  FaultyHardware& operator=(const FaultyHardware&) = delete;
  ~FaultyHardware() {
    if (command_log_.empty()) return;
    if (std::FILE* f = std::fopen(command_log_.c_str(), "w")) {
      std::fprintf(f, "%lu %.17g %.17g %.17g\n", commands_, last_[0], last_[1], last_[2]);
      std::fclose(f);
    }
  }

  /// What this read returns: MHD_OK, or the fault once fail_after_reads reads have passed
  /// (error: thrown, so the SDK returns MHD_ERROR with the message). `absurd_out` is set
  /// when the read must report absurd() in place of a good value.
  mhd_status next_read(bool& absurd_out) {
    absurd_out = false;
    if (++reads_ <= fail_after_reads_ || fault_ == "none") return MHD_OK;
    if (fault_ == "nan" || fault_ == "huge") absurd_out = true;
    if (fault_ == "error") throw std::runtime_error("injected fault: hardware not responding");
    if (fault_ == "deactivate") return MHD_DEACTIVATE;
    if (fault_ == "block" && !blocked_) {
      blocked_ = true;
      std::this_thread::sleep_for(std::chrono::duration<double>(block_s_));
    }
    return MHD_OK;
  }

  /// The value a faulty read reports in place of a good one: NaN, or 1e30 with fault=huge.
  [[nodiscard]] double absurd() const { return fault_ == "huge" ? 1e30 : std::numeric_limits<double>::quiet_NaN(); }

  void record(double a, double b, double c) {
    last_ = {a, b, c};
    ++commands_;
  }

  [[nodiscard]] double now_s() const { return mhd::sdk::host_now(host_); }

 private:
  mhd_host host_;
  std::uint64_t fail_after_reads_;
  std::string fault_;
  double block_s_;
  std::string command_log_;
  std::array<double, 3> last_{};
  unsigned long commands_ = 0;
  std::uint64_t reads_ = 0;
  bool blocked_ = false;
};

}  // namespace fault_injection
