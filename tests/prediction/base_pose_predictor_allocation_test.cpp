// The predictor runs in the 1 kHz haptic thread: feeding and querying it must not allocate.
// This binary replaces the global operator new to count allocations while counting is on.

#include "prediction/base_pose_predictor.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace mhd {
namespace {

TEST(BasePosePredictorAllocation, FeedingAndPredictingAllocatesNothing) {
  BasePosePredictor predictor;
  g_allocations = 0;
  g_counting = true;
  double sum = 0;
  for (int i = 0; i < 5000; ++i) {
    const double t = 0.001 * i;
    if (i % 100 == 0) predictor.add_command(t, BaseTwist{0.2, 0.0, 0.5});
    if (i % 10 == 0) predictor.add_measurement(t, BasePose{0.2 * t, 0.01 * std::sin(t), 0.5 * t});
    if (i % 37 == 0) predictor.add_measurement(t - 0.02, BasePose{});  // out of order
    const BasePose out = predictor.predict(t);
    sum += out.x_m + predictor.age_s(t);
  }
  g_counting = false;
  EXPECT_TRUE(std::isfinite(sum));
  EXPECT_EQ(g_allocations.load(), 0);
}

}  // namespace
}  // namespace mhd
