#include "realtime/wake_event.h"

#include <cerrno>
#include <ctime>

namespace mhd::realtime {

WakeEvent::WakeEvent() noexcept { sem_init(&semaphore_, 0, 0); }

WakeEvent::~WakeEvent() { sem_destroy(&semaphore_); }

void WakeEvent::signal() noexcept {
  // A count above 1 would only make later waits return at once for nothing.
  int value = 0;
  if (sem_getvalue(&semaphore_, &value) == 0 && value > 0) return;
  sem_post(&semaphore_);
}

bool WakeEvent::try_consume() noexcept {
  bool any = false;
  while (sem_trywait(&semaphore_) == 0) any = true;
  return any;
}

bool WakeEvent::wait_until_ns(std::int64_t deadline_ns) noexcept {
  timespec deadline{};
  deadline.tv_sec = static_cast<time_t>(deadline_ns / 1'000'000'000);
  deadline.tv_nsec = static_cast<long>(deadline_ns % 1'000'000'000);
  for (;;) {
    if (sem_clockwait(&semaphore_, CLOCK_MONOTONIC, &deadline) == 0) {
      (void)try_consume();
      return true;
    }
    if (errno == ETIMEDOUT) return try_consume();
    if (errno != EINTR) return false;
  }
}

}  // namespace mhd::realtime
