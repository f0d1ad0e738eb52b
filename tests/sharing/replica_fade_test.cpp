// The force from a stale replica fades out at its rate, comes back at its own once the
// data is fresh again, never steps, and a broken age or tick is handled safely.

#include "sharing/replica_fade.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace mhd::fade_test {

TEST(ReplicaFade, StaleDataFadesTheForceAndFreshDataBringsItBack) {
  ReplicaFade fade(ReplicaFadeSettings{0.1, 0.1, 0.3});
  constexpr double kDt_s = 0.001;
  for (int k = 0; k < 100; ++k) EXPECT_EQ(fade.update(0.05, kDt_s), 1.0);  // fresh: full force
  double last = 1.0;
  int ticks_to_zero = 0;
  while (fade.update(0.2, kDt_s) > 0.0) {  // stale
    EXPECT_LT(fade.gain(), last);
    EXPECT_NEAR(last - fade.gain(), kDt_s / 0.1, 1e-12);  // never a step
    last = fade.gain();
    ++ticks_to_zero;
  }
  EXPECT_NEAR(ticks_to_zero, 99, 1);  // 0.1 s
  EXPECT_EQ(fade.update(std::numeric_limits<double>::infinity(), kDt_s), 0.0);
  int ticks_to_one = 0;
  while (fade.update(0.0, kDt_s) < 1.0) ++ticks_to_one;
  EXPECT_NEAR(ticks_to_one, 299, 1);  // 0.3 s
}

TEST(ReplicaFade, ANaNAgeIsStaleAndABrokenTickChangesNothing) {
  ReplicaFade fade;
  EXPECT_LT(fade.update(std::numeric_limits<double>::quiet_NaN(), 0.001), 1.0);
  const double g = fade.gain();
  for (const double bad_dt : {0.0, -0.001, std::numeric_limits<double>::quiet_NaN(),
                              std::numeric_limits<double>::infinity()}) {
    EXPECT_EQ(fade.update(1.0, bad_dt), g);
  }
}

}  // namespace mhd::fade_test
