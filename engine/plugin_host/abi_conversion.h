#pragma once
// The engine's hardware_io.h structs to and from the plugin ABI's (mhd/plugin_abi.h),
// field by field. plugin_host converts at every call; code that meets the ABI itself (a
// tool, a test, a plugin that shares the engine's types) links the ABI header too and
// uses these, so no other engine layer needs it.

#include "plugin_host/hardware_io.h"

#include <mhd/plugin_abi.h>

namespace mhd {

[[nodiscard]] DeviceState from_abi(const mhd_device_state& s) noexcept;
[[nodiscard]] mhd_device_state to_abi(const DeviceState& s) noexcept;
[[nodiscard]] DeviceCommand from_abi(const mhd_device_command& c) noexcept;
[[nodiscard]] mhd_device_command to_abi(const DeviceCommand& c) noexcept;
/// Copies at most kMaxWorkspaceBoxes boxes; the count is kept as reported, so a check can
/// refuse a count out of range.
[[nodiscard]] DeviceInfo from_abi(const mhd_device_info& info) noexcept;
[[nodiscard]] mhd_device_info to_abi(const DeviceInfo& info) noexcept;
[[nodiscard]] TrackerSample from_abi(const mhd_tracker_sample& s) noexcept;
[[nodiscard]] mhd_tracker_sample to_abi(const TrackerSample& s) noexcept;
[[nodiscard]] BaseState from_abi(const mhd_base_state& s) noexcept;
[[nodiscard]] mhd_base_state to_abi(const BaseState& s) noexcept;
[[nodiscard]] BaseCommand from_abi(const mhd_base_command& c) noexcept;
[[nodiscard]] mhd_base_command to_abi(const BaseCommand& c) noexcept;
[[nodiscard]] DisplayFrame from_abi(const mhd_display_frame& f) noexcept;
[[nodiscard]] mhd_display_frame to_abi(const DisplayFrame& f) noexcept;
[[nodiscard]] LinkMessage from_abi(const mhd_link_message& m) noexcept;
[[nodiscard]] mhd_link_message to_abi(const LinkMessage& m) noexcept;
[[nodiscard]] CounterReading from_abi(const mhd_counter& c) noexcept;

}  // namespace mhd
