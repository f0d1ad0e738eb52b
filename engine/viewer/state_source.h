#pragma once
// Where the viewer's rig state comes from. The viewer asks latest() once per frame; a
// source never blocks it. In-process (osg_stereo) the haptic side publishes into a
// LatestStateSlot; `mhd viewer` without a live source uses a FixedStateSource, and a
// network source (DDS) plugs in by implementing StateSource.

#include "viewer/rig_state.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <optional>

namespace mhd::viewer {

class StateSource {
 public:
  virtual ~StateSource() = default;
  /// The newest state, or nullopt while none has arrived. Called from the render thread.
  [[nodiscard]] virtual std::optional<RigState> latest() = 0;
};

/// Always the same state (or none).
class FixedStateSource final : public StateSource {
 public:
  explicit FixedStateSource(std::optional<RigState> state) : state_(std::move(state)) {}
  [[nodiscard]] std::optional<RigState> latest() override { return state_; }

 private:
  std::optional<RigState> state_;
};

/// A lock-free latest-value slot for one writer thread and one reader thread (a triple
/// buffer): publish() never waits and never allocates, so the haptic side can call it;
/// latest() returns the newest published state, older ones are dropped.
class LatestStateSlot final : public StateSource {
 public:
  /// Writer thread only.
  void publish(const RigState& state) noexcept {
    buffers_[back_] = state;
    // Hand the back buffer over as the newest; take whichever buffer was "middle".
    const std::uint8_t previous = middle_.exchange(static_cast<std::uint8_t>(back_ | kFresh), std::memory_order_acq_rel);
    back_ = previous & kIndexMask;
    published_.fetch_add(1, std::memory_order_relaxed);
  }

  /// Reader thread only.
  [[nodiscard]] std::optional<RigState> latest() override {
    if ((middle_.load(std::memory_order_acquire) & kFresh) != 0) {
      const std::uint8_t previous = middle_.exchange(front_, std::memory_order_acq_rel);
      front_ = previous & kIndexMask;
      has_state_ = true;
    }
    if (!has_state_) return std::nullopt;
    return buffers_[front_];
  }

  /// How many states were published (any thread).
  [[nodiscard]] std::uint64_t published() const noexcept { return published_.load(std::memory_order_relaxed); }

 private:
  static constexpr std::uint8_t kFresh = 0x4;
  static constexpr std::uint8_t kIndexMask = 0x3;

  std::array<RigState, 3> buffers_{};
  std::uint8_t back_ = 0;                // owned by the writer
  std::atomic<std::uint8_t> middle_{1};  // exchanged; kFresh set when it holds an unread state
  std::uint8_t front_ = 2;               // owned by the reader
  bool has_state_ = false;               // reader
  std::atomic<std::uint64_t> published_{0};
};

}  // namespace mhd::viewer
