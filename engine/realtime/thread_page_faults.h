#pragma once
// The page faults the calling thread has taken: a real-time thread that takes one waits on
// the kernel (microseconds from memory, milliseconds from the disk), so the haptic thread
// counts those of its loop and the run's report says them.

namespace mhd::realtime {

struct PageFaults {
  long minor = 0;  ///< the page was in memory (the page cache, or a fresh page)
  long major = 0;  ///< the page was read from the disk
};

/// The calling thread's page faults since it started (getrusage, RUSAGE_THREAD); zero
/// where they cannot be read. One system call: not for every tick.
[[nodiscard]] PageFaults current_thread_page_faults() noexcept;

/// a - b, field by field.
[[nodiscard]] inline PageFaults operator-(const PageFaults& a, const PageFaults& b) {
  return {a.minor - b.minor, a.major - b.major};
}

}  // namespace mhd::realtime
