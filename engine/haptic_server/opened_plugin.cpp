#include "haptic_server/opened_plugin.h"

#include <fmt/core.h>

#include <exception>

namespace mhd {
namespace {

/// The plugin call in progress on this thread: the last gasp names it when the thread dies.
thread_local const OpenedPlugin* t_plugin_in_call = nullptr;
thread_local const char* t_call_in_progress = nullptr;
thread_local const OpenedPlugin* t_last_plugin = nullptr;
thread_local const char* t_last_call = nullptr;

}  // namespace

std::string culprit_of(const PluginDescription& d) {
  return d.where.line > 0 ? fmt::format("plugin '{}' ({}:{})", d.name, d.where.file, d.where.line)
                          : fmt::format("plugin '{}' ({})", d.name, d.where.file);
}

InCall::InCall(OpenedPlugin& plugin, const char* call, double now_s) noexcept
    : watch_(*plugin.watch), outer_plugin_(t_plugin_in_call), outer_call_(t_call_in_progress),
      exceptions_(std::uncaught_exceptions()) {
  watch_.call.store(call, std::memory_order_relaxed);
  watch_.since_s.store(now_s, std::memory_order_release);
  t_plugin_in_call = &plugin;
  t_call_in_progress = call;
  t_last_plugin = &plugin;
  t_last_call = call;
}

InCall::~InCall() {
  watch_.since_s.store(0.0, std::memory_order_release);
  if (std::uncaught_exceptions() > exceptions_) return;
  t_plugin_in_call = outer_plugin_;
  t_call_in_progress = outer_call_;
}

std::pair<const OpenedPlugin*, const char*> plugin_call_on_this_thread() noexcept {
  return {t_plugin_in_call, t_call_in_progress};
}

std::pair<const OpenedPlugin*, const char*> last_plugin_call_on_this_thread() noexcept {
  return {t_last_plugin, t_last_call};
}

}  // namespace mhd
