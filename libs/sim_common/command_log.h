#pragma once
// What a simulated backend received, seen from the hardware's side: a CSV of every command
// with the host time it arrived, and the backend's own watchdog firing. The caller (the
// host's real-time thread) only copies a fixed-size row into a lock-free SPSC ring; a
// writer thread the log owns writes the rows and flushes at least every 50 ms, and at close.
//
// File: the header "t_s,event,<value names>", then one row per event:
//   start    the backend was started (values 0)
//   command  a command as received (e.g. torques, or a base twist and lift speed)
//   timeout  the backend's command watchdog fired: no command for command_timeout_s; t_s is
//            when the last command expired, the values are what then acts (0)
//   stop     the backend was stopped (values 0)
//   dropped  at close, when the ring was ever full: the first value is how many rows were lost

#include "realtime/spsc_ring.h"

#include <array>
#include <cstddef>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <string>
#include <thread>

namespace mhd::plugin_support {

enum class CommandEvent : std::uint8_t { Start, Command, Timeout, Stop };

class CommandLog {
 public:
  static constexpr std::size_t kMaxValues = 4;

  /// Creates `path` (truncating it), writes the header and starts the writer thread.
  /// Throws std::runtime_error "cannot write the command log '<path>': <reason>".
  template <std::size_t N>
    requires(N >= 1 && N <= kMaxValues)
  CommandLog(const std::string& path, const std::array<const char*, N>& value_names)
      : CommandLog(path, value_names.data(), N) {}
  /// Stops the writer, writes every queued row, flushes and closes the file.
  ~CommandLog();
  CommandLog(const CommandLog&) = delete;
  CommandLog& operator=(const CommandLog&) = delete;

  /// Real-time side: never blocks, allocates or does I/O. One producer at a time (the
  /// plugins call it inside SDK calls, which mhd/plugin_sdk.hpp runs one at a time). A
  /// full ring drops the row (counted).
  /// `values` has as many values as the log has names.
  template <std::size_t N>
    requires(N <= kMaxValues)
  void add(double t_s, CommandEvent event, const std::array<double, N>& values) noexcept {
    Row row{t_s, event, {}};
    for (std::size_t i = 0; i < N; ++i) row.values[i] = values[i];
    push(row);
  }
  [[nodiscard]] std::uint64_t dropped() const noexcept { return dropped_.load(std::memory_order_relaxed); }

 private:
  struct Row {
    double t_s = 0.0;
    CommandEvent event = CommandEvent::Command;
    std::array<double, kMaxValues> values{};
  };
  CommandLog(const std::string& path, const char* const* value_names, std::size_t value_count);
  void push(const Row& row) noexcept;
  void write_queued();
  void writer_loop();

  std::FILE* file_ = nullptr;
  std::size_t value_count_ = 0;
  realtime::SpscRing<Row> ring_{1 << 14};  // 16 s of 1 kHz commands
  std::atomic<std::uint64_t> dropped_{0};
  std::atomic<bool> stop_{false};
  std::thread writer_;
};

}  // namespace mhd::plugin_support
