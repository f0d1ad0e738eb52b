#pragma once
// A scene plugin as the server drives it, and the mark a call to it leaves: on its
// CallWatch for the watchdog (plugin_watchdog.h), and on the calling thread for the last
// gasp, which names the plugin a dying thread was inside.

#include "haptic_server/plugin_watchdog.h"
#include "plugin_host/plugin_instance.h"
#include "scene/scene_description.h"

#include <atomic>
#include <memory>
#include <string>
#include <utility>

namespace mhd {

/// "plugin 'x' (scene.xml:12)", or "plugin 'x' (scene.xml)" without a line.
[[nodiscard]] std::string culprit_of(const PluginDescription& description);

/// Taken around every call to the base from a server thread, so that run()'s thread can
/// send the base its stop while the io thread is stuck inside another plugin. Taking it
/// never waits and never locks: the io thread, which finds it taken only while run()'s
/// thread stops the base at the run's end, then ends its loop.
class CallClaim {
 public:
  [[nodiscard]] bool try_take() noexcept { return !taken_.exchange(true, std::memory_order_acquire); }
  void give_back() noexcept { taken_.store(false, std::memory_order_release); }

 private:
  std::atomic<bool> taken_{false};
};

/// Holds a CallClaim for as long as it lives, when it could take it (see taken()).
class ClaimedCall {
 public:
  explicit ClaimedCall(CallClaim& claim) noexcept : claim_(claim), taken_(claim.try_take()) {}
  ~ClaimedCall() {
    if (taken_) claim_.give_back();
  }
  ClaimedCall(const ClaimedCall&) = delete;
  ClaimedCall& operator=(const ClaimedCall&) = delete;
  [[nodiscard]] bool taken() const noexcept { return taken_; }

 private:
  CallClaim& claim_;
  bool taken_;
};

struct OpenedPlugin {
  PluginDescription description;
  PluginInstance instance;
  /// Made at open: a crash message names the plugin without allocating.
  std::string culprit = culprit_of(description);
  std::unique_ptr<CallWatch> watch = std::make_unique<CallWatch>();
  /// Taken around every call to the base from a server thread (in a box: plugins move).
  std::unique_ptr<CallClaim> call_claim = std::make_unique<CallClaim>();
};

/// Marks `plugin` as inside `call` for as long as it lives, for the watchdog and, on this
/// thread, for the last gasp. An exception leaving the call keeps the thread's mark, so
/// std::terminate can still name the plugin it came from. No lock, no allocation.
class InCall {
 public:
  InCall(OpenedPlugin& plugin, const char* call, double now_s) noexcept;
  ~InCall();
  InCall(const InCall&) = delete;
  InCall& operator=(const InCall&) = delete;

 private:
  CallWatch& watch_;
  const OpenedPlugin* outer_plugin_;
  const char* outer_call_;
  int exceptions_;
};

/// The plugin and call an InCall on this thread marks (nulls when none). Async-signal-safe
/// (reads thread-locals).
[[nodiscard]] std::pair<const OpenedPlugin*, const char*> plugin_call_on_this_thread() noexcept;

/// The plugin and call this thread entered last, returned or not (nulls when none): what a
/// thread that vanished (pthread_exit) was doing, after the unwinding cleared its mark.
[[nodiscard]] std::pair<const OpenedPlugin*, const char*> last_plugin_call_on_this_thread() noexcept;

}  // namespace mhd
