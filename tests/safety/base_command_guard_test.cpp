#include "safety/base_command_guard.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace {

using mhd::BaseCommandGuard;
using mhd::BaseCommandGuardSettings;
using mhd::BaseGuardAction;
using mhd::BaseGuardInput;
using mhd::BasePose;
using mhd::BaseStopCause;
using mhd::BaseTwist;

constexpr double kInf = std::numeric_limits<double>::infinity();
const Eigen::Vector2d kFarUser(100.0, 100.0);

/// Base and head measured `age_s` ago (both), at time t_s.
BaseGuardInput input(const BasePose& base, const Eigen::Vector2d& user, double age_s, double t_s = 0.0) {
  BaseGuardInput in;
  in.t_s = t_s;
  in.X_WB = base;
  in.base_age_s = age_s;
  in.p_W_head_xz_m = user;
  in.head_age_s = age_s;
  return in;
}

/// Exact keep-out (no margin for ages or command hold).
BaseCommandGuardSettings exact_keep_out() {
  BaseCommandGuardSettings s;
  s.command_hold_s = 0.0;
  return s;
}

/// World velocity (x, z) of a body twist at heading h: Ry(h) (vx, 0, vz).
Eigen::Vector2d world_velocity(const BaseTwist& t, double h) {
  return {std::cos(h) * t.vx_mps + std::sin(h) * t.vz_mps, -std::sin(h) * t.vx_mps + std::cos(h) * t.vz_mps};
}

TEST(BaseCommandGuard, PassesACommandWithinLimits) {
  BaseCommandGuard guard;
  const auto r = guard.apply({0.2, -0.1, 0.3}, input({}, kFarUser, 0.01));
  EXPECT_EQ(r.action, BaseGuardAction::Passed);
  EXPECT_DOUBLE_EQ(r.twist_B.vx_mps, 0.2);
  EXPECT_DOUBLE_EQ(r.twist_B.vz_mps, -0.1);
  EXPECT_DOUBLE_EQ(r.twist_B.omega_radps, 0.3);
}

TEST(BaseCommandGuard, StaleTrackingOrANonFiniteCommandStopsTheBase) {
  BaseCommandGuard guard;
  const auto stale = guard.apply({0.2, 0, 0}, input({}, kFarUser, 0.05));
  EXPECT_EQ(stale.action, BaseGuardAction::Stopped);
  EXPECT_EQ(stale.twist_B.vx_mps, 0.0);
  const auto nan = guard.apply({std::numeric_limits<double>::quiet_NaN(), 0, 0}, input({}, kFarUser, 0.01));
  EXPECT_EQ(nan.action, BaseGuardAction::Stopped);
  EXPECT_EQ(nan.twist_B.vx_mps, 0.0);
  EXPECT_EQ(nan.twist_B.omega_radps, 0.0);
  EXPECT_EQ(guard.counts().base_stale, 1u);
  EXPECT_EQ(guard.counts().not_finite, 1u);
  EXPECT_EQ(guard.counts().stops(), 2u);
}

TEST(BaseCommandGuard, ScalesIntoTheLimitsKeepingDirectionAndTurnRatio) {
  BaseCommandGuard guard;  // 0.5 m/s, 40 deg/s
  const auto fast = guard.apply({0.6, 0.8, 0.2}, input({}, kFarUser, 0.01));  // 1 m/s
  EXPECT_EQ(fast.action, BaseGuardAction::Scaled);
  EXPECT_NEAR(std::hypot(fast.twist_B.vx_mps, fast.twist_B.vz_mps), 0.5, 1e-12);
  EXPECT_NEAR(fast.twist_B.vx_mps / fast.twist_B.vz_mps, 0.75, 1e-12);
  EXPECT_NEAR(fast.twist_B.omega_radps, 0.1, 1e-12);
  const auto spin = guard.apply({0.1, 0, 1.3962634015954636}, input({}, kFarUser, 0.01));  // 80 deg/s
  EXPECT_NEAR(spin.twist_B.omega_radps, 40.0 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_NEAR(spin.twist_B.vx_mps, 0.05, 1e-12);
}

TEST(BaseCommandGuard, NeverMovesTowardsAUserInsideTheKeepOutDistance) {
  BaseCommandGuard guard(exact_keep_out());  // keep-out 0.475 m, fresh data: no margin
  for (const double heading : {0.0, 0.7, 2.0, -2.5}) {
    const BasePose base{1.0, 2.0, heading};
    const Eigen::Vector2d user(1.3, 2.2);  // 0.36 m away
    const Eigen::Vector2d to_user = (user - Eigen::Vector2d(1.0, 2.0)).normalized();
    // A command straight at the user, in the base frame.
    const double c = std::cos(heading), s = std::sin(heading);
    const BaseTwist at_user{0.3 * (c * to_user.x() - s * to_user.y()), 0.3 * (s * to_user.x() + c * to_user.y()), 0.0};
    ASSERT_NEAR(world_velocity(at_user, heading).dot(to_user), 0.3, 1e-12);
    const auto r = guard.apply(at_user, input(base, user, 0.0));
    EXPECT_EQ(r.action, BaseGuardAction::Deflected);
    EXPECT_NEAR(world_velocity(r.twist_B, heading).dot(to_user), 0.0, 1e-12);
    // Moving away is untouched.
    const BaseTwist away{-at_user.vx_mps, -at_user.vz_mps, 0.0};
    const auto a = guard.apply(away, input(base, user, 0.0));
    EXPECT_EQ(a.action, BaseGuardAction::Passed);
    EXPECT_NEAR(world_velocity(a.twist_B, heading).dot(to_user), -0.3, 1e-12);
  }
  // Outside the keep-out distance, approaching is allowed.
  const auto far = guard.apply({0.3, 0, 0}, input({0, 0, 0}, Eigen::Vector2d(1.0, 0.0), 0.01));
  EXPECT_EQ(far.action, BaseGuardAction::Passed);
}

TEST(BaseCommandGuard, StaleOrUnknownHeadDataStopsTheBaseAndCountsTheCause) {
  BaseCommandGuard guard;
  BaseGuardInput in = input({}, kFarUser, 0.01, 1.0);
  in.head_age_s = 0.05;  // as old as the base sensor's timeout
  const auto stale = guard.apply({0.2, 0, 0.1}, in);
  EXPECT_EQ(stale.action, BaseGuardAction::Stopped);
  EXPECT_EQ(stale.stop_cause, BaseStopCause::HeadStale);
  EXPECT_EQ(stale.twist_B.vx_mps, 0.0);
  EXPECT_EQ(stale.twist_B.omega_radps, 0.0);
  in.head_age_s = kInf;  // never measured: the same episode
  EXPECT_EQ(guard.apply({0.2, 0, 0}, in).stop_cause, BaseStopCause::HeadStale);
  in.head_age_s = 0.01;
  in.p_W_head_xz_m = Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(guard.apply({0.2, 0, 0}, in).stop_cause, BaseStopCause::HeadStale);
  EXPECT_EQ(guard.counts().head_stale, 1u);
  EXPECT_EQ(guard.counts().base_stale, 0u);
  EXPECT_EQ(guard.counts().stops(), 1u);
}

TEST(BaseCommandGuard, ResumesWithLimitsRampingBackAfterAStop) {
  BaseCommandGuard guard;  // resume over 0.5 s
  BaseGuardInput in = input({}, kFarUser, 0.01, 1.0);
  in.head_age_s = 0.2;
  (void)guard.apply({0.4, 0, 0}, in);
  in.head_age_s = 0.01;
  EXPECT_EQ(guard.apply({0.4, 0, 0}, in).twist_B.vx_mps, 0.0);  // the first fresh command: still zero
  in.t_s = 1.125;
  const auto quarter = guard.apply({0.4, 0, 0.4}, in);
  EXPECT_EQ(quarter.action, BaseGuardAction::Scaled);
  EXPECT_NEAR(quarter.twist_B.vx_mps, 0.125, 1e-12);  // a quarter of 0.5 m/s
  EXPECT_NEAR(quarter.twist_B.omega_radps, 0.125, 1e-12);
  in.t_s = 1.5;
  const auto full = guard.apply({0.4, 0, 0.4}, in);
  EXPECT_EQ(full.action, BaseGuardAction::Passed);
  EXPECT_DOUBLE_EQ(full.twist_B.vx_mps, 0.4);
  EXPECT_EQ(guard.counts().head_stale, 1u);
}

TEST(BaseCommandGuard, OlderDataWidensTheKeepOutToWhereTheUserMayBe) {
  BaseCommandGuard guard;  // user up to 1.5 m/s, base 0.5 m/s, 1 ms hold
  const BasePose base{0.0, 0.0, 0.0};
  const Eigen::Vector2d user(0.52, 0.0);  // outside 0.475 m
  // 29 ms old: the margin is 1.5 * 0.03 + 0.5 * 0.03 = 0.06 m, so the user may be 0.46 m away.
  const auto r = guard.apply({0.3, 0.0, 0.0}, input(base, user, 0.029));
  EXPECT_EQ(r.action, BaseGuardAction::Deflected);
  EXPECT_EQ(r.twist_B.vx_mps, 0.0);
  // Sideways past the user: bent away from every place the user may be (0.06 m around).
  const auto side = guard.apply({0.0, 0.3, 0.0}, input(base, user, 0.029));
  EXPECT_EQ(side.action, BaseGuardAction::Deflected);
  const double sin_theta = 0.06 / 0.52;
  for (const double angle : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
    const double phi = angle * std::asin(sin_theta);
    EXPECT_LE(world_velocity(side.twist_B, 0.0).dot(Eigen::Vector2d(std::cos(phi), std::sin(phi))), 1e-12);
  }
  EXPECT_GT(std::abs(side.twist_B.vz_mps), 0.25);
  // With fresh data the same place is outside the zone.
  BaseCommandGuard exact(exact_keep_out());
  EXPECT_EQ(exact.apply({0.3, 0.0, 0.0}, input(base, user, 0.0)).action, BaseGuardAction::Passed);
  // Closer than the margin: no linear motion at all, turning allowed.
  const auto close = guard.apply({-0.3, 0.1, 0.2}, input(base, Eigen::Vector2d(0.05, 0.0), 0.029));
  EXPECT_EQ(close.twist_B.vx_mps, 0.0);
  EXPECT_EQ(close.twist_B.vz_mps, 0.0);
  EXPECT_DOUBLE_EQ(close.twist_B.omega_radps, 0.2);
  EXPECT_EQ(guard.counts().keep_out_deflections, 3u);
}

}  // namespace
