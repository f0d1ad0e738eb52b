#pragma once
// A few doubles shared with a real-time reader: read() never locks, never allocates and
// never waits on a writer that is not writing (it retries only while a write is under
// way). One writer at a time: callers that may write from several threads serialise
// their write() calls themselves (a writer-side mutex is fine; the reader takes none).
//
// No standalone fences (ThreadSanitizer cannot check them): each value is stored with
// release after the sequence turned odd, so a reader that acquires a value from an
// overlapping write also sees the odd sequence in its second look and retries.

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
    for (std::size_t i = 0; i < N; ++i) values_[i].store(initial[i], std::memory_order_relaxed);
  }

  /// The values of one complete write (or the initial ones).
  [[nodiscard]] std::array<double, N> read() const noexcept {
    std::array<double, N> out{};
    for (;;) {
      const std::uint64_t before = sequence_.load(std::memory_order_acquire);
      if ((before & 1u) != 0) continue;  // a write is under way
      for (std::size_t i = 0; i < N; ++i) out[i] = values_[i].load(std::memory_order_acquire);
      if (sequence_.load(std::memory_order_relaxed) == before) return out;
    }
  }

  /// Not for concurrent writers (see above).
  void write(const std::array<double, N>& values) noexcept {
    const std::uint64_t sequence = sequence_.load(std::memory_order_relaxed);
    sequence_.store(sequence + 1, std::memory_order_relaxed);
    for (std::size_t i = 0; i < N; ++i) values_[i].store(values[i], std::memory_order_release);
    sequence_.store(sequence + 2, std::memory_order_release);
  }

 private:
  std::atomic<std::uint64_t> sequence_{0};  ///< odd while a write is under way
  std::array<std::atomic<double>, N> values_{};
};

}  // namespace mhd::realtime
