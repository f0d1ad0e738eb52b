#include "realtime/alternate_signal_stack.h"

#include <sys/mman.h>
#include <unistd.h>

#include <csignal>

namespace mhd::realtime {

AlternateSignalStack::AlternateSignalStack() noexcept {
  const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  const std::size_t bytes = kBytes + page;
  void* mapping = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_STACK, -1, 0);
  if (mapping == MAP_FAILED) return;
  // The lowest page traps: a handler that overflows this stack too faults, not corrupts.
  (void)::mprotect(mapping, page, PROT_NONE);
  stack_t stack{};
  stack.ss_sp = static_cast<char*>(mapping) + page;
  stack.ss_size = kBytes;
  stack.ss_flags = 0;
  if (::sigaltstack(&stack, &previous_) != 0) {
    ::munmap(mapping, bytes);
    return;
  }
  mapping_ = mapping;
  mapping_bytes_ = bytes;
}

AlternateSignalStack::~AlternateSignalStack() {
  if (mapping_ == nullptr) return;
  stack_t restore = previous_;
  if ((restore.ss_flags & SS_DISABLE) != 0) restore = stack_t{nullptr, SS_DISABLE, 0};
  (void)::sigaltstack(&restore, nullptr);
  ::munmap(mapping_, mapping_bytes_);
}

}  // namespace mhd::realtime
