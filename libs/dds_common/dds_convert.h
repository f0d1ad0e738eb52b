#pragma once
// Between the plugin ABI's structs (host clock, seconds) and the DDS types (publisher's
// CLOCK_REALTIME, nanoseconds). A host-clock time t maps to realtime as
// now_ns - (host_now_s - t): both clocks advance at the same rate.

#include "mhd_dds_types.h"

#include <mhd/plugin_abi.h>

#include <cstdint>

namespace mhd::dds {

/// Host-clock seconds -> realtime nanoseconds, given both clocks read now.
[[nodiscard]] std::int64_t realtime_from_host(double t_s, double host_now_s, std::int64_t now_ns);
/// Realtime nanoseconds -> host-clock seconds.
[[nodiscard]] double host_from_realtime(std::int64_t t_ns, double host_now_s, std::int64_t now_ns);

[[nodiscard]] mhd_dds_TrackerSample to_dds(const mhd_tracker_sample& s, std::uint32_t rig_id, std::int64_t timestamp_ns);
[[nodiscard]] mhd_tracker_sample from_dds(const mhd_dds_TrackerSample& s, double timestamp_s);

[[nodiscard]] mhd_dds_RigState to_dds(const mhd_display_frame& f, std::uint32_t rig_id, std::uint64_t sequence,
                                      std::int64_t timestamp_ns);
[[nodiscard]] mhd_display_frame from_dds(const mhd_dds_RigState& s, double timestamp_s);

}  // namespace mhd::dds
