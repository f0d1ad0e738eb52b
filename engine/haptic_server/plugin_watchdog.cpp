#include "haptic_server/plugin_watchdog.h"

#include <fmt/core.h>

namespace mhd {

std::string stuck_call_message(const std::string& plugin_name, const StuckCall& stuck) {
  return fmt::format("plugin '{}': {} has not returned after {:.0f} ms (plugin_call_timeout_s); the run ends",
                     plugin_name, stuck.call == nullptr ? "a call" : stuck.call, stuck.running_for_s * 1e3);
}

std::size_t PluginWatchdog::watch(const CallWatch& watch) {
  watches_.push_back(&watch);
  return watches_.size() - 1;
}

std::optional<StuckCall> PluginWatchdog::check(double now_s) noexcept {
  if (fired_) return std::nullopt;
  for (std::size_t i = 0; i < watches_.size(); ++i) {
    const double since_s = watches_[i]->since_s.load(std::memory_order_acquire);
    if (since_s > 0.0 && now_s - since_s > call_timeout_s_) {
      fired_ = true;
      return StuckCall{i, watches_[i]->call.load(std::memory_order_relaxed), now_s - since_s};
    }
  }
  return std::nullopt;
}

}  // namespace mhd
