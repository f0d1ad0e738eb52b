#include "safety/base_command_guard.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace {

using mhd::BaseCommandGuard;
using mhd::BaseGuardAction;
using mhd::BasePose;
using mhd::BaseTwist;

const Eigen::Vector2d kNoUser = Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());

/// World velocity (x, z) of a body twist at heading h: Ry(h) (vx, 0, vz).
Eigen::Vector2d world_velocity(const BaseTwist& t, double h) {
  return {std::cos(h) * t.vx_mps + std::sin(h) * t.vz_mps, -std::sin(h) * t.vx_mps + std::cos(h) * t.vz_mps};
}

TEST(BaseCommandGuard, PassesACommandWithinLimits) {
  BaseCommandGuard guard;
  const auto r = guard.apply({0.2, -0.1, 0.3}, {}, kNoUser, 0.01);
  EXPECT_EQ(r.action, BaseGuardAction::Passed);
  EXPECT_DOUBLE_EQ(r.twist_B.vx_mps, 0.2);
  EXPECT_DOUBLE_EQ(r.twist_B.vz_mps, -0.1);
  EXPECT_DOUBLE_EQ(r.twist_B.omega_radps, 0.3);
}

TEST(BaseCommandGuard, StaleTrackingOrANonFiniteCommandStopsTheBase) {
  BaseCommandGuard guard;
  const auto stale = guard.apply({0.2, 0, 0}, {}, kNoUser, 0.05);
  EXPECT_EQ(stale.action, BaseGuardAction::Stopped);
  EXPECT_EQ(stale.twist_B.vx_mps, 0.0);
  const auto nan = guard.apply({std::numeric_limits<double>::quiet_NaN(), 0, 0}, {}, kNoUser, 0.01);
  EXPECT_EQ(nan.action, BaseGuardAction::Stopped);
  EXPECT_EQ(nan.twist_B.vx_mps, 0.0);
  EXPECT_EQ(nan.twist_B.omega_radps, 0.0);
  EXPECT_EQ(guard.stops(), 2u);
}

TEST(BaseCommandGuard, ScalesIntoTheLimitsKeepingDirectionAndTurnRatio) {
  BaseCommandGuard guard;  // 0.5 m/s, 40 deg/s
  const auto fast = guard.apply({0.6, 0.8, 0.2}, {}, kNoUser, 0.01);  // 1 m/s
  EXPECT_EQ(fast.action, BaseGuardAction::Scaled);
  EXPECT_NEAR(std::hypot(fast.twist_B.vx_mps, fast.twist_B.vz_mps), 0.5, 1e-12);
  EXPECT_NEAR(fast.twist_B.vx_mps / fast.twist_B.vz_mps, 0.75, 1e-12);
  EXPECT_NEAR(fast.twist_B.omega_radps, 0.1, 1e-12);
  const auto spin = guard.apply({0.1, 0, 1.3962634015954636}, {}, kNoUser, 0.01);  // 80 deg/s
  EXPECT_NEAR(spin.twist_B.omega_radps, 40.0 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_NEAR(spin.twist_B.vx_mps, 0.05, 1e-12);
}

TEST(BaseCommandGuard, NeverMovesTowardsAUserInsideTheKeepOutDistance) {
  BaseCommandGuard guard;  // keep-out 0.475 m
  for (const double heading : {0.0, 0.7, 2.0, -2.5}) {
    const BasePose base{1.0, 2.0, heading};
    const Eigen::Vector2d user(1.3, 2.2);  // 0.36 m away
    const Eigen::Vector2d to_user = (user - Eigen::Vector2d(1.0, 2.0)).normalized();
    // A command straight at the user, in the base frame.
    const double c = std::cos(heading), s = std::sin(heading);
    const BaseTwist at_user{0.3 * (c * to_user.x() - s * to_user.y()), 0.3 * (s * to_user.x() + c * to_user.y()), 0.0};
    ASSERT_NEAR(world_velocity(at_user, heading).dot(to_user), 0.3, 1e-12);
    const auto r = guard.apply(at_user, base, user, 0.01);
    EXPECT_EQ(r.action, BaseGuardAction::Deflected);
    EXPECT_NEAR(world_velocity(r.twist_B, heading).dot(to_user), 0.0, 1e-12);
    // Moving away is untouched.
    const BaseTwist away{-at_user.vx_mps, -at_user.vz_mps, 0.0};
    const auto a = guard.apply(away, base, user, 0.01);
    EXPECT_EQ(a.action, BaseGuardAction::Passed);
    EXPECT_NEAR(world_velocity(a.twist_B, heading).dot(to_user), -0.3, 1e-12);
  }
  // Outside the keep-out distance, approaching is allowed.
  const auto far = guard.apply({0.3, 0, 0}, {0, 0, 0}, Eigen::Vector2d(1.0, 0.0), 0.01);
  EXPECT_EQ(far.action, BaseGuardAction::Passed);
}

}  // namespace
