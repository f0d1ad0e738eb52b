// Keep-outs: the other users and bases of a shared floor. Default settings: robot radius
// 0.225 m, human radius 0.25 m (a user's contact distance 0.475 m, band 0.525 m; another
// base's contact distance 0.45 m, band 0.5 m), 0.5 m/s, 0.1 s period.

#include "planner/keep_outs.h"
#include "planner/planner.h"
#include "planner/planner_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <iostream>
#include <random>

namespace mhd {
namespace keep_outs_test {

constexpr double kPi = std::numbers::pi;

KeepOut other_user(double x, double z) { return KeepOut{KeepOutKind::User, {x, z}, 0.25}; }
KeepOut other_base(double x, double z) { return KeepOut{KeepOutKind::Base, {x, z}, 0.225}; }

/// The least distance from the arc the base drives over one period to `centre`, at 1,000
/// points (a hundred times finer than the guard's own check).
double min_distance_on_arc(const BasePose& base, const BaseTwist& twist, double period_s,
                           const Eigen::Vector2d& centre) {
  double least = (Eigen::Vector2d(base.x_m, base.z_m) - centre).norm();
  for (int i = 1; i <= 1000; ++i) {
    const BasePose b = integrate_twist(base, twist, period_s * i / 1000.0);
    least = std::min(least, (Eigen::Vector2d(b.x_m, b.z_m) - centre).norm());
  }
  return least;
}

TEST(KeepOuts, HoldsAFixedNumberAndRefusesMore) {
  KeepOuts k;
  for (std::size_t i = 0; i < KeepOuts::kCapacity; ++i) EXPECT_TRUE(k.add(other_user(double(i), 0.0)));
  EXPECT_FALSE(k.add(other_user(99.0, 0.0)));
  EXPECT_EQ(k.size(), KeepOuts::kCapacity);
  k.clear();
  EXPECT_TRUE(k.empty());
}

TEST(KeepOuts, TheGuardRemovesMotionIntoAnotherUserAndKeepsMotionAway) {
  const PlannerSettings s;
  KeepOuts k;
  k.add(other_user(0.55, 0.0));  // 0.55 m ahead: one period at 0.5 m/s ends inside the band
  const BasePose base{0.0, 0.0, 0.0};
  const Eigen::Vector2d own_user(-5.0, 0.0);

  Eigen::Vector2d towards(0.5, 0.0);
  EXPECT_TRUE(guard_keep_outs(base, own_user, 0.525, k, s, 0.0, towards));
  EXPECT_GE(towards.dot(Eigen::Vector2d(-1.0, 0.0)), -1e-12);  // nothing left towards it

  Eigen::Vector2d away(-0.5, 0.0);  // dual: away (and towards nobody) is untouched
  EXPECT_FALSE(guard_keep_outs(base, own_user + Eigen::Vector2d(-5.0, 0.0), 0.525, k, s, 0.0, away));
  EXPECT_EQ(away, Eigen::Vector2d(-0.5, 0.0));

  KeepOuts far;
  far.add(other_user(3.0, 0.0));  // dual: towards a user still beyond the band is untouched
  Eigen::Vector2d towards_far(0.5, 0.0);
  EXPECT_FALSE(guard_keep_outs(base, own_user, 0.525, far, s, 0.0, towards_far));
  EXPECT_EQ(towards_far, Eigen::Vector2d(0.5, 0.0));
}

TEST(KeepOuts, BetweenTwoDiscsTheBaseStopsRatherThanEnterEither) {
  // Another base ahead-left and another user ahead-right, both inside their bands: the
  // guard of one slides the base along it, into the other.
  const PlannerSettings s;
  KeepOuts k;
  k.add(other_base(0.35, -0.36));
  k.add(other_user(0.35, 0.39));
  const BasePose base{0.0, 0.0, 0.3};
  Eigen::Vector2d v(0.5, 0.0);
  EXPECT_TRUE(guard_keep_outs(base, {-3.0, 0.0}, 0.525, k, s, 0.5, v));
  const BaseTwist twist = planner_geometry::body_twist(base.heading_rad, v, 0.5, s);
  for (const KeepOut& o : k) {
    const double d0 = (Eigen::Vector2d(base.x_m, base.z_m) - o.centre_W).norm();
    EXPECT_GE(min_distance_on_arc(base, twist, s.command_period_s, o.centre_W),
              std::min(d0, contact_distance_m(o, s)) - 1e-9);
  }
}

TEST(KeepOuts, RandomDiscsAndVelocitiesNeverEnterAnyDiscByTheOracle) {
  const PlannerSettings s;
  std::mt19937_64 rng(20261129);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int guarded = 0;
  int entered = 0;
  int unguarded_entered = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    KeepOuts k;
    const int n = 1 + trial % 4;
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2d c(0.8 * u(rng), 0.8 * u(rng));
      k.add(i % 2 == 0 ? other_user(c.x(), c.y()) : other_base(c.x(), c.y()));
    }
    const Eigen::Vector2d own_user(1.2 * u(rng), 1.2 * u(rng));
    const BasePose base{0.0, 0.0, kPi * u(rng)};
    const double omega = s.max_angular_speed_radps * u(rng);
    Eigen::Vector2d v(u(rng), u(rng));
    if (v.norm() > s.max_linear_speed_mps) v *= s.max_linear_speed_mps / v.norm();
    const auto enters_any = [&](const Eigen::Vector2d& v_W) {
      const BaseTwist twist = planner_geometry::body_twist(base.heading_rad, v_W, omega, s);
      const auto enters = [&](const Eigen::Vector2d& centre, double contact_m) {
        const double d0 = centre.norm();
        return min_distance_on_arc(base, twist, s.command_period_s, centre) < std::min(d0, contact_m) - 1e-9;
      };
      bool any = enters(own_user, s.collision_radius_m());
      for (const KeepOut& o : k) any = enters(o.centre_W, contact_distance_m(o, s)) || any;
      return any;
    };
    if (enters_any(v)) ++unguarded_entered;
    if (guard_keep_outs(base, own_user, s.collision_radius_m() + s.safety_margin_m, k, s, omega, v)) ++guarded;
    if (enters_any(v)) ++entered;
  }
  std::cout << "[ keep-outs ] " << guarded << " of 4000 velocities guarded; " << unguarded_entered
            << " would enter a disc unguarded, " << entered << " do guarded\n";
  EXPECT_GT(guarded, 400);             // the trials make the guard work
  EXPECT_GT(unguarded_entered, 400);   // and the oracle sees entries where there are some
  EXPECT_EQ(entered, 0);
}

/// Two rigs' bases sent past each other by their planners: each user's hand asks for a
/// base position on the other base's side of the line z = 0. Returns the least distance
/// between the bases over 5 s.
double least_base_distance(PlannerKind kind, bool see_each_other) {
  const PlannerSettings s;
  const auto a = make_planner(kind, s);
  const auto b = make_planner(kind, s);
  BasePose base_a{-0.6, 0.0, 0.0};
  BasePose base_b{0.6, 0.0, kPi};
  const Eigen::Vector2d user_a(0.3, -0.675);  // reaching to +z: the target (0.3, 0)
  const Eigen::Vector2d user_b(-0.3, 0.675);  // reaching to -z: the target (-0.3, 0)
  double least = 1e9;
  for (int tick = 0; tick < 50; ++tick) {
    PlannerInput in_a;
    in_a.base = base_a;
    in_a.user_W = user_a;
    in_a.user_heading_rad = -kPi / 2;
    in_a.p_W_hip = Eigen::Vector3d(0.3, 1.1, -0.225);
    PlannerInput in_b;
    in_b.base = base_b;
    in_b.user_W = user_b;
    in_b.user_heading_rad = kPi / 2;
    in_b.p_W_hip = Eigen::Vector3d(-0.3, 1.1, 0.225);
    if (see_each_other) {
      in_a.keep_outs.add(other_base(base_b.x_m, base_b.z_m));
      in_a.keep_outs.add(other_user(user_b.x(), user_b.y()));
      in_b.keep_outs.add(other_base(base_a.x_m, base_a.z_m));
      in_b.keep_outs.add(other_user(user_a.x(), user_a.y()));
    }
    const BaseTwist ta = a->update(in_a).twist_B;
    const BaseTwist tb = b->update(in_b).twist_B;
    for (int i = 1; i <= 10; ++i) {
      const BasePose pa = integrate_twist(base_a, ta, s.command_period_s * i / 10.0);
      const BasePose pb = integrate_twist(base_b, tb, s.command_period_s * i / 10.0);
      least = std::min(least, std::hypot(pa.x_m - pb.x_m, pa.z_m - pb.z_m));
    }
    base_a = integrate_twist(base_a, ta, s.command_period_s);
    base_b = integrate_twist(base_b, tb, s.command_period_s);
  }
  return least;
}

TEST(KeepOuts, TwoBasesSeeingEachOtherNeverTouch) {
  for (const PlannerKind kind : {PlannerKind::Seed, PlannerKind::Predictive}) {
    const double contact = 2.0 * PlannerSettings{}.robot_radius_m;
    EXPECT_GE(least_base_distance(kind, true), contact) << to_string(kind);
    // Dual: blind to each other, the same two planners drive one base into the other.
    EXPECT_LT(least_base_distance(kind, false), contact) << to_string(kind);
  }
}

TEST(KeepOuts, StaleKeepOutsHoldTheBaseAndCurrentOnesReleaseIt) {
  const PlannerSettings s;
  for (const PlannerKind kind : {PlannerKind::Seed, PlannerKind::Predictive}) {
    const auto planner = make_planner(kind, s);
    PlannerInput in;
    in.base = BasePose{0.675, 0.0, -kPi / 2};
    in.p_W_hip = Eigen::Vector3d(0.0, 1.1, -0.6);  // far outside the usable workspace
    in.keep_outs.add(other_user(3.0, 3.0));
    in.keep_outs_current = false;
    const PlannerOutput held = planner->update(in);
    EXPECT_EQ(held.status, PlannerCase::Held) << to_string(kind);
    EXPECT_EQ(held.twist_B.vx_mps, 0.0);
    EXPECT_EQ(held.twist_B.vz_mps, 0.0);
    EXPECT_EQ(held.twist_B.omega_radps, 0.0);
    EXPECT_FALSE(held.hip_in_usable);
    EXPECT_FALSE(planner->active());
    // Dual: once the data is current again, the base goes to the hand.
    in.keep_outs_current = true;
    const PlannerOutput moving = planner->update(in);
    EXPECT_NE(moving.status, PlannerCase::Held) << to_string(kind);
    EXPECT_GT(std::hypot(moving.twist_B.vx_mps, moving.twist_B.vz_mps), 0.1) << to_string(kind);
  }
}

TEST(KeepOuts, ThePredictivePlannerReachesTheHandPastAnotherUser) {
  // Another user stands beside the way from the base to its catch goal: the base gets the
  // hand into the usable workspace without coming within the other user's contact distance.
  const PlannerSettings s;
  const auto planner = make_planner(PlannerKind::Predictive, s);
  BasePose base{0.675, 0.0, -kPi / 2};
  const Eigen::Vector2d other(0.9, -0.9);
  const Eigen::Vector3d hand(0.0, 1.1, -0.45);  // the user at the origin reaches to -z
  double least = 1e9;
  bool reached = false;
  for (int tick = 0; tick < 60 && !reached; ++tick) {
    PlannerInput in;
    in.base = base;
    in.user_heading_rad = kPi / 2;
    in.p_W_hip = hand;
    in.keep_outs.add(other_user(other.x(), other.y()));
    const PlannerOutput out = planner->update(in);
    base = integrate_twist(base, out.twist_B, s.command_period_s);
    least = std::min(least, (Eigen::Vector2d(base.x_m, base.z_m) - other).norm());
    reached = out.hip_in_usable;
  }
  EXPECT_TRUE(reached);
  EXPECT_GE(least, s.robot_radius_m + 0.25);
}

}  // namespace keep_outs_test
}  // namespace mhd
