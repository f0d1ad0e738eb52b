#pragma once
// Bounded single-producer single-consumer queue of events (tracker samples, recording
// rows) between two threads, without locks or allocation after construction. push()
// fails when full instead of waiting, and the producer counts what it dropped: the
// real-time side never blocks on a slow consumer.

#include <atomic>
#include <cstddef>
#include <new>
#include <type_traits>
#include <vector>

namespace mhd::realtime {

template <typename T>
class SpscRing {
  static_assert(std::is_copy_assignable_v<T>, "elements are copied in and out; a copy must not allocate (fixed-size types)");

 public:
  /// Room for `capacity` elements (allocated here, once).
  explicit SpscRing(std::size_t capacity) : slots_(capacity + 1) {}
  SpscRing(const SpscRing&) = delete;
  SpscRing& operator=(const SpscRing&) = delete;

  /// Producer: false (and nothing stored) when the ring is full.
  bool push(const T& value) noexcept {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    const std::size_t next = advance(head);
    if (next == tail_.load(std::memory_order_acquire)) return false;
    slots_[head] = value;
    head_.store(next, std::memory_order_release);
    return true;
  }

  /// Consumer: false when empty.
  bool pop(T& out) noexcept {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    if (tail == head_.load(std::memory_order_acquire)) return false;
    out = slots_[tail];
    tail_.store(advance(tail), std::memory_order_release);
    return true;
  }

  [[nodiscard]] std::size_t capacity() const noexcept { return slots_.size() - 1; }
  /// Consumer side: true when nothing is queued.
  [[nodiscard]] bool empty() const noexcept {
    return tail_.load(std::memory_order_relaxed) == head_.load(std::memory_order_acquire);
  }

 private:
  [[nodiscard]] std::size_t advance(std::size_t i) const noexcept { return i + 1 == slots_.size() ? 0 : i + 1; }

  std::vector<T> slots_;
  alignas(64) std::atomic<std::size_t> head_{0};  ///< next slot the producer writes
  alignas(64) std::atomic<std::size_t> tail_{0};  ///< next slot the consumer reads
};

}  // namespace mhd::realtime
