#pragma once
// One opened plugin and its lifecycle:
//   Loaded --open--> Open --start--> Running --stop--> Stopped --start--> Running ...
//   any state --close--> Closed (a running plugin is stopped first; the destructor closes)
// Calls out of this order are refused with WrongState before the plugin sees them.
// Kind-specific calls are refused with WrongKind on a plugin of another kind, so no
// null pointer is ever called. Reads and writes need Running; device_info needs an
// opened plugin. What a plugin returns is checked (finite numbers, unit quaternions,
// count <= capacity, known statuses) and a violation is an InvalidData error naming the
// call and the field; an out-parameter is written only when the call returns Ok.
// What the host sends is checked too: a non-finite command never reaches a plugin, and
// device forces and torques are clamped to what the device reported at open.
// An instance is driven by one thread at a time; wrappers allocate only on error.
// The calls take and give the engine's types (hardware_io.h); the ABI's stay inside.

#include "plugin_host/plugin_library.h"
#include "diagnostics/result.h"
#include "plugin_host/hardware_io.h"
#include "plugin_host/plugin_error.h"

#include <cstddef>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>

struct mhd_host;
struct mhd_plugin_instance;

namespace mhd {

enum class PluginState { Loaded, Open, Running, Stopped, Closed };

/// "loaded", "open", "running", "stopped", "closed".
[[nodiscard]] std::string_view to_string(PluginState state);

/// A read or write that did not fail (MHD_ERROR and bad returns are PluginErrors).
enum class PluginCallStatus {
  Ok,          ///< done; a read's output is written
  NoData,      ///< a read found nothing new; output untouched
  Deactivate,  ///< the hardware asks to be stopped (e.g. emergency stop): call stop()
};

class PluginInstance {
 public:
  /// The most samples one tracker_read hands on, and counters one counters() call.
  static constexpr std::size_t kMaxTrackerSamplesPerRead = 256;
  static constexpr std::size_t kMaxCountersPerRead = 64;
  static constexpr std::size_t kMaxLinkMessagesPerCall = 64;

  /// A Loaded instance of `library` (not null).
  explicit PluginInstance(std::shared_ptr<const PluginLibrary> library);
  ~PluginInstance();
  PluginInstance(PluginInstance&& other) noexcept;
  PluginInstance& operator=(PluginInstance&& other) noexcept;
  PluginInstance(const PluginInstance&) = delete;
  PluginInstance& operator=(const PluginInstance&) = delete;

  /// Loaded -> Open: calls open(params) with `host`, which must outlive this instance
  /// (the plugin may keep the pointer). A device's info is read and checked here.
  /// On failure the instance stays Loaded.
  Status<PluginError> open(const std::map<std::string, std::string>& params, const mhd_host& host);
  /// Open or Stopped -> Running. On failure the state does not change.
  Status<PluginError> start();
  /// Running -> Stopped; the state changes even when the plugin reports an error.
  Status<PluginError> stop();
  /// Any state -> Closed (stops a running plugin first and returns that error, if any).
  /// Closing a closed instance does nothing.
  Status<PluginError> close();

  [[nodiscard]] PluginState state() const noexcept { return state_; }
  [[nodiscard]] const std::string& name() const noexcept;
  [[nodiscard]] PluginKind kind() const noexcept;
  /// Null only for a moved-from instance.
  [[nodiscard]] const std::shared_ptr<const PluginLibrary>& library() const noexcept { return library_; }
  /// True when the plugin provides simulate_until.
  [[nodiscard]] bool simulates() const noexcept;
  /// True when the plugin is a tracker that provides tracker_wait.
  [[nodiscard]] bool waits() const noexcept;
  /// True when the plugin provides counters.
  [[nodiscard]] bool counts() const noexcept;

  /// Device: what it reported at open (Open, Running or Stopped), checked
  /// (plugin_host/device_info_check.h).
  [[nodiscard]] Result<DeviceInfo, PluginError> device_info() const;
  [[nodiscard]] Result<PluginCallStatus, PluginError> device_read(DeviceState& out);
  /// The force (torque) is scaled down to the device's max_force_N (max_torque_Nm) before
  /// the plugin sees it; a 3-DOF-out device gets a zero torque.
  [[nodiscard]] Result<PluginCallStatus, PluginError> device_write(const DeviceCommand& command);
  /// Tracker: up to out.size() samples (at most kMaxTrackerSamplesPerRead); `count` is
  /// how many were written (0 unless Ok).
  [[nodiscard]] Result<PluginCallStatus, PluginError> tracker_read(std::span<TrackerSample> out, std::size_t& count);
  [[nodiscard]] Result<PluginCallStatus, PluginError> base_read(BaseState& out);
  [[nodiscard]] Result<PluginCallStatus, PluginError> base_write(const BaseCommand& command);
  [[nodiscard]] Result<PluginCallStatus, PluginError> display_write(const DisplayFrame& frame);
  /// Link: hands `messages` (at most kMaxLinkMessagesPerCall) to the other rigs. A
  /// message with a non-finite number or an unknown kind is refused before the plugin
  /// sees any.
  [[nodiscard]] Result<PluginCallStatus, PluginError> link_send(std::span<const LinkMessage> messages);
  /// Link: up to out.size() messages (at most kMaxLinkMessagesPerCall) from the other
  /// rigs; `count` is how many were written (0 unless Ok). Each is checked: a known kind,
  /// finite numbers, a state's unit quaternion.
  [[nodiscard]] Result<PluginCallStatus, PluginError> link_read(std::span<LinkMessage> out, std::size_t& count);
  /// Simulated backends: advance to host time t_s (WrongKind when the plugin does not simulate).
  [[nodiscard]] Result<PluginCallStatus, PluginError> simulate_until(double t_s);
  /// Tracker with tracker_wait (WrongKind otherwise): blocks up to timeout_s (clamped to
  /// 0..1 s) until tracker_read has data; Ok when it has, NoData on timeout.
  [[nodiscard]] Result<PluginCallStatus, PluginError> tracker_wait(double timeout_s);
  /// The plugin's counters (WrongKind when it keeps none): writes up to out.size() and
  /// returns how many were written. Every name is checked (present, printable, at most
  /// 64 characters) before it is handed on.
  [[nodiscard]] Result<std::size_t, PluginError> counters(std::span<CounterReading> out);

 private:
  [[nodiscard]] PluginError error(PluginErrorKind kind, std::string message) const;
  [[nodiscard]] Status<PluginError> check_call(std::string_view call, PluginKind needed_kind) const;
  [[nodiscard]] Status<PluginError> check_running(std::string_view call) const;
  Status<PluginError> read_device_info();
  void close_handle() noexcept;

  std::shared_ptr<const PluginLibrary> library_;
  mhd_plugin_instance* handle_ = nullptr;
  PluginState state_ = PluginState::Loaded;
  DeviceInfo info_{};
};

}  // namespace mhd
