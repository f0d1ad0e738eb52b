#pragma once
// Counts heap allocations, for tests that code on the 1 kHz path allocates nothing.
// Linking this library replaces the global operator new of the whole test binary (the
// replacement lives in the same object file as AllocationCounter, so using the class
// brings it in); link it only into a binary of its own.

namespace mhd::test {

/// Counts operator new calls from construction until stop(). One at a time.
class AllocationCounter {
 public:
  AllocationCounter();
  ~AllocationCounter();
  AllocationCounter(const AllocationCounter&) = delete;
  AllocationCounter& operator=(const AllocationCounter&) = delete;

  void stop();
  [[nodiscard]] long count() const;
};

}  // namespace mhd::test
