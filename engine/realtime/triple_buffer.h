#pragma once
// Latest-value hand-off between one writer thread and one reader thread, without locks
// or allocation: three slots, one being written, one ready, one being read. The writer
// never waits for the reader and the reader always gets the newest complete value; values
// the reader missed are dropped (this is for state, not for events: use SpscRing there).

#include <atomic>
#include <cstdint>
#include <type_traits>

namespace mhd::realtime {

template <typename T>
class TripleBuffer {
  static_assert(std::is_copy_assignable_v<T>, "slots are copied by the hand-off; a copy must not allocate (fixed-size types)");

 public:
  TripleBuffer() = default;
  explicit TripleBuffer(const T& initial) : slots_{initial, initial, initial} {}
  TripleBuffer(const TripleBuffer&) = delete;
  TripleBuffer& operator=(const TripleBuffer&) = delete;

  /// Writer: publishes `value` as the newest.
  void write(const T& value) noexcept {
    slots_[write_index_] = value;
    // Swap the freshly written slot into "ready" and mark it new; take the old ready slot.
    const std::uint8_t previous = ready_.exchange(static_cast<std::uint8_t>(write_index_ | kFreshBit),
                                                  std::memory_order_acq_rel);
    write_index_ = previous & kIndexMask;
  }

  /// Reader: copies the newest value into `out`. Returns true when it is newer than what
  /// the previous read returned; false leaves `out` at the previous read's value.
  bool read(T& out) noexcept {
    if ((ready_.load(std::memory_order_relaxed) & kFreshBit) != 0) {
      const std::uint8_t previous = ready_.exchange(read_index_, std::memory_order_acq_rel);
      read_index_ = previous & kIndexMask;
      out = slots_[read_index_];
      return true;
    }
    out = slots_[read_index_];
    return false;
  }

  /// Reader: the newest value (whether or not it was read before).
  [[nodiscard]] T latest() noexcept {
    T out;
    read(out);
    return out;
  }

 private:
  static constexpr std::uint8_t kFreshBit = 0x4;
  static constexpr std::uint8_t kIndexMask = 0x3;

  T slots_[3]{};
  std::uint8_t write_index_ = 0;          ///< writer's own slot
  std::atomic<std::uint8_t> ready_{1};    ///< ready slot index | kFreshBit when unread
  std::uint8_t read_index_ = 2;           ///< reader's own slot
};

}  // namespace mhd::realtime
