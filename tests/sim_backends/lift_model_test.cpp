// The simulated lift (plugins/base/sim_omni3/lift_model.h), swept over
// commands, steps and end stops: it never leaves its range, its speed or its
// acceleration limit; it reaches an end stop at rest; it follows a command; and
// its watchdog brakes it to a stop and lets a fresh command move it again.
#include "lift_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace {

using mhd::sim_omni3::LiftConfig;
using mhd::sim_omni3::LiftModel;

LiftConfig config() {
  LiftConfig c;
  c.min_m = -0.7;
  c.max_m = 0.9;
  c.max_speed_mps = 0.3;
  c.max_acceleration_mps2 = 1.5;
  c.command_timeout_s = 0.2;
  return c;
}

TEST(LiftModel, NeverLeavesItsRangeSpeedOrAccelerationWhateverItIsCommanded) {
  std::mt19937_64 rng(20261129);
  std::uniform_real_distribution<double> command(-3.0, 3.0);
  std::uniform_real_distribution<double> gap(0.001,
                                             0.4);  // also past the watchdog
  LiftModel lift(config());
  lift.start(0.0);
  long step = 0;  // of 1 ms, the model's own grid: one step per check
  double v_before = 0.0;
  for (int i = 0; i < 20000; ++i) {
    lift.command(command(rng), static_cast<double>(step) * 1e-3);
    const long until = step + static_cast<long>(gap(rng) * 1000.0);
    for (; step < until; ++step) {
      const double t_s = static_cast<double>(step + 1) * 1e-3;
      lift.simulate_until(t_s);
      ASSERT_GE(lift.height_m(), -0.7);
      ASSERT_LE(lift.height_m(), 0.9);
      ASSERT_LE(std::abs(lift.velocity_mps()), 0.3 + 1e-12);
      // Only an end stop may halt it faster than its acceleration allows.
      const bool on_a_stop = lift.height_m() == -0.7 || lift.height_m() == 0.9;
      if (!on_a_stop) {
        ASSERT_LE(std::abs(lift.velocity_mps() - v_before), 1.5 * 0.001 + 1e-9) << "at " << t_s;
      }
      v_before = lift.velocity_mps();
    }
  }
}

TEST(LiftModel, ReachesEachEndStopAtRestAndStaysThere) {
  for (const double v_mps : {0.3, -0.3}) {
    LiftModel lift(config());
    lift.start(0.0);
    double fastest_near_stop = 0.0;
    for (int k = 1; k <= 800; ++k) {  // commanded at 100 Hz, as a base's io
                                      // thread does: simulated up to now first
      const double t_s = 0.01 * k;
      lift.simulate_until(t_s);
      lift.command(v_mps, t_s);
      const double room_m = v_mps > 0 ? 0.9 - lift.height_m() : lift.height_m() + 0.7;
      if (room_m < 0.005) fastest_near_stop = std::max(fastest_near_stop, std::abs(lift.velocity_mps()));
    }
    EXPECT_DOUBLE_EQ(lift.height_m(), v_mps > 0 ? 0.9 : -0.7);
    EXPECT_EQ(lift.velocity_mps(), 0.0);
    // Braked ahead of the stop: within 5 mm of it, at most what stops within
    // that room.
    EXPECT_LT(fastest_near_stop, std::sqrt(2.0 * 1.5 * 0.005) + 1.5 * 0.001);
  }
}

TEST(LiftModel, FollowsACommandedSpeed) {
  LiftModel lift(config());
  lift.start(0.0);
  for (int k = 0; k <= 20; ++k) {
    const double t_s = 0.05 * k;
    lift.simulate_until(t_s);
    lift.command(0.1, t_s);
  }
  lift.simulate_until(1.0 + 1e-9);
  EXPECT_NEAR(lift.velocity_mps(), 0.1, 1e-9);
  // 0.1 m/s reached after 1/15 s of acceleration: about 0.1 m less 3.3 mm.
  EXPECT_NEAR(lift.height_m(), 0.1 - 0.5 * 0.1 * 0.1 / 1.5, 2e-3);
}

TEST(LiftModel, ItsWatchdogBrakesItToAStopAndAFreshCommandMovesItAgain) {
  LiftModel lift(config());
  lift.start(0.0);
  lift.command(0.3, 0.0);
  lift.simulate_until(0.19);
  EXPECT_FALSE(lift.watchdog_stopped());
  EXPECT_GT(lift.velocity_mps(), 0.2);
  lift.simulate_until(0.6);  // the command expired at 0.2 s; 0.3 m/s brakes away in 0.2 s
  EXPECT_TRUE(lift.watchdog_stopped());
  EXPECT_EQ(lift.velocity_mps(), 0.0);
  const double stopped_at_m = lift.height_m();
  lift.simulate_until(1.0);
  EXPECT_EQ(lift.height_m(), stopped_at_m);
  lift.command(-0.2, 1.0);
  lift.simulate_until(1.15);  // within the command's 0.2 s
  EXPECT_FALSE(lift.watchdog_stopped());
  EXPECT_LT(lift.height_m(), stopped_at_m);
}

TEST(LiftModel, RefusesBadSettingsAndCommandsAndAcceptsGoodOnes) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double LiftConfig::*field : {&LiftConfig::max_speed_mps, &LiftConfig::max_acceleration_mps2,
                                    &LiftConfig::command_timeout_s, &LiftConfig::physics_step_s}) {
    for (const double bad : {nan, inf, -inf, 0.0, -1.0}) {
      LiftConfig c = config();
      c.*field = bad;
      EXPECT_THROW(LiftModel{c}, std::invalid_argument) << bad;
    }
  }
  for (const auto &[min_m, max_m] : {std::pair{0.1, 0.9}, {-0.7, -0.1}, {0.0, 0.0}, {nan, 0.9}, {-0.7, inf}}) {
    LiftConfig c = config();
    c.min_m = min_m;
    c.max_m = max_m;
    EXPECT_THROW(LiftModel{c}, std::invalid_argument) << min_m << " " << max_m;
  }
  LiftConfig outside = config();
  outside.initial_m = 1.0;
  EXPECT_THROW(LiftModel{outside}, std::invalid_argument);
  LiftModel lift(config());
  lift.start(0.0);
  EXPECT_THROW(lift.command(nan, 0.0), std::invalid_argument);
  EXPECT_THROW(lift.command(0.1, inf), std::invalid_argument);
  // The dual: one end of the range at 0 is a lift too, and a good command is
  // taken.
  LiftConfig at_bottom = config();
  at_bottom.min_m = 0.0;
  EXPECT_NO_THROW(LiftModel{at_bottom});
  EXPECT_NO_THROW(lift.command(0.1, 0.0));
}

}  // namespace
