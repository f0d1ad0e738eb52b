#pragma once
// The broken-engine half of the moving and pushed stress tests: the same run with the
// proxy left behind by the moving object (fault_skip_carry) must be caught, and the
// reproducer must replay its first failure at the same tick.

#include "stress/moving_stress_run.h"

#include <cstdint>

namespace mhd::stress::test {

/// Runs `settings` on object `object` of `scene` with the carry skipped and checks, with
/// gtest, that it reports crossings or ticks inside and that replay_moving_stroke fails
/// at the first failure's stroke, tick and HIP.
void expect_skipped_carry_caught_and_replayed(const CompiledScene& scene, int object, std::uint64_t key,
                                              MovingStressSettings settings);

}  // namespace mhd::stress::test
