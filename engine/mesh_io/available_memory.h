#pragma once
// How much memory the machine can give a load now, so that a mesh too large for it is
// refused from its header instead of the process being killed halfway.

#include <cstdint>

namespace mhd {

/// MemAvailable from /proc/meminfo, in bytes; 0 when it cannot be read (then nothing is
/// refused for memory).
[[nodiscard]] std::uint64_t available_memory_bytes();

}  // namespace mhd
