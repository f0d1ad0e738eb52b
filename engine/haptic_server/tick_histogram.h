#pragma once
// Durations of the haptic loop's ticks, for median and tail figures without storing every
// sample or allocating on the real-time thread: 0.1 us bins up to 5 ms, and the maximum.

#include <array>
#include <cstdint>

namespace mhd {

class TickHistogram {
 public:
  static constexpr double kBinWidthUs = 0.1;
  static constexpr std::size_t kBins = 50000;

  void add(double duration_s) noexcept;
  /// The q-quantile (0..1) in microseconds, to the bin width; 0 without samples. A
  /// quantile among the durations beyond the last bin is the maximum.
  [[nodiscard]] double quantile_us(double q) const noexcept;
  [[nodiscard]] double max_us() const noexcept { return max_us_; }
  [[nodiscard]] std::uint64_t count() const noexcept { return count_; }

 private:
  std::array<std::uint32_t, kBins> bins_{};
  std::uint64_t overflow_ = 0;
  std::uint64_t count_ = 0;
  double max_us_ = 0.0;
};

}  // namespace mhd
