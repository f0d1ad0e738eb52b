#pragma once
// Counts the mutex locks, heap allocations and writes made on one named thread (the
// haptic thread, realtime::kHapticThreadName, or the io thread) by interposing
// pthread_mutex_lock, operator new, write and fwrite for the whole binary that links
// haptic_thread_watch.cpp.

#include <string>

namespace mhd::test {

struct ThreadCalls {
  long locks = 0, allocations = 0, writes = 0;  ///< all of them, the plugins' included
  /// Of those, the ones made inside a call to a plugin (haptic_server/opened_plugin.h,
  /// InCall): the plugin's own, not the engine's.
  long locks_in_plugins = 0, allocations_in_plugins = 0;
  std::string first_caller;  ///< library and function of the first lock or allocation, or "-"
};

/// Zeroes the counts and starts counting the calls made on the thread named `thread_name`
/// (a static string).
void start_thread_watch(const char* thread_name) noexcept;
/// Stops counting; the counts since the start.
ThreadCalls stop_thread_watch();

}  // namespace mhd::test
