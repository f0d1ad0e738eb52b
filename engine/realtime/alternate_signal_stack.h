#pragma once
// A signal stack of the calling thread's own, so that a fatal-signal handler installed with
// SA_ONSTACK still runs when the fault is the thread's stack overflowing (runaway recursion
// in a plugin call): the handler cannot run on the stack that has no room left.

#include <csignal>
#include <cstddef>

namespace mhd::realtime {

class AlternateSignalStack {
 public:
  /// Room for the last gasp: a message and the device's and base's zero commands through
  /// their plugins.
  static constexpr std::size_t kBytes = 256 * 1024;

  /// Maps the stack (with a guard page below it) and makes it the calling thread's; on
  /// failure the thread simply has none (active() is false). Make one before the thread's
  /// real-time loop: it allocates.
  AlternateSignalStack() noexcept;
  /// Restores the thread's previous signal stack and unmaps this one.
  ~AlternateSignalStack();
  AlternateSignalStack(const AlternateSignalStack&) = delete;
  AlternateSignalStack& operator=(const AlternateSignalStack&) = delete;

  [[nodiscard]] bool active() const noexcept { return mapping_ != nullptr; }

 private:
  void* mapping_ = nullptr;
  std::size_t mapping_bytes_ = 0;
  stack_t previous_{};  ///< the thread's signal stack before this one
};

}  // namespace mhd::realtime
