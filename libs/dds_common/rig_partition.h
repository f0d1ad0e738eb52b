#pragma once
// Every reader and writer of rig N lives in DDS partition "mhd_rigN". DDS access
// control grants topics per partition, never per key value, so the partition is what
// lets rig 1's tracker publish rig 1's samples only (docs/networking.md, "Security").
// Secured or not, the endpoints are the same: one code path.

#include <cstdint>
#include <string>

namespace mhd::dds {

[[nodiscard]] inline std::string rig_partition(std::uint32_t rig_id) { return "mhd_rig" + std::to_string(rig_id); }

/// Viewers that follow any rig subscribe with this pattern.
inline constexpr const char* kAllRigsPartition = "mhd_rig*";

}  // namespace mhd::dds
