// Keep-out on fresh data only: the predictive planner and the
// BaseCommandGuard, stepped as the server's io thread steps them (guard every 1 ms, plan
// every 0.1 s), on random users (mhd::simulation::SimulatedUser) whose head and base
// tracker samples (120 Hz each) drop out for random windows of 5 ms to 2 s.
//
// Judged on the TRUE head, not the tracked one: over each 1 ms step the base, moved by
// its own command with the head held where it truly was, never ends inside keep_out_m of
// the head nearer than it started (a user walking into a base cannot be prevented; that
// is the user's motion, not the base's). And every command is zero while the head or
// the base data is stale. The dual: with fresh data the base follows the user.
// MHD_KEEP_OUT_WALKS sets the number of walks (default 1500 of 8 s; 10000 on request).

#include "kinematics/base_pose.h"
#include "planner/planner.h"
#include "planner/planner_geometry.h"
#include "safety/base_command_guard.h"
#include "simulation/simulated_user.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

namespace mhd {
namespace {

constexpr double kIoStep_s = 0.001;
constexpr double kSamplePeriod_s = 1.0 / 120.0;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Window {
  double start_s = 0.0, end_s = 0.0;
};

bool in_any(const std::vector<Window>& windows, double t_s) {
  return std::any_of(windows.begin(), windows.end(), [&](const Window& w) { return t_s >= w.start_s && t_s < w.end_s; });
}

struct WalkCounts {
  std::int64_t walks = 0, steps = 0, stale_steps = 0, fresh_steps = 0;
  std::int64_t intrusions = 0;            ///< the base moved itself into (or deeper into) the keep-out of the true head
  std::int64_t moving_while_stale = 0;    ///< a non-zero command on stale data
  std::int64_t moving_fresh_steps = 0;    ///< fresh data and a non-zero command
  std::int64_t hip_usable_fresh_ticks = 0, fresh_ticks = 0;
  double min_true_distance_m = kInf;      ///< after the base's own step
};

/// One simulated session: the user, the base, the tracker's view, planner and guard.
class DropoutSession {
 public:
  DropoutSession(std::uint64_t seed, std::vector<Window> head_out, std::vector<Window> base_out,
                 simulation::SimulatedUserConfig config)
      : user_(config), head_out_(std::move(head_out)), base_out_(std::move(base_out)),
        planner_(make_planner(PlannerKind::Predictive, settings_)), guard_(guard_settings()) {
    (void)seed;
  }
  static BaseCommandGuardSettings guard_settings() {
    BaseCommandGuardSettings g;
    g.keep_out_m = PlannerSettings{}.collision_radius_m();
    g.command_hold_s = kIoStep_s;
    return g;
  }
  void place_base(const BasePose& X_WB) { base_ = X_WB; }
  const simulation::SimulatedUser& user() const { return user_; }
  const BasePose& base() const { return base_; }
  const BaseCommandGuard& guard() const { return guard_; }
  bool hip_in_usable() const { return last_plan_.hip_in_usable; }
  const BaseTwist& command() const { return command_; }

  /// One 1 ms io step from t_s.
  void step(double t_s, WalkCounts& counts) {
    user_.advance_to(t_s);
    const Eigen::Vector3d p_W_head = user_.head().p_W_m;
    const Eigen::Vector2d head_true(p_W_head.x(), p_W_head.z());
    if (t_s >= next_sample_s_) {  // both sensors sample together, each unless dropped out
      next_sample_s_ += kSamplePeriod_s;
      if (!in_any(head_out_, t_s)) {
        head_sample_t_s_ = t_s;
        head_xz_ = head_true;
        head_velocity_ = user_.velocity_W();
      }
      if (!in_any(base_out_, t_s)) {
        base_sample_t_s_ = t_s;
        base_seen_ = base_;
      }
    }
    const double head_age_s = t_s - head_sample_t_s_, base_age_s = t_s - base_sample_t_s_;
    const bool stale = !(head_age_s < guard_.settings().tracker_timeout_s && base_age_s < guard_.settings().tracker_timeout_s);
    if (t_s >= next_plan_s_) {
      next_plan_s_ += settings_.command_period_s;
      planned_ = BaseTwist{};
      if (!stale) {  // the server's scene planner: hold still on stale inputs
        PlannerInput in;
        in.time_s = t_s;
        in.base = base_seen_;
        in.user_W = head_xz_;
        in.user_heading_rad = user_.body().heading_rad;
        in.user_velocity_W = head_velocity_;
        in.p_W_hip = user_.hand_W();
        last_plan_ = planner_->update(in);
        planned_ = last_plan_.twist_B;
        ++counts.fresh_ticks;
        if (last_plan_.hip_in_usable) ++counts.hip_usable_fresh_ticks;
      }
    }
    BaseGuardInput judged;
    judged.t_s = t_s;
    judged.X_WB = base_seen_;
    judged.base_age_s = base_age_s;
    judged.p_W_head_xz_m = head_xz_;
    judged.head_age_s = head_age_s;
    command_ = guard_.apply(planned_, judged).twist_B;
    const bool moving = command_.vx_mps != 0.0 || command_.vz_mps != 0.0 || command_.omega_radps != 0.0;

    const double d0 = (Eigen::Vector2d(base_.x_m, base_.z_m) - head_true).norm();
    base_ = integrate_twist(base_, command_, kIoStep_s);
    const double d1 = (Eigen::Vector2d(base_.x_m, base_.z_m) - head_true).norm();
    ++counts.steps;
    if (stale) {
      ++counts.stale_steps;
      if (moving) ++counts.moving_while_stale;
    } else {
      ++counts.fresh_steps;
      if (moving) ++counts.moving_fresh_steps;
    }
    if (moving && d1 < guard_.settings().keep_out_m && d1 < d0 - 1e-12) ++counts.intrusions;
    if (moving) counts.min_true_distance_m = std::min(counts.min_true_distance_m, d1);
  }

 private:
  PlannerSettings settings_;
  simulation::SimulatedUser user_;
  std::vector<Window> head_out_, base_out_;
  std::unique_ptr<Planner> planner_;
  BaseCommandGuard guard_;
  BasePose base_, base_seen_;
  double next_sample_s_ = 0.0, next_plan_s_ = 0.0;
  double head_sample_t_s_ = -kInf, base_sample_t_s_ = -kInf;
  Eigen::Vector2d head_xz_ = Eigen::Vector2d::Zero(), head_velocity_ = Eigen::Vector2d::Zero();
  BaseTwist planned_, command_;
  PlannerOutput last_plan_;
};

int walk_count() {
  if (const char* env = std::getenv("MHD_KEEP_OUT_WALKS")) {
    const int n = std::atoi(env);
    if (n > 0) return n;
  }
  return 1500;
}

std::vector<Window> random_dropouts(std::mt19937_64& rng, double duration_s) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Window> out;
  const int n = static_cast<int>(unit(rng) * 3.0);  // 0, 1 or 2 windows
  for (int i = 0; i < n; ++i) {
    const double start_s = 0.3 + unit(rng) * (duration_s - 0.3);
    const double length_s = 0.005 * std::pow(400.0, unit(rng));  // 5 ms .. 2 s, log-uniform
    out.push_back({start_s, start_s + length_s});
  }
  return out;
}

void run_walk(std::uint64_t seed, double duration_s, WalkCounts& counts) {
  std::mt19937_64 rng(seed * 104729u + 7u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  simulation::SimulatedUserConfig config;
  config.seed = seed;
  config.start.heading_rad = 2.0 * std::numbers::pi * unit(rng);
  config.walk_speed_max_mps = 1.0 + 0.5 * unit(rng);
  config.side_step_probability = 0.4;
  DropoutSession session(seed, random_dropouts(rng, duration_s), random_dropouts(rng, duration_s), config);
  // The base where it follows the user, or anywhere within 1.5 m (inside the keep-out too).
  const PlannerSettings settings;
  const auto body = session.user().body();
  const Eigen::Vector2d u0(body.x_m, body.z_m);
  if (seed % 2 == 0) {
    const Eigen::Vector3d hand = session.user().hand_W();
    const Eigen::Vector2d t = planner_geometry::follow_target(u0, {hand.x(), hand.z()}, body.heading_rad,
                                                              settings.target_distance_m());
    session.place_base({t.x(), t.y(), planner_geometry::facing_heading(t, u0, settings.facing_angle_rad)});
  } else {
    const double r = 1.5 * std::sqrt(unit(rng)), a = 2.0 * std::numbers::pi * unit(rng);
    session.place_base({u0.x() + r * std::cos(a), u0.y() + r * std::sin(a), 2.0 * std::numbers::pi * unit(rng)});
  }
  const int steps = static_cast<int>(duration_s / kIoStep_s);
  for (int k = 0; k < steps; ++k) session.step(k * kIoStep_s, counts);
  ++counts.walks;
}

TEST(KeepOutDropout, TheBaseNeverMovesIntoTheTrueHeadWhateverDropsOut) {
  WalkCounts counts;
  const int walks = walk_count();
  for (int i = 0; i < walks; ++i) run_walk(static_cast<std::uint64_t>(i) + 1u, 8.0, counts);
  std::cout << "[ keep-out ] walks " << counts.walks << ", steps " << counts.steps << " (" << counts.stale_steps
            << " stale), moving on fresh data " << counts.moving_fresh_steps << " of " << counts.fresh_steps
            << ", HIP usable on " << counts.hip_usable_fresh_ticks << " of " << counts.fresh_ticks
            << " fresh plans, intrusions " << counts.intrusions << ", moving while stale " << counts.moving_while_stale
            << ", nearest the base drove to the true head " << counts.min_true_distance_m << " m\n";
  EXPECT_EQ(counts.walks, walks);
  EXPECT_GT(counts.stale_steps, counts.steps / 20);  // the dropouts are exercised
  EXPECT_EQ(counts.intrusions, 0);
  EXPECT_EQ(counts.moving_while_stale, 0);
  // The dual: not simply always stopped.
  EXPECT_GT(counts.moving_fresh_steps, counts.fresh_steps / 5);
  // (A user walking at up to 1.5 m/s outpaces a 0.5 m/s base: the HIP is often out of reach.)
  EXPECT_GT(counts.hip_usable_fresh_ticks, counts.fresh_ticks / 20);
}

/// A user who walks 1 m and stands; the base starts 1.5 m off.
simulation::SimulatedUserConfig standing_user() {
  simulation::SimulatedUserConfig config;
  config.path = simulation::parse_waypoints("0 0 0; 1 0 0.5");
  return config;
}

TEST(KeepOutDropout, WithFreshDataTheBaseReachesTheUsersWorkspace) {
  DropoutSession session(1, {}, {}, standing_user());
  session.place_base({-1.5, 0.0, 0.0});
  WalkCounts counts;
  double reached_s = kInf;
  for (int k = 0; k < 12000; ++k) {
    session.step(k * kIoStep_s, counts);
    if (session.hip_in_usable() && session.user().path_finished() && !std::isfinite(reached_s)) reached_s = k * kIoStep_s;
  }
  EXPECT_LT(reached_s, 10.0);
  EXPECT_TRUE(session.hip_in_usable());
  EXPECT_EQ(counts.intrusions, 0);
}

TEST(KeepOutDropout, AHeadDropoutStopsTheBaseWhichResumesSmoothlyAfter) {
  DropoutSession session(1, {{2.0, 3.0}}, {}, standing_user());
  session.place_base({-1.5, 0.0, 0.0});
  WalkCounts counts;
  double last_moving_in_dropout_s = -kInf, first_moving_after_s = kInf, max_speed_first_100ms_mps = 0.0;
  for (int k = 0; k < 12000; ++k) {
    const double t_s = k * kIoStep_s;
    session.step(t_s, counts);
    const BaseTwist& c = session.command();
    const bool moving = c.vx_mps != 0.0 || c.vz_mps != 0.0 || c.omega_radps != 0.0;
    if (moving && t_s >= 2.0 && t_s < 3.0) last_moving_in_dropout_s = t_s;
    if (moving && t_s >= 3.0 && !std::isfinite(first_moving_after_s)) first_moving_after_s = t_s;
    if (std::isfinite(first_moving_after_s) && t_s < first_moving_after_s + 0.1)
      max_speed_first_100ms_mps = std::max(max_speed_first_100ms_mps, std::hypot(c.vx_mps, c.vz_mps));
  }
  ASSERT_TRUE(std::isfinite(last_moving_in_dropout_s)) << "the base was not moving when the head dropped out";
  EXPECT_LT(last_moving_in_dropout_s, 2.0 + 0.05);  // stale at the tracker timeout after the last sample
  EXPECT_LT(first_moving_after_s, 3.0 + 0.5);       // moving again once a fresh plan comes
  EXPECT_LT(max_speed_first_100ms_mps, 0.5 * 0.2 + 1e-9);  // ramped: at most 0.1 s of the 0.5 s resume
  EXPECT_EQ(session.guard().counts().head_stale, 1u);
  EXPECT_TRUE(session.hip_in_usable());
}

}  // namespace
}  // namespace mhd
