#pragma once
// Wakes a real-time loop early from another thread: the io thread signals the haptic
// thread when a new tracker sample is in the ring, so the force is computed from it at
// once instead of at the next 1 ms deadline. Signals do not pile up: one wait consumes
// every signal given before it. signal() never blocks and never allocates.

#include <semaphore.h>

#include <cstdint>

namespace mhd::realtime {

class WakeEvent {
 public:
  WakeEvent() noexcept;
  ~WakeEvent();
  WakeEvent(const WakeEvent&) = delete;
  WakeEvent& operator=(const WakeEvent&) = delete;

  /// Wakes the waiter (or makes its next wait return at once).
  void signal() noexcept;
  /// Waits until signalled or until `deadline_ns` on CLOCK_MONOTONIC has passed; true
  /// when signalled. Consumes all pending signals.
  bool wait_until_ns(std::int64_t deadline_ns) noexcept;
  /// True, and consumes them, when signals are pending; never waits.
  bool try_consume() noexcept;

 private:
  sem_t semaphore_;
};

}  // namespace mhd::realtime
