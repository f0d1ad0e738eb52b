// When the io thread writes a base command, decided alone: at the base rate (feeding the
// base's watchdog) while nothing changes, at once for a new plan, and at once when the
// guard turns a moving command into a stop, but not again for every io tick of a stop.
#include "haptic_server/base_command_scheduler.h"

#include <gtest/gtest.h>

namespace {

using namespace mhd;

constexpr double kBasePeriod_s = 0.125;  // 8 Hz: exact in binary, so the period boundary is too
constexpr BaseTwist kMoving{0.2, 0.0, 0.1};
constexpr BaseTwist kStop{};

TEST(BaseCommandScheduler, SendsTheFirstCommandAtOnce) {
  const BaseCommandScheduler scheduler(kBasePeriod_s);
  EXPECT_TRUE(scheduler.should_send(0.0, false, kMoving));
  EXPECT_TRUE(scheduler.should_send(123.4, false, kStop));
}

TEST(BaseCommandScheduler, SendsAnUnchangedCommandAtTheBaseRateOnly) {
  BaseCommandScheduler scheduler(kBasePeriod_s);
  scheduler.sent(10.0, kMoving);
  EXPECT_FALSE(scheduler.should_send(10.001, false, kMoving));
  EXPECT_FALSE(scheduler.should_send(10.124, false, kMoving));
  EXPECT_TRUE(scheduler.should_send(10.125, false, kMoving));  // feeds the base's watchdog
  // A held stop goes out at the base rate too.
  scheduler.sent(10.125, kStop);
  EXPECT_FALSE(scheduler.should_send(10.2, false, kStop));
  EXPECT_TRUE(scheduler.should_send(10.25, false, kStop));
}

TEST(BaseCommandScheduler, SendsANewPlanAtOnce) {
  BaseCommandScheduler scheduler(kBasePeriod_s);
  scheduler.sent(10.0, kMoving);
  EXPECT_TRUE(scheduler.should_send(10.001, true, kMoving));
}

TEST(BaseCommandScheduler, StopsAtOnceWhenTheGuardZeroesAMovingCommand) {
  BaseCommandScheduler scheduler(kBasePeriod_s);
  scheduler.sent(10.0, kMoving);
  EXPECT_TRUE(scheduler.should_send(10.001, false, kStop));
  scheduler.sent(10.001, kStop);
  // Stopped: the next io ticks of the same stop wait for the base rate.
  EXPECT_FALSE(scheduler.should_send(10.002, false, kStop));
  // Moving again waits for the rate (or a new plan); only stopping is urgent.
  EXPECT_FALSE(scheduler.should_send(10.003, false, kMoving));
}

TEST(BaseCommandScheduler, ShouldSendIsPure) {
  BaseCommandScheduler scheduler(kBasePeriod_s);
  scheduler.sent(10.0, kMoving);
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(scheduler.should_send(10.001, false, kStop));
}

TEST(BaseCommandScheduler, AStopIsZeroInAllThreeComponents) {
  EXPECT_TRUE(BaseCommandScheduler::is_stop(kStop));
  EXPECT_FALSE(BaseCommandScheduler::is_stop({0.0, 0.0, 1e-9}));
  EXPECT_FALSE(BaseCommandScheduler::is_stop({0.0, -0.1, 0.0}));
  EXPECT_TRUE(BaseCommandScheduler::is_stop({-0.0, 0.0, 0.0}));
}

}  // namespace
