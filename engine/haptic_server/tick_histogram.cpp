#include "haptic_server/tick_histogram.h"

#include <algorithm>
#include <cmath>

namespace mhd {

void TickHistogram::add(double duration_s) noexcept {
  const double us = std::max(0.0, duration_s * 1e6);
  if (!std::isfinite(us)) return;
  ++count_;
  max_us_ = std::max(max_us_, us);
  const double bin = std::floor(us / kBinWidthUs);
  if (bin >= static_cast<double>(kBins)) {
    ++overflow_;
  } else {
    ++bins_[static_cast<std::size_t>(bin)];
  }
}

double TickHistogram::quantile_us(double q) const noexcept {
  if (count_ == 0) return 0.0;
  const auto rank = static_cast<std::uint64_t>(std::ceil(std::clamp(q, 0.0, 1.0) * static_cast<double>(count_)));
  std::uint64_t seen = 0;
  for (std::size_t i = 0; i < kBins; ++i) {
    seen += bins_[i];
    if (seen >= std::max<std::uint64_t>(rank, 1)) return (static_cast<double>(i) + 1.0) * kBinWidthUs;
  }
  return max_us_;
}

}  // namespace mhd
