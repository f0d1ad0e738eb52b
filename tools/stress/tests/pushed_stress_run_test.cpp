// The moving-object stress with a pushed body (pushed_mover.h) end to end: a box pushed on
// a floor under gravity and a floating cube, each thrown at every proxy reset and pushed
// by the proxy's force as the haptic tick pushes it. Both halves: the real engine is clean
// (0 crossings, 0 follow failures) AND the body really moved, by the throws and by the
// hand alone; the same runs with the proxy left behind by the moving body are caught, and
// the reproducer replays the failure.

#include "stress/moving_stress_run.h"

#include "skipped_carry_check.h"
#include "stress_test_scenes.h"

#include <gtest/gtest.h>

#include <memory>
#include <numbers>

namespace mhd::stress {
namespace {

using test::compile_uncached;
using test::firm_object;

using Eigen::Vector3d;

// A 150 mm, 0.6 kg box resting on a y-up floor (as scenes/pushable_box.xml): gravity acts.
std::unique_ptr<CompiledScene> box_on_floor() {
  SceneDescription d;
  d.name = "pushed_stress_test";
  ObjectDescription box = firm_object("box", BoxSource{Vector3d::Constant(0.15)}, Vector3d(0.0, 0.075, -0.5));
  box.dynamics = ObjectDynamics{0.6, 0.4};
  d.objects.push_back(box);
  ObjectDescription floor = firm_object("floor", PlaneSource{6.0, 6.0}, Vector3d::Zero());
  floor.X_WO.linear() = Eigen::AngleAxisd(-std::numbers::pi / 2, Vector3d::UnitX()).toRotationMatrix();
  d.objects.push_back(floor);
  return compile_uncached(d);
}

// A 120 mm cube alone, not pushable in its scene: it floats (no gravity), 1 kg.
std::unique_ptr<CompiledScene> floating_cube_scene() {
  SceneDescription d;
  d.name = "floating_cube_test";
  d.objects.push_back(firm_object("cube", BoxSource{Vector3d::Constant(0.12)}, Vector3d(0.0, 1.0, -0.5)));
  return compile_uncached(d);
}

MovingStressSettings pushed_run() {
  MovingStressSettings s;
  s.mover = MoverKind::Pushed;
  s.strokes = 200;
  s.seed = 11;
  s.chain_length = 4;
  return s;
}

void expect_clean_moved_and_pushed(const MovingStressReport& r, std::size_t strokes) {
  EXPECT_EQ(r.strokes, strokes);
  EXPECT_EQ(r.crossing_ticks, 0U);
  EXPECT_EQ(r.inside_ticks, 0U);
  EXPECT_EQ(r.not_followed_ticks, 0U);
  EXPECT_EQ(r.free_force_ticks, 0U);
  EXPECT_TRUE(r.clean());
  // ... and not vacuously: the strokes touched the body, pressed on it, and it moved.
  EXPECT_GT(r.contact_ticks, r.ticks / 20);
  EXPECT_GT(r.object_force_ticks, r.ticks / 20);
  EXPECT_GT(r.ride_ticks, 0U);
  EXPECT_GT(r.max_reached_speed_mps, 0.3);
  EXPECT_GT(r.max_reached_rate_radps, 1.0);
  EXPECT_GT(r.max_travel_m, 0.05);
}

TEST(PushedStress, ABoxPushedOnAFloorIsCleanAndMoves) {
  const auto scene = box_on_floor();
  ASSERT_TRUE(scene);
  const MovingStressReport r = stress_moving_object(*scene, 0, name_key("pushed_stress_test/box"), pushed_run());
  expect_clean_moved_and_pushed(r, 200);
  EXPECT_EQ(r.chains_by_motion[static_cast<std::size_t>(MotionKind::Twist)], r.chains);  // thrown, never keyframed
  EXPECT_GT(r.max_object_speed_mps, 0.49);  // full-speed throws were drawn
}

TEST(PushedStress, AFloatingCubeIsCleanAndMoves) {
  const auto scene = floating_cube_scene();
  ASSERT_TRUE(scene);
  const MovingStressReport r = stress_moving_object(*scene, 0, name_key("floating_cube_test/cube"), pushed_run());
  expect_clean_moved_and_pushed(r, 200);
}

TEST(PushedStress, TheHandAloneMovesAnUnthrownBodyAndAStillObjectStaysPut) {
  const auto scene = floating_cube_scene();
  ASSERT_TRUE(scene);
  const std::uint64_t key = name_key("floating_cube_test/cube");
  MovingStressSettings s = pushed_run();
  s.strokes = 100;
  s.motion.max_speed_mps = 0.0;  // no throws: only the proxy's force moves it
  s.motion.max_rate_radps = 0.0;
  const MovingStressReport pushed = stress_moving_object(*scene, 0, key, s);
  EXPECT_TRUE(pushed.clean());
  EXPECT_EQ(pushed.max_object_speed_mps, 0.0);
  EXPECT_GT(pushed.max_reached_speed_mps, 0.1);
  EXPECT_GT(pushed.max_travel_m, 0.02);
  // The other half: the same strokes at a scripted object that does not move leave it put.
  s.mover = MoverKind::Scripted;
  const MovingStressReport still = stress_moving_object(*scene, 0, key, s);
  EXPECT_TRUE(still.clean());
  EXPECT_GT(still.contact_ticks, 0U);
  EXPECT_EQ(still.max_reached_speed_mps, 0.0);
  EXPECT_EQ(still.max_travel_m, 0.0);
}

TEST(PushedStress, BodiesMovedWithoutTheCarryAreCaught) {
  for (const bool floating : {false, true}) {
    SCOPED_TRACE(floating ? "floating cube" : "box on a floor");
    const auto scene = floating ? floating_cube_scene() : box_on_floor();
    ASSERT_TRUE(scene);
    const std::uint64_t key = name_key(floating ? "floating_cube_test/cube" : "pushed_stress_test/box");
    MovingStressSettings s = pushed_run();
    s.strokes = 60;
    test::expect_skipped_carry_caught_and_replayed(*scene, 0, key, s);
  }
}

}  // namespace
}  // namespace mhd::stress
