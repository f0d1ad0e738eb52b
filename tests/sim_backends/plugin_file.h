#pragma once
// A freshly built plugin file opened the way the host opens it (dlopen, then
// dlsym("mhd_plugin_entry")), and a host table with a clock the test sets and a
// SimulatedWorld.

#include "sim_world/sim_session.h"
#include "simulation/simulated_world.h"

#include <mhd/plugin_abi.h>

#include <initializer_list>
#include <string>
#include <utility>

namespace mhd::test {

class PluginFile {
 public:
  /// Throws std::runtime_error with dlerror()'s message.
  explicit PluginFile(const char* path);
  ~PluginFile();
  PluginFile(const PluginFile&) = delete;
  PluginFile& operator=(const PluginFile&) = delete;

  /// What mhd_plugin_entry returns for a host of this ABI version.
  [[nodiscard]] const mhd_plugin_api* entry(std::uint32_t host_abi_version) const { return entry_(host_abi_version); }
  /// The table for this ABI version; throws if the plugin refuses it.
  [[nodiscard]] const mhd_plugin_api& api() const;

 private:
  void* handle_ = nullptr;
  mhd_plugin_entry_fn entry_ = nullptr;
};

/// A host with a clock the test sets and no scene file; it holds the simulated world the
/// simulated plugins opened with it share (the session of "no scene"), so the test can
/// place the base, head and hand there.
struct FakeHost {
  FakeHost();
  FakeHost(const FakeHost&) = delete;
  FakeHost& operator=(const FakeHost&) = delete;

  double now_s = 0.0;
  mhd_host host{};
  std::shared_ptr<sim_world::SimSession> session;
  simulation::SimulatedWorld& world;
};

struct Opened {
  mhd_plugin_instance* instance = nullptr;
  std::string error;  ///< the plugin's message when instance is NULL
};

[[nodiscard]] Opened open_plugin(const mhd_plugin_api& api, const mhd_host& host,
                                 std::initializer_list<std::pair<const char*, const char*>> params);

/// A plugin opened with `params` and started, stopped and closed when it goes. Throws
/// std::runtime_error with the plugin's message when the open or the start fails.
class StartedPlugin {
 public:
  StartedPlugin(const mhd_plugin_api& api, const mhd_host& host,
                std::initializer_list<std::pair<const char*, const char*>> params);
  ~StartedPlugin();
  StartedPlugin(const StartedPlugin&) = delete;
  StartedPlugin& operator=(const StartedPlugin&) = delete;
  [[nodiscard]] mhd_plugin_instance* get() const { return instance_; }

 private:
  const mhd_plugin_api& api_;
  mhd_plugin_instance* instance_ = nullptr;
};

}  // namespace mhd::test
