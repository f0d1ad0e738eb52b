#pragma once
// A few doubles shared with real-time readers (any number of them): read() never locks,
// never allocates and never waits for a writer, not even one the scheduler has stopped
// half-way through a write. Writes alternate between two slots, each guarded by its own
// sequence, and a counter names the last complete write: a reader takes that write's
// slot, and retries only when the writer has since completed another write and begun
// overwriting it, that is, only while the writer makes progress. (One slot, as in a
// plain seqlock, makes the reader spin until a stopped writer runs again: on a loaded
// machine that held a plugin call on the haptic thread for over 100 ms.)
//
// One writer at a time: callers that may write from several threads serialise their
// write() calls themselves (a writer-side mutex is fine; readers take none).
//
// No standalone fences (ThreadSanitizer cannot check them): each value is stored with
// release after its slot's sequence turned odd, so a reader that acquires a value from an
// overlapping write also sees the changed sequence in its second look and retries.

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

namespace mhd::realtime {

template <std::size_t N>
class Seqlock {
 public:
  static_assert(std::atomic<double>::is_always_lock_free && std::atomic<std::uint64_t>::is_always_lock_free);

  explicit Seqlock(const std::array<double, N>& initial = {}) noexcept {
    for (Slot& slot : slots_) {
      for (std::size_t i = 0; i < N; ++i) slot.values[i].store(initial[i], std::memory_order_relaxed);
    }
  }

  /// The values of the last complete write (or the initial ones). Successive reads never
  /// return an older write than an earlier read did.
  [[nodiscard]] std::array<double, N> read() const noexcept {
    std::array<double, N> out{};
    for (;;) {
      const std::uint64_t k = completed_.load(std::memory_order_acquire);
      const Slot& slot = slots_[k & 1u];
      // Only write k itself: the slot may hold a newer write already, and returning it
      // would let the next read, which may still see completed_ == k + 1, go backwards.
      if (slot.sequence.load(std::memory_order_acquire) != 2 * k) continue;  // since overwritten
      for (std::size_t i = 0; i < N; ++i) out[i] = slot.values[i].load(std::memory_order_acquire);
      if (slot.sequence.load(std::memory_order_relaxed) == 2 * k) return out;
    }
  }

  /// Not for concurrent writers (see above).
  void write(const std::array<double, N>& values) noexcept {
    write(values, [] {});
  }

  /// write(), calling `half_way()` with half the values stored: tests stand in it for a
  /// writer the scheduler stops mid-write.
  template <typename HalfWay>
  void write(const std::array<double, N>& values, HalfWay&& half_way) noexcept {
    // Write k goes to slot k % 2, never the slot of the last complete write, k - 1.
    const std::uint64_t k = completed_.load(std::memory_order_relaxed) + 1;
    Slot& slot = slots_[k & 1u];
    slot.sequence.store(2 * k - 1, std::memory_order_relaxed);
    for (std::size_t i = 0; i < N; ++i) {
      if (i == N / 2) half_way();
      slot.values[i].store(values[i], std::memory_order_release);
    }
    slot.sequence.store(2 * k, std::memory_order_release);
    completed_.store(k, std::memory_order_release);
  }

 private:
  struct Slot {
    std::atomic<std::uint64_t> sequence{0};  ///< 2k - 1 while write k is under way here, 2k once done
    std::array<std::atomic<double>, N> values{};
  };
  std::array<Slot, 2> slots_{};
  std::atomic<std::uint64_t> completed_{0};  ///< writes completed; the last is in slot completed_ % 2
};

}  // namespace mhd::realtime
