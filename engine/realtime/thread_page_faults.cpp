#include "realtime/thread_page_faults.h"

#include <sys/resource.h>

namespace mhd::realtime {

PageFaults current_thread_page_faults() noexcept {
  rusage usage{};
  if (::getrusage(RUSAGE_THREAD, &usage) != 0) return {};
  return {usage.ru_minflt, usage.ru_majflt};
}

}  // namespace mhd::realtime
