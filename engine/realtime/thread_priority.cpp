#include "realtime/thread_priority.h"

#include <pthread.h>
#include <sched.h>

#include <cstring>

namespace mhd::realtime {

RealtimePriority make_current_thread_realtime(int priority) noexcept {
  RealtimePriority r;
  try {
    sched_param param{};
    param.sched_priority = priority;
    const int error = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param);
    if (error == 0) {
      r.realtime = true;
      r.detail = "SCHED_FIFO " + std::to_string(priority);
    } else {
      r.detail = std::string("normal scheduling (SCHED_FIFO refused: ") + std::strerror(error) + ")";
    }
  } catch (...) {
    r.detail = "normal scheduling";
  }
  return r;
}

}  // namespace mhd::realtime
