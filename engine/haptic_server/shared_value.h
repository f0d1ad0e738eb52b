#pragma once
// A value handed between the server's non-real-time threads behind a mutex (never from
// the haptic thread, which takes no lock).

#include <mutex>

namespace mhd {

template <typename T>
class SharedValue {
 public:
  void set(const T& value) {
    const std::lock_guard lock(mutex_);
    value_ = value;
  }
  [[nodiscard]] T get() const {
    const std::lock_guard lock(mutex_);
    return value_;
  }

 private:
  mutable std::mutex mutex_;
  T value_{};
};

}  // namespace mhd
