#pragma once
// The main thread's watch on plugin calls (docs/haptic_server.md, "Faults"): a device,
// tracker or base call still running after plugin_call_timeout_s ends the run.

#include <atomic>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace mhd {

/// Which call a plugin is inside and since when (host seconds; 0: none). Written by the
/// thread making the call, read by the watchdog's thread; lock-free.
struct CallWatch {
  std::atomic<double> since_s{0.0};
  std::atomic<const char*> call{nullptr};
};

/// A call found running past the timeout.
struct StuckCall {
  std::size_t index = 0;         ///< of the watch, in the order watch() was called
  const char* call = nullptr;    ///< e.g. "tracker_read"; null if the call had no name
  double running_for_s = 0.0;    ///< at the check
};

/// "plugin 'x': tracker_read has not returned after 103 ms (plugin_call_timeout_s); the run ends"
[[nodiscard]] std::string stuck_call_message(const std::string& plugin_name, const StuckCall& stuck);

class PluginWatchdog {
 public:
  explicit PluginWatchdog(double call_timeout_s) : call_timeout_s_(call_timeout_s) {}

  /// Adds a watch (before the checks start); returns its index. `watch` must outlive this.
  std::size_t watch(const CallWatch& watch);

  /// The first watch (in watch() order) inside one call for longer than the timeout at
  /// host time `now_s`, the first time one is: a run ends once, so later checks report
  /// nothing. No lock, no allocation.
  [[nodiscard]] std::optional<StuckCall> check(double now_s) noexcept;

 private:
  double call_timeout_s_;
  std::vector<const CallWatch*> watches_;
  bool fired_ = false;
};

}  // namespace mhd
