#include "simulation/simulated_user.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <numbers>
#include <stdexcept>
#include <string>

namespace mhd::simulation {
namespace {

constexpr double kPi = std::numbers::pi;

Eigen::Vector2d position(const SimulatedUser& u) { return {u.body().x_m, u.body().z_m}; }
Eigen::Vector2d forward(double heading_rad) { return {std::cos(heading_rad), -std::sin(heading_rad)}; }
Eigen::Vector2d right(double heading_rad) { return {std::sin(heading_rad), std::cos(heading_rad)}; }

std::string error_of(const SimulatedUserConfig& config) {
  try {
    const SimulatedUser user(config);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

/// Largest speed seen between samples 1 ms apart over duration_s.
double max_sampled_speed(SimulatedUser& user, double duration_s) {
  double top = 0.0;
  Eigen::Vector2d last = position(user);
  for (int i = 1; i <= static_cast<int>(duration_s * 1000.0); ++i) {
    user.advance_to(i * 1e-3);
    const Eigen::Vector2d p = position(user);
    top = std::max(top, (p - last).norm() / 1e-3);
    last = p;
  }
  return top;
}

TEST(SimulatedUser, RandomWalkNeverExceedsTheDefaultMaximum) {
  SimulatedUserConfig config;
  config.seed = 3;
  SimulatedUser user(config);
  const double top = max_sampled_speed(user, 120.0);
  EXPECT_LE(top, 1.5 + 1e-9);
  EXPECT_GT(top, 0.75);  // side-steps reach at least half the side-step maximum
}

TEST(SimulatedUser, RandomWalkNeverExceedsALowerConfiguredMaximum) {
  SimulatedUserConfig config;
  config.seed = 11;
  config.max_speed_mps = 0.8;
  config.walk_speed_max_mps = 0.6;
  config.side_step_speed_max_mps = 0.8;
  SimulatedUser user(config);
  EXPECT_LE(max_sampled_speed(user, 120.0), 0.8 + 1e-9);
  EXPECT_LE(user.velocity_W().norm(), 0.8 + 1e-9);
}

TEST(SimulatedUser, SideStepsHappenAndMoveSideways) {
  SimulatedUserConfig config;
  config.seed = 5;
  SimulatedUser user(config);
  double fastest_sideways = 0.0;
  double largest_forward_while_side_stepping = 0.0;
  for (int i = 1; i <= 60000; ++i) {
    user.advance_to(i * 1e-3);
    if (!user.side_stepping()) continue;
    const double h = user.body().heading_rad;
    fastest_sideways = std::max(fastest_sideways, std::abs(user.velocity_W().dot(right(h))));
    largest_forward_while_side_stepping =
        std::max(largest_forward_while_side_stepping, std::abs(user.velocity_W().dot(forward(h))));
  }
  EXPECT_GE(user.side_steps_started(), 3);
  EXPECT_GT(fastest_sideways, 0.75);
  EXPECT_LT(largest_forward_while_side_stepping, 1e-9);
}

TEST(SimulatedUser, RandomWalkStaysNearItsArea) {
  SimulatedUserConfig config;
  config.seed = 9;
  config.area_half_size_m = 2.0;
  SimulatedUser user(config);
  double farthest = 0.0;
  for (int i = 1; i <= 300 * 100; ++i) {
    user.advance_to(i * 0.01);
    farthest = std::max(farthest, position(user).cwiseAbs().maxCoeff());
  }
  // A soft bound: the walk turns back at 3 rad/s and side-steps point inwards.
  EXPECT_LT(farthest, 2.0 + 2.0);
  EXPECT_GT(farthest, 1.0);
}

TEST(SimulatedUser, TheSameSeedGivesTheSameWalkWhateverTheUpdateRate) {
  SimulatedUserConfig config;
  config.seed = 42;
  SimulatedUser fine(config);
  SimulatedUser coarse(config);
  for (int i = 1; i <= 20000; ++i) {
    fine.advance_to(i * 1e-3);
    if (i % 37 == 0 || i % 1000 == 0) {
      coarse.advance_to(i * 1e-3);
      ASSERT_EQ(fine.body().x_m, coarse.body().x_m) << "at " << i * 1e-3 << " s";
      ASSERT_EQ(fine.body().z_m, coarse.body().z_m);
      ASSERT_EQ(fine.body().heading_rad, coarse.body().heading_rad);
      ASSERT_EQ(fine.hand_W(), coarse.hand_W());
    }
  }
  config.seed = 43;
  SimulatedUser other(config);
  other.advance_to(20.0);
  EXPECT_GT((position(other) - position(fine)).norm(), 0.01);
}

TEST(SimulatedUser, WalksAScriptedPathAtItsSpeeds) {
  SimulatedUserConfig config;
  config.path = parse_waypoints("0 0 0; 2 0 1.0; 2 2 0.5");
  SimulatedUser user(config);
  EXPECT_NEAR(user.body().heading_rad, 0.0, 1e-12);  // facing the first leg
  user.advance_to(1.0);
  EXPECT_TRUE(position(user).isApprox(Eigen::Vector2d(1.0, 0.0), 1e-9));
  EXPECT_NEAR(user.velocity_W().norm(), 1.0, 1e-9);
  user.advance_to(4.0);
  EXPECT_LT((position(user) - Eigen::Vector2d(2.0, 1.0)).norm(), 1e-6);
  EXPECT_NEAR(user.velocity_W().norm(), 0.5, 1e-9);
  EXPECT_NEAR(user.body().heading_rad, -kPi / 2, 1e-9);  // turned to face +z
  EXPECT_FALSE(user.path_finished());
  user.advance_to(6.1);
  EXPECT_TRUE(user.path_finished());
  EXPECT_EQ(position(user), Eigen::Vector2d(2.0, 2.0));
  EXPECT_EQ(user.velocity_W(), Eigen::Vector2d::Zero());
}

TEST(SimulatedUser, LoopsAPathWhenAsked) {
  SimulatedUserConfig config;
  config.path = parse_waypoints("0 0 1; 1 0 1");
  config.loop_path = true;
  SimulatedUser user(config);
  user.advance_to(1.5);
  EXPECT_LT((position(user) - Eigen::Vector2d(0.5, 0.0)).norm(), 1e-6);
  user.advance_to(2.25);
  EXPECT_LT((position(user) - Eigen::Vector2d(0.25, 0.0)).norm(), 1e-6);
  EXPECT_FALSE(user.path_finished());
}

TEST(SimulatedUser, RejectsAPathFasterThanTheMaximum) {
  SimulatedUserConfig config;
  config.path = parse_waypoints("0 0 0; 1 0 2");
  EXPECT_EQ(error_of(config), "waypoint 2: speed 2 m/s is above max_speed_mps 1.5");
  config.path = parse_waypoints("0 0 0; 1 0 0");
  EXPECT_EQ(error_of(config), "waypoint 2: speed must be positive, got 0");
  config.path = parse_waypoints("1 1 1; 1 1 1");
  config.loop_path = true;
  EXPECT_EQ(error_of(config), "a looping path needs two different waypoints");
  config.path = parse_waypoints("0 0 0; 1 0 1");
  config.loop_path = false;
  config.side_step_probability = 0.9;
  EXPECT_EQ(error_of(config), "side_step_probability and stand_probability must be >= 0 with a sum <= 1");
}

TEST(ParseWaypoints, ReadsAndRejects) {
  const auto path = parse_waypoints(" 0 0 0 ;2\t-1.5 0.8; ");
  ASSERT_EQ(path.size(), 2u);
  EXPECT_EQ(path[1].x_m, 2.0);
  EXPECT_EQ(path[1].z_m, -1.5);
  EXPECT_EQ(path[1].speed_mps, 0.8);

  const auto message = [](const char* text) -> std::string {
    try {
      (void)parse_waypoints(text);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(message("1 2"), "waypoint 1: expected 'x z speed_mps', got '1 2'");
  EXPECT_EQ(message("0 0 0; a b c"), "waypoint 2: expected 'x z speed_mps', got 'a b c'");
  EXPECT_EQ(message("0 0 0 0"), "waypoint 1: expected 'x z speed_mps', got '0 0 0 0'");
  EXPECT_EQ(message("0 0 0;; 1 1 1"), "waypoint 2: expected 'x z speed_mps', got ''");
  EXPECT_EQ(message(""), "no waypoints");
}

TEST(SimulatedUser, HeadIsAtEyeHeightFacingTheWalkingDirection) {
  SimulatedUserConfig config;
  config.path = parse_waypoints("0 0 0; 0 2 1");  // towards +z
  SimulatedUser user(config);
  user.advance_to(1.0);
  const HeadPose head = user.head();
  EXPECT_NEAR(head.p_W_m.y(), 1.65, 1e-12);
  EXPECT_TRUE((head.q_W * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitZ(), 1e-9));
  EXPECT_TRUE((head.q_W * Eigen::Vector3d::UnitY()).isApprox(Eigen::Vector3d::UnitY(), 1e-9));
}

TEST(SimulatedUser, HeadFacesAFixedTargetWhenGiven) {
  SimulatedUserConfig config;
  config.seed = 2;
  config.gaze_target_W = Eigen::Vector3d(1.0, 0.9, -0.5);
  SimulatedUser user(config);
  for (double t : {0.5, 3.0, 7.5}) {
    user.advance_to(t);
    const HeadPose head = user.head();
    const Eigen::Vector3d to_target = (*config.gaze_target_W - head.p_W_m).normalized();
    EXPECT_TRUE((head.q_W * Eigen::Vector3d::UnitX()).isApprox(to_target, 1e-9)) << "at " << t << " s";
  }
}

TEST(SimulatedUser, HoldsTheHandAtArmsReachInFrontOfTheChest) {
  SimulatedUserConfig config;
  config.seed = 8;
  SimulatedUser user(config);
  for (int i = 1; i <= 3000; ++i) {
    user.advance_to(i * 0.01);
    const Eigen::Vector3d hand = user.hand_W();
    const PlanarPose body = user.body();
    const Eigen::Vector2d offset(hand.x() - body.x_m, hand.z() - body.z_m);
    ASSERT_GE(hand.y(), 1.0);
    ASSERT_LE(hand.y(), 1.2);
    ASSERT_NEAR(offset.dot(forward(body.heading_rad)), 0.45, 0.04);
    ASSERT_LE(std::abs(offset.dot(right(body.heading_rad))), 0.04);
  }
}

TEST(SimulatedUser, UpdateWritesHeadAndHandIntoTheWorld) {
  SimulatedWorld world;
  SimulatedUserConfig config;
  config.seed = 1;
  SimulatedUser user(config);
  user.update(2.5, world);
  EXPECT_EQ(world.hand(), user.hand_W());
  EXPECT_EQ(world.head().p_W_m, user.head().p_W_m);
  EXPECT_TRUE(world.head().q_W.isApprox(user.head().q_W, 1e-15));
}

TEST(SimulatedUser, ACrouchingAndReachingUserSweepsTheHandsHeightAndCrouchesForTheLowHand) {
  SimulatedUserConfig c;
  c.path = {{0.0, 0.0, 0.0}};
  c.hand_motion_amplitude_m = 0.0;
  c.hand_height_sweep = HandHeightSweep{0.3, 1.9, 0.4, 0.5};  // legs of 4 s, holds of 0.5 s
  SimulatedUser user(c);
  double lowest = 10.0, highest = 0.0, fastest = 0.0, lowest_eyes = 10.0;
  double last = user.hand_W().y();
  for (int i = 1; i <= 18000; ++i) {  // two whole sweeps of 9 s
    user.advance_to(i * 1e-3);
    const double y = user.hand_W().y();
    lowest = std::min(lowest, y);
    highest = std::max(highest, y);
    fastest = std::max(fastest, std::abs(y - last) / 1e-3);
    lowest_eyes = std::min(lowest_eyes, user.head().p_W_m.y());
    // The eyes stay between a crouch (1 m) and standing height.
    ASSERT_GE(user.head().p_W_m.y(), 1.0);
    ASSERT_LE(user.head().p_W_m.y(), c.eye_height_m);
    last = y;
  }
  EXPECT_DOUBLE_EQ(lowest, 0.3);
  EXPECT_DOUBLE_EQ(highest, 1.9);
  EXPECT_NEAR(fastest, 0.4, 1e-9);  // continuous: no step between ticks
  EXPECT_DOUBLE_EQ(lowest_eyes, 1.0);
  // At 2.5 s the hand is half-way up (0.5 s hold, then 2 s at 0.4 m/s), and standing eyes
  // come back once the hand is 0.7 m below them.
  EXPECT_NEAR(hand_height_at(c.hand_height_sweep, 1.1, 2.5), 1.1, 1e-12);
  EXPECT_DOUBLE_EQ(eye_height_at(1.65, 0.95), 1.65);
  EXPECT_DOUBLE_EQ(eye_height_at(1.65, 0.5), 1.2);
  // The dual: without a sweep the hand holds hand_height_m.
  EXPECT_DOUBLE_EQ(hand_height_at(std::nullopt, 1.1, 3.0), 1.1);
}

TEST(SimulatedUser, RefusesASweepThatIsNoRange) {
  for (const HandHeightSweep& bad : {HandHeightSweep{1.0, 0.5, 0.3, 1.0}, HandHeightSweep{0.0, 1.0, 0.3, 1.0},
                                     HandHeightSweep{0.3, 1.9, 0.0, 1.0}, HandHeightSweep{0.3, 1.9, 0.3, -1.0},
                                     HandHeightSweep{std::nan(""), 1.9, 0.3, 1.0}}) {
    SimulatedUserConfig c;
    c.hand_height_sweep = bad;
    EXPECT_NE(error_of(c), "") << bad.low_m << " " << bad.high_m;
  }
  SimulatedUserConfig good;
  good.hand_height_sweep = HandHeightSweep{};
  EXPECT_EQ(error_of(good), "");
}

}  // namespace
}  // namespace mhd::simulation
