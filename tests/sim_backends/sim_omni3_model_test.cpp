#include "sim_omni3_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace mhd::sim_omni3 {
namespace {

constexpr double kPi = std::numbers::pi;

/// Sends `twist_B` at 10 Hz from t_begin_s for duration_s, simulating in between.
void drive(Omni3Model& m, const Twist& twist_B, double t_begin_s, double duration_s) {
  const int commands = static_cast<int>(std::lround(duration_s * 10.0));
  for (int k = 0; k < commands; ++k) {
    const double t = t_begin_s + 0.1 * k;
    m.command(twist_B, t);
    m.simulate_until(t + 0.1);
  }
}

/// The body twist of the base's true motion.
Twist body_velocity(const Omni3Model& m) {
  const Twist v_W = m.velocity_W();
  const double h = m.pose().heading_rad;
  // Inverse of R_y(h): (x, z) -> (c x - s z, s x + c z).
  return {std::cos(h) * v_W[0] - std::sin(h) * v_W[1], std::sin(h) * v_W[0] + std::cos(h) * v_W[1], v_W[2]};
}

TEST(Omni3Kinematics, ForwardIsTheExactInverseOfInverse) {
  const Omni3Kinematics k(0.2, 0.04);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int i = 0; i < 100; ++i) {
    const Twist t(u(rng), u(rng), u(rng));
    EXPECT_LT((k.body_twist(k.wheel_speeds(t)) - t).norm(), 1e-12);
    const WheelSpeeds w(10 * u(rng), 10 * u(rng), 10 * u(rng));
    EXPECT_LT((k.wheel_speeds(k.body_twist(w)) - w).norm(), 1e-11);
  }
}

TEST(Omni3Kinematics, WheelSpeedsOfPureMotions) {
  const Omni3Kinematics k(0.2, 0.04);
  // Turning in place: every rim moves at omega * R.
  const WheelSpeeds spin = k.wheel_speeds({0.0, 0.0, 1.0});
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(spin[i], 0.2 / 0.04, 1e-12);
  // Straight ahead: the front wheel (0) only rolls on its rollers; 1 and 2 turn opposite.
  const WheelSpeeds ahead = k.wheel_speeds({0.5, 0.0, 0.0});
  EXPECT_NEAR(ahead[0], 0.0, 1e-12);
  EXPECT_NEAR(ahead[1], -ahead[2], 1e-12);
  EXPECT_NEAR(std::abs(ahead[1]), 0.5 * std::sin(2 * kPi / 3) / 0.04, 1e-12);
  // Sideways along +z: the front wheel takes it all at speed / r.
  EXPECT_NEAR(k.wheel_speeds({0.0, 0.5, 0.0})[0], -0.5 / 0.04, 1e-12);
}

TEST(Omni3Limits, ScaleTheWholeCommandAndKeepItsDirection) {
  const double max_omega = 40.0 * kPi / 180.0;
  EXPECT_EQ(limit_twist({0.3, 0.1, 0.2}, 0.5, max_omega), Twist(0.3, 0.1, 0.2));
  const Twist fast = limit_twist({0.6, 0.8, 0.0}, 0.5, max_omega);
  EXPECT_TRUE(fast.isApprox(Twist(0.3, 0.4, 0.0), 1e-15));
  const Twist spinning = limit_twist({0.3, 0.4, 2.0}, 0.5, max_omega);  // omega binds
  EXPECT_NEAR(spinning[2], max_omega, 1e-15);
  EXPECT_NEAR(spinning[0] / spinning[1], 0.75, 1e-15);
  EXPECT_NEAR(spinning[0] / spinning[2], 0.15, 1e-15);
}

TEST(Omni3Model, SettlesAtTheLimitedVelocity) {
  Omni3Model m({});
  m.start(0.0);
  drive(m, {2.0, 0.0, 0.0}, 0.0, 2.0);
  EXPECT_NEAR(body_velocity(m)[0], 0.5, 1e-6);
  EXPECT_NEAR(body_velocity(m)[1], 0.0, 1e-12);
  drive(m, {0.0, 0.0, -3.0}, 2.0, 2.0);
  EXPECT_NEAR(m.velocity_W()[2], -40.0 * kPi / 180.0, 1e-6);
  EXPECT_NEAR(std::hypot(m.velocity_W()[0], m.velocity_W()[1]), 0.0, 1e-6);
}

TEST(Omni3Model, TheControllerActsOnlyAtItsFiftyHertzTicks) {
  Omni3Model m({});
  m.start(0.0);
  m.command({0.3, 0.0, 0.0}, 0.005);  // after the tick at 0
  m.simulate_until(0.019);
  EXPECT_TRUE(m.wheel_speeds().isZero(0.0));
  m.simulate_until(0.0215);
  EXPECT_FALSE(m.wheel_speeds().isZero(0.0));
  EXPECT_NEAR(m.time_s(), 0.021, 1e-12);  // the state sits on the 1 ms grid
}

TEST(Omni3Model, AStaleCommandStopsTheBase) {
  Omni3Model m({});
  m.start(0.0);
  m.command({0.3, 0.0, 0.0}, 0.0);
  m.simulate_until(0.2);
  EXPECT_FALSE(m.watchdog_stopped());
  EXPECT_GT(body_velocity(m)[0], 0.2);
  m.simulate_until(0.23);  // the tick at 0.22 finds the command 0.22 s old
  EXPECT_TRUE(m.watchdog_stopped());
  m.simulate_until(1.5);  // the speed loop decays exponentially: zero to within 1e-6
  EXPECT_TRUE(m.velocity_W().isZero(1e-6));
  EXPECT_TRUE(m.wheel_speeds().isZero(1e-6));

  // Commands every 0.15 s keep it going.
  Omni3Model n({});
  n.start(0.0);
  for (int k = 0; k < 12; ++k) {
    n.command({0.3, 0.0, 0.0}, 0.15 * k);
    n.simulate_until(0.15 * (k + 1));
    EXPECT_FALSE(n.watchdog_stopped());
  }
  EXPECT_NEAR(body_velocity(n)[0], 0.3, 1e-9);
}

TEST(Omni3Model, DrivesStraightExactlyWithoutSlip) {
  Omni3Config config;
  config.initial_pose = {1.0, -0.5, 30.0 * kPi / 180.0};
  Omni3Model m(config);
  m.start(10.0);
  drive(m, {0.3, 0.0, 0.0}, 10.0, 2.0);
  drive(m, {0.0, 0.0, 0.0}, 12.0, 1.0);
  // 0.6 m along the heading: the lag at the start and the stop cancel exactly.
  const double h = config.initial_pose.heading_rad;
  EXPECT_NEAR(m.pose().x_m, 1.0 + 0.6 * std::cos(h), 1e-9);
  EXPECT_NEAR(m.pose().z_m, -0.5 - 0.6 * std::sin(h), 1e-9);
  EXPECT_NEAR(m.pose().heading_rad, h, 1e-12);
  EXPECT_TRUE(m.velocity_W().isZero(1e-6));
}

TEST(Omni3Model, DrivesSidewaysExactlyWithoutSlip) {
  Omni3Model m({});
  m.start(0.0);
  drive(m, {0.0, -0.25, 0.0}, 0.0, 2.0);
  drive(m, {0.0, 0.0, 0.0}, 2.0, 1.0);
  EXPECT_NEAR(m.pose().x_m, 0.0, 1e-9);
  EXPECT_NEAR(m.pose().z_m, -0.5, 1e-9);
  EXPECT_NEAR(m.pose().heading_rad, 0.0, 1e-12);
}

TEST(Omni3Model, TurnsInPlaceExactlyWithoutSlip) {
  Omni3Config config;
  config.initial_pose = {0.4, 0.7, 0.0};
  Omni3Model m(config);
  m.start(0.0);
  drive(m, {0.0, 0.0, 0.5}, 0.0, 2.0);
  drive(m, {0.0, 0.0, 0.0}, 2.0, 1.0);
  EXPECT_NEAR(m.pose().heading_rad, 1.0, 1e-9);
  EXPECT_NEAR(m.pose().x_m, 0.4, 1e-12);
  EXPECT_NEAR(m.pose().z_m, 0.7, 1e-12);
  // Turning on past pi wraps the heading into [-pi, pi].
  drive(m, {0.0, 0.0, 0.5}, 3.0, 6.0);
  drive(m, {0.0, 0.0, 0.0}, 9.0, 1.0);
  EXPECT_NEAR(m.pose().heading_rad, 4.0 - 2.0 * kPi, 1e-9);
}

TEST(Omni3Model, OdometryIsTheTruthWithoutSlip) {
  Omni3Model m({});
  m.start(0.0);
  drive(m, {0.3, 0.1, 0.4}, 0.0, 3.0);
  EXPECT_EQ(m.odometry().x_m, m.pose().x_m);
  EXPECT_EQ(m.odometry().z_m, m.pose().z_m);
  EXPECT_EQ(m.odometry().heading_rad, m.pose().heading_rad);
}

TEST(Omni3Model, SlipMakesOdometryDrift) {
  Omni3Config config;
  config.slip_fraction = 0.2;
  config.seed = 7;
  Omni3Model m(config);
  m.start(0.0);
  drive(m, {0.3, 0.0, 0.0}, 0.0, 3.0);
  drive(m, {0.0, 0.0, 0.0}, 3.0, 1.0);
  const double odometry_m = std::hypot(m.odometry().x_m, m.odometry().z_m);
  const double true_m = std::hypot(m.pose().x_m, m.pose().z_m);
  EXPECT_NEAR(odometry_m, 0.9, 1e-6);  // the encoders see the commanded motion
  EXPECT_LT(true_m, 0.9 * 0.95);       // the ground sees less
  EXPECT_GT(true_m, 0.9 * 0.75);
  EXPECT_GT(std::abs(m.pose().heading_rad - m.odometry().heading_rad), 1e-4);  // and some turning

  // The same seed gives the same drift; another seed another.
  Omni3Model same(config);
  same.start(0.0);
  drive(same, {0.3, 0.0, 0.0}, 0.0, 3.0);
  drive(same, {0.0, 0.0, 0.0}, 3.0, 1.0);
  EXPECT_EQ(same.pose().x_m, m.pose().x_m);
  EXPECT_EQ(same.pose().z_m, m.pose().z_m);
  config.seed = 8;
  Omni3Model other(config);
  other.start(0.0);
  drive(other, {0.3, 0.0, 0.0}, 0.0, 3.0);
  EXPECT_NE(other.pose().z_m, m.pose().z_m);
}

TEST(Omni3Model, ResultsDoNotDependOnHowOftenItIsAdvanced) {
  Omni3Config config;
  config.slip_fraction = 0.1;
  Omni3Model coarse(config);
  Omni3Model fine(config);
  coarse.start(0.0);
  fine.start(0.0);
  for (int k = 0; k < 20; ++k) {
    const Twist cmd(0.4, -0.1, 0.3 * std::sin(k));
    coarse.command(cmd, 0.1 * k);
    fine.command(cmd, 0.1 * k);
    coarse.simulate_until(0.1 * (k + 1));
    for (int i = 1; i <= 100; ++i) fine.simulate_until(0.1 * k + 0.001 * i);
  }
  EXPECT_EQ(coarse.pose().x_m, fine.pose().x_m);
  EXPECT_EQ(coarse.pose().heading_rad, fine.pose().heading_rad);
}

TEST(Omni3Model, RejectsBadSettingsAndCommands) {
  Omni3Config config;
  config.wheel_radius_m = 0.0;
  EXPECT_THROW(Omni3Model{config}, std::invalid_argument);
  Omni3Model m({});
  EXPECT_THROW(m.simulate_until(1.0), std::logic_error);
  m.start(0.0);
  EXPECT_THROW(m.command({std::nan(""), 0.0, 0.0}, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace mhd::sim_omni3
