#pragma once
// Counts the mutex locks, heap allocations and writes made on the haptic thread (named
// realtime::kHapticThreadName) by interposing pthread_mutex_lock, operator new, write
// and fwrite for the whole binary that links haptic_thread_watch.cpp.

#include <string>

namespace mhd::test {

struct HapticThreadCalls {
  long locks = 0, allocations = 0, writes = 0;
  std::string first_caller;  ///< library and function of the first lock or allocation, or "-"
};

/// Zeroes the counts and starts counting.
void start_haptic_thread_watch() noexcept;
/// Stops counting; the counts since the start.
HapticThreadCalls stop_haptic_thread_watch();

}  // namespace mhd::test
