#pragma once
// The safe state's last step (docs/haptic_server.md, "How a run ends"): zero torque to the
// device and a zero twist to the base, written straight through the plugins. The haptic
// thread, the io thread, run()'s watchdog and the last gasp all end a run through here.

#include "plugin_host/host_services.h"
#include "plugin_host/plugin_instance.h"

namespace mhd {

/// Writes zero torque (timestamped now on `clock`) to `device` if it is Running. True
/// when the device took it; false when it refused it or was not running. No lock, no
/// allocation unless the plugin fails.
[[nodiscard]] bool send_zero_torque(PluginInstance& device, const HostServices& clock) noexcept;

/// Writes a zero twist to `base` if it is Running. True when the base took it, and when
/// there is no base (null); false when it refused it or was not running. No lock, no
/// allocation unless the plugin fails.
[[nodiscard]] bool send_base_stop(PluginInstance* base, const HostServices& clock) noexcept;

struct SafeStopSent {
  bool zero_torque = false;  ///< as send_zero_torque
  bool base_stop = false;    ///< as send_base_stop
};

/// Which plugin goes last: the one a dying thread was inside may hang or crash again.
enum class SafeStopOrder { DeviceFirst, BaseFirst };

/// Both writes, in `order`.
[[nodiscard]] SafeStopSent send_safe_stop(PluginInstance& device, PluginInstance* base, SafeStopOrder order,
                                          const HostServices& clock) noexcept;

}  // namespace mhd
