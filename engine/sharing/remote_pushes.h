#pragma once
// The authority's inbox of the other rigs' pushes on its objects: the newest push of
// each (object, rig), acting until a newer one replaces it or until it is hold_s old.
// Pushes arrive at the rate of the sender's haptic loop; one that stops coming (a lost
// link, a crashed rig) stops pushing after hold_s instead of pushing the object on for
// ever. Fixed size, no allocation: used on the haptic thread.

#include "sharing/shared_object_state.h"

#include <array>
#include <cstdint>

namespace mhd {

inline constexpr int kMaxRemotePushes = 32;

struct RemotePushSettings {
  /// A push older than this no longer acts: a few sender periods and network jitters.
  double hold_s = 0.05;
};

class RemotePushes {
 public:
  explicit RemotePushes(const RemotePushSettings& settings = {}) noexcept : settings_(settings) {}

  /// Keeps `push` as its (object, rig)'s newest. False (nothing kept) when it is not
  /// finite, not newer than that pair's newest, or the table is full.
  bool receive(const SharedPush& push) noexcept;

  /// Calls fn(const SharedPush&) for each kept push that still acts at now_s.
  template <class Fn>
  void for_each_acting(double now_s, Fn&& fn) const {
    for (int i = 0; i < count_; ++i) {
      const SharedPush& p = pushes_[static_cast<std::size_t>(i)];
      if (acts(p, now_s)) fn(p);
    }
  }
  [[nodiscard]] bool acts(const SharedPush& push, double now_s) const noexcept {
    return now_s - push.t_s <= settings_.hold_s;
  }
  [[nodiscard]] std::uint64_t refused() const noexcept { return refused_; }

 private:
  RemotePushSettings settings_;
  std::array<SharedPush, kMaxRemotePushes> pushes_{};
  int count_ = 0;
  std::uint64_t refused_ = 0;
};

}  // namespace mhd
