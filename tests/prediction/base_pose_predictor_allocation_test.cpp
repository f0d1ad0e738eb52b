// The predictor runs in the 1 kHz haptic thread: feeding and querying it must not allocate.
// Counted with test::AllocationCounter (its own binary: it replaces operator new).

#include "prediction/base_pose_predictor.h"

#include "support/allocation_counter.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mhd {
namespace {

TEST(BasePosePredictorAllocation, FeedingAndPredictingAllocatesNothing) {
  BasePosePredictor predictor;
  test::AllocationCounter allocations;
  double sum = 0;
  for (int i = 0; i < 5000; ++i) {
    const double t = 0.001 * i;
    if (i % 100 == 0) predictor.add_command(t, BaseTwist{0.2, 0.0, 0.5});
    if (i % 10 == 0) predictor.add_measurement(t, BasePose{0.2 * t, 0.01 * std::sin(t), 0.5 * t});
    if (i % 37 == 0) predictor.add_measurement(t - 0.02, BasePose{});  // out of order
    const BasePose out = predictor.predict(t);
    sum += out.x_m + predictor.age_s(t);
  }
  allocations.stop();
  EXPECT_TRUE(std::isfinite(sum));
  EXPECT_EQ(allocations.count(), 0);
}

}  // namespace
}  // namespace mhd
