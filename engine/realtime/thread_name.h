#pragma once
// Names the calling thread (shown by top -H, gdb, perf; read by the tests that watch what
// the haptic thread does). Linux keeps at most 15 characters; longer names are cut.

namespace mhd::realtime {

/// The haptic server's thread names.
inline constexpr const char* kHapticThreadName = "mhd-haptic";
inline constexpr const char* kIoThreadName = "mhd-io";

void name_current_thread(const char* name) noexcept;

}  // namespace mhd::realtime
