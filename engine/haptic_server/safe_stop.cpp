#include "haptic_server/safe_stop.h"

namespace mhd {

bool send_zero_torque(PluginInstance& device, const HostServices& clock) noexcept {
  if (device.state() != PluginState::Running) return false;
  DeviceCommand zero{};
  zero.timestamp_s = clock.now_s();
  return device.device_write(zero).ok();
}

bool send_base_stop(PluginInstance* base, const HostServices& clock) noexcept {
  if (base == nullptr) return true;
  if (base->state() != PluginState::Running) return false;
  BaseCommand zero{};
  zero.timestamp_s = clock.now_s();
  return base->base_write(zero).ok();
}

SafeStopSent send_safe_stop(PluginInstance& device, PluginInstance* base, SafeStopOrder order,
                            const HostServices& clock) noexcept {
  SafeStopSent sent;
  if (order == SafeStopOrder::BaseFirst) {
    sent.base_stop = send_base_stop(base, clock);
    sent.zero_torque = send_zero_torque(device, clock);
  } else {
    sent.zero_torque = send_zero_torque(device, clock);
    sent.base_stop = send_base_stop(base, clock);
  }
  return sent;
}

}  // namespace mhd
