#include "skipped_carry_check.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace mhd::stress::test {

void expect_skipped_carry_caught_and_replayed(const CompiledScene& scene, int object, std::uint64_t key,
                                              MovingStressSettings settings) {
  settings.fault_skip_carry = true;
  const MovingStressReport r = stress_moving_object(scene, object, key, settings);
  EXPECT_GT(r.crossing_ticks + r.inside_ticks, 0U);
  EXPECT_FALSE(r.clean());
  ASSERT_FALSE(r.failures.empty());
  EXPECT_EQ(r.push_ticks, 0U);  // nothing carried the proxy

  // The reproducer reruns the failing stroke's chain and fails at the same tick.
  const MovingStrokeFailure& f = r.failures.front();
  std::FILE* sink = std::tmpfile();
  ASSERT_NE(sink, nullptr);
  const MovingStressReport replay = replay_moving_stroke(scene, object, key, settings, f.stroke, sink);
  std::fclose(sink);
  ASSERT_FALSE(replay.failures.empty());
  EXPECT_EQ(replay.failures.back().stroke, f.stroke);
  EXPECT_EQ(replay.failures.back().tick, f.tick);
  EXPECT_EQ(replay.failures.back().p_W_hip, f.p_W_hip);
}

}  // namespace mhd::stress::test
