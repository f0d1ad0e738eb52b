#pragma once
// Real-time scheduling for the calling thread: SCHED_FIFO at a priority, where the
// process may (root, CAP_SYS_NICE or an rtprio limit). Without it the loop still runs
// with normal scheduling, where other load can delay its wake-ups (counted as overruns).

#include <string>

namespace mhd::realtime {

struct RealtimePriority {
  bool realtime = false;
  std::string detail;  ///< "SCHED_FIFO 80", or why it was refused
};

/// Asks for SCHED_FIFO at `priority` (1-99) for the calling thread.
RealtimePriority make_current_thread_realtime(int priority) noexcept;

}  // namespace mhd::realtime
