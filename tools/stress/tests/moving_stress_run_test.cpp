// The moving-object stress end to end on small compiled scenes: a small box that moves
// (twists, loops, ping-pongs) beside a still wall, and a cube that only turns. The real
// proxy carried by MovingWorld is clean AND the strokes provably touch the moving surfaces
// (contact, pushes, rides); the same runs with the objects teleported without the carry
// report crossings or ticks inside, and the reproducer replays the failure. Plus the
// motion draw's bounds and the tick check's overlap rule, both halves.

#include "stress/moving_stress_run.h"

#include "skipped_carry_check.h"
#include "stress_test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

namespace mhd::stress {
namespace {

using test::compile_uncached;

using Eigen::Vector3d;

ObjectDescription box(const std::string& name, const Vector3d& size_m, const Vector3d& p_W_m) {
  return test::firm_object(name, BoxSource{size_m}, p_W_m);
}

// A 100 mm box (object 0) at hand height with a still 40 mm wall 100 mm beside it.
std::unique_ptr<CompiledScene> box_and_wall() {
  SceneDescription d;
  d.name = "moving_stress_test";
  d.objects.push_back(box("box", Vector3d::Constant(0.1), Vector3d(0.0, 1.0, -0.5)));
  d.objects.push_back(box("wall", Vector3d(0.04, 0.3, 0.3), Vector3d(0.17, 1.0, -0.5)));
  return compile_uncached(d);
}

// A 120 mm cube alone.
std::unique_ptr<CompiledScene> cube() {
  SceneDescription d;
  d.name = "turning_cube_test";
  d.objects.push_back(box("cube", Vector3d::Constant(0.12), Vector3d(0.0, 1.0, -0.5)));
  return compile_uncached(d);
}

MovingStressSettings box_run() {
  MovingStressSettings s;
  s.strokes = 200;
  s.seed = 11;
  s.chain_length = 4;
  return s;
}

// The cube only turns (a twist with no linear speed), at up to 180 deg/s.
MovingStressSettings turning_run() {
  MovingStressSettings s = box_run();
  s.motion.weight_loop = 0.0;
  s.motion.weight_pingpong = 0.0;
  s.motion.max_speed_mps = 0.0;
  return s;
}

void expect_clean_and_touching(const MovingStressReport& r, std::size_t strokes) {
  EXPECT_EQ(r.strokes, strokes);
  EXPECT_EQ(r.crossing_ticks, 0U);
  EXPECT_EQ(r.inside_ticks, 0U);
  EXPECT_EQ(r.not_followed_ticks, 0U);
  EXPECT_EQ(r.free_force_ticks, 0U);
  EXPECT_TRUE(r.clean());
  // ... and the strokes reached the moving surface: in contact on a good share of the
  // ticks, riding with it, and pushed by it in free space.
  EXPECT_GT(r.contact_ticks, r.ticks / 10);
  EXPECT_GT(r.ride_ticks, r.ticks / 20);
  EXPECT_GT(r.push_ticks, 10U);
  EXPECT_GT(r.strokes_with_push, strokes / 50);
  EXPECT_GT(r.max_hip_depth_m, 0.01);
}

TEST(MovingStress, ASmallMovingBoxBesideAWallIsCleanAndPushesTheProxy) {
  const auto scene = box_and_wall();
  ASSERT_TRUE(scene);
  const MovingStressReport r = stress_moving_object(*scene, 0, name_key("moving_stress_test/box"), box_run());
  expect_clean_and_touching(r, 200);
  EXPECT_GT(r.squeeze_ticks, 0U);  // pressed against the still wall (the overlap then is by design)
  for (const std::size_t n : r.chains_by_motion) EXPECT_GT(n, 0U);
  for (const std::size_t n : r.chains_by_anchor) EXPECT_GT(n, 0U);
  EXPECT_LE(r.max_object_speed_mps, 0.5 + 1e-9);
  EXPECT_GT(r.max_object_speed_mps, 0.49);  // full-speed motions were drawn
  EXPECT_LE(r.max_object_rate_radps, std::numbers::pi + 1e-9);
  EXPECT_GT(r.max_object_rate_radps, 0.99 * std::numbers::pi);
}

TEST(MovingStress, ATurningCubeIsCleanAndPushesTheProxy) {
  const auto scene = cube();
  ASSERT_TRUE(scene);
  const MovingStressReport r = stress_moving_object(*scene, 0, name_key("turning_cube_test/cube"), turning_run());
  expect_clean_and_touching(r, 200);
  EXPECT_EQ(r.chains_by_motion[static_cast<std::size_t>(MotionKind::Twist)], r.chains);
  EXPECT_EQ(r.max_object_speed_mps, 0.0);
  EXPECT_GT(r.max_object_rate_radps, 0.99 * std::numbers::pi);
}

TEST(MovingStress, ObjectsTeleportedWithoutTheCarryAreCaught) {
  for (const bool turning : {false, true}) {
    SCOPED_TRACE(turning ? "turning cube" : "moving box");
    const auto scene = turning ? cube() : box_and_wall();
    ASSERT_TRUE(scene);
    const std::uint64_t key = name_key(turning ? "turning_cube_test/cube" : "moving_stress_test/box");
    MovingStressSettings s = turning ? turning_run() : box_run();
    s.strokes = 60;
    test::expect_skipped_carry_caught_and_replayed(*scene, 0, key, s);
  }
}

TEST(MovingStress, TheSameSeedGivesTheSameRunAnotherSeedAnother) {
  const auto scene = box_and_wall();
  ASSERT_TRUE(scene);
  MovingStressSettings s = box_run();
  s.strokes = 40;
  const std::uint64_t key = name_key("moving_stress_test/box");
  const MovingStressReport a = stress_moving_object(*scene, 0, key, s);
  const MovingStressReport b = stress_moving_object(*scene, 0, key, s);
  EXPECT_EQ(a.ticks, b.ticks);
  EXPECT_EQ(a.contact_ticks, b.contact_ticks);
  EXPECT_EQ(a.push_ticks, b.push_ticks);
  s.seed = 12;
  const MovingStressReport c = stress_moving_object(*scene, 0, key, s);
  EXPECT_NE(a.ticks, c.ticks);
}

TEST(StressMotion, MotionsStartAtThePoseAndKeepToTheirSpeedAndRateBounds) {
  Pose X_WO_0 = Pose::Identity();
  X_WO_0.translation() = Vector3d(0.1, 1.0, -0.5);
  MotionDrawParams p;
  bool reached_speed = false, reached_rate = false;
  for (std::size_t chain = 0; chain < 300; chain += 1) {
    const StressMotion m = draw_stress_motion(3, 5, chain, X_WO_0, Vector3d(0.15, 1.0, -0.5), p);
    EXPECT_TRUE(m.motion.X_WO_at(0.0).isApprox(X_WO_0, 1e-12));
    EXPECT_LE(m.motion.max_speed_mps(), p.max_speed_mps * (1.0 + 1e-9));
    EXPECT_LE(m.motion.max_rate_radps(), p.max_rate_radps * (1.0 + 1e-9));
    reached_speed = reached_speed || m.motion.max_speed_mps() > 0.999 * p.max_speed_mps;
    reached_rate = reached_rate || m.motion.max_rate_radps() > 0.999 * p.max_rate_radps;
    EXPECT_EQ(m.anchor_time_s(0.0), 0.0);
    const double t_s = 0.7;
    EXPECT_EQ(m.anchor_time_s(t_s), m.anchor == StrokeAnchor::Riding    ? t_s
                                    : m.anchor == StrokeAnchor::Lagging ? std::max(0.0, t_s - m.lag_s)
                                                                        : 0.0);
  }
  EXPECT_TRUE(reached_speed);
  EXPECT_TRUE(reached_rate);
}

TEST(MovingTickCheck, AnOverlapObjectsCrossingIsToldApartAndNoOtherObjects) {
  const auto scene = box_and_wall();
  ASSERT_TRUE(scene);
  verify::MovingTickCheck check(scene->world);
  check.before_move(scene->world);
  // The proxy jumps through the box (object 0) into its middle.
  const Vector3d before_W(-0.2, 1.0, -0.5), after_W(0.0, 1.0, -0.5);
  ProxyOutput out;
  out.proxy_W = after_W;
  const std::array<Vector3d, 1> path{after_W};
  const auto plain = check.judge(scene->world, before_W, after_W, path, out, after_W);
  EXPECT_TRUE(plain.crossed);
  EXPECT_TRUE(plain.inside);
  EXPECT_FALSE(plain.overlap);
  const auto excused = check.judge(scene->world, before_W, after_W, path, out, after_W, 0);
  EXPECT_FALSE(excused.crossed);
  EXPECT_FALSE(excused.inside);
  EXPECT_TRUE(excused.overlap);
  const auto other = check.judge(scene->world, before_W, after_W, path, out, after_W, 1);
  EXPECT_TRUE(other.crossed);
  EXPECT_FALSE(other.overlap);
}

}  // namespace
}  // namespace mhd::stress
