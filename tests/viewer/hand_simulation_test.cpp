// `mhd try`'s haptic side (engine/viewer/hand_simulation.h) on scenes/cube_wall.xml, whose
// cube's front face is z = -0.3 m over x, y in [-0.2, 0.2] x [0.8, 1.2] m (wall: 2000 N/m):
// free space gives no force and the proxy at the HIP; pressing in gives the spring force
// out of the face with the proxy on it; a hand that jumps through the whole cube in one
// frame still stops at the face; ticks run at 1 kHz of simulated time.

#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"
#include "viewer/hand_simulation.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

namespace mhd::viewer {
namespace {

constexpr double kFrame_s = 1.0 / 60.0;
constexpr double kFace_z_m = -0.3;

std::unique_ptr<CompiledScene> compiled_scene(const char* file) {
  const Result<SceneDescription> read = read_scene_file(std::filesystem::path(MHD_SOURCE_DIR) / file);
  EXPECT_TRUE(read.ok());
  if (!read.ok()) return nullptr;
  CompileOptions options;
  options.use_cache = false;
  Result<std::unique_ptr<CompiledScene>> compiled = compile_scene(*read, options);
  EXPECT_TRUE(compiled.ok());
  return std::move(compiled).value();
}

std::unique_ptr<CompiledScene> cube_wall() { return compiled_scene("scenes/cube_wall.xml"); }

/// Several frames at the same HIP, so the velocity filter's damping dies away.
const HandSample& hold(HandSimulation& sim, const Eigen::Vector3d& p_W_hip_m, int frames = 6) {
  for (int i = 0; i < frames - 1; ++i) sim.advance(p_W_hip_m, kFrame_s);
  return sim.advance(p_W_hip_m, kFrame_s);
}

TEST(HandSimulation, FreeSpaceHasNoForceAndTheProxyAtTheHip) {
  const auto scene = cube_wall();
  ASSERT_TRUE(scene);
  HandSimulation sim(*scene, Eigen::Vector3d(0.0, 1.0, -0.2));
  const HandSample& s = sim.advance(Eigen::Vector3d(0.05, 1.0, -0.25), kFrame_s);
  EXPECT_EQ(s.ticks, 16);  // 16.67 ms: the rest carries over
  EXPECT_FALSE(s.in_contact);
  EXPECT_EQ(s.force_W_N, Eigen::Vector3d::Zero());
  EXPECT_EQ(s.penetration_m, 0.0);
  EXPECT_EQ(s.contact_object, -1);
  EXPECT_LT((s.p_W_proxy_m - Eigen::Vector3d(0.05, 1.0, -0.25)).norm(), 1e-12);
  EXPECT_LT((s.p_W_hip_m - Eigen::Vector3d(0.05, 1.0, -0.25)).norm(), 1e-12);
}

TEST(HandSimulation, PressingInGivesTheSpringForceOutOfTheFace) {
  const auto scene = cube_wall();
  ASSERT_TRUE(scene);
  HandSimulation sim(*scene, Eigen::Vector3d(0.0, 1.0, -0.2));
  const HandSample& s = hold(sim, Eigen::Vector3d(0.0, 1.0, kFace_z_m - 0.002));
  ASSERT_TRUE(s.in_contact);
  EXPECT_EQ(scene->object_names.at(static_cast<std::size_t>(s.contact_object)), "cube");
  EXPECT_GE(s.p_W_proxy_m.z(), kFace_z_m);  // the surface side
  EXPECT_LT(s.p_W_proxy_m.z(), kFace_z_m + 1e-5);
  EXPECT_NEAR(s.penetration_m, 0.002, 1e-5);
  EXPECT_NEAR(s.force_W_N.z(), 2000.0 * 0.002, 0.05);  // wall: 2000 N/m
  EXPECT_NEAR(s.force_W_N.x(), 0.0, 1e-6);
  EXPECT_NEAR(s.force_W_N.y(), 0.0, 1e-6);

  // Back out: nothing is felt and the proxy is at the HIP again.
  const HandSample& out = hold(sim, Eigen::Vector3d(0.0, 1.0, -0.2));
  EXPECT_FALSE(out.in_contact);
  EXPECT_EQ(out.force_W_N, Eigen::Vector3d::Zero());
  EXPECT_LT((out.p_W_proxy_m - out.p_W_hip_m).norm(), 1e-12);
}

TEST(HandSimulation, AHandThatJumpsThroughTheCubeInOneFrameStopsAtTheFace) {
  const auto scene = cube_wall();
  ASSERT_TRUE(scene);
  HandSimulation sim(*scene, Eigen::Vector3d(0.0, 1.0, -0.2));
  // Through the whole cube (back face z = -0.7) to free space behind it, in 16 ticks.
  const HandSample& s = sim.advance(Eigen::Vector3d(0.0, 1.0, -0.75), kFrame_s);
  ASSERT_TRUE(s.in_contact);
  EXPECT_NEAR(s.p_W_proxy_m.z(), kFace_z_m, 1e-5);
  EXPECT_GT(s.force_W_N.z(), 0.0);
  EXPECT_LE(s.force_W_N.norm(), scene->proxy.max_force_N + 1e-9);
  EXPECT_NEAR(s.force_W_N.norm(), scene->proxy.max_force_N, 1e-9);  // 0.45 m deep: clamped
}

TEST(HandSimulation, SixtyFramesAreOneSecondOfTicks) {
  const auto scene = cube_wall();
  ASSERT_TRUE(scene);
  HandSimulation sim(*scene, Eigen::Vector3d(0.0, 1.0, -0.2));
  const HandSample* s = nullptr;
  for (int i = 0; i < 60; ++i) s = &sim.advance(Eigen::Vector3d(0.0, 1.0, -0.2), kFrame_s);
  EXPECT_EQ(s->ticks, 1000);
  EXPECT_NEAR(s->t_s, 1.0, 1e-12);
}

TEST(HandSimulation, AStartInsideAnObjectIsRefused) {
  const auto scene = cube_wall();
  ASSERT_TRUE(scene);
  EXPECT_EQ(HandSimulation::start_blocked(*scene, Eigen::Vector3d(0.0, 1.0, -0.5)), "is inside an object");
  EXPECT_FALSE(HandSimulation::start_blocked(*scene, Eigen::Vector3d(0.0, 1.0, -0.2)));
}

TEST(HandSimulation, MovingObjectsMoveWithSimulatedTimeAndPushAStillHand) {
  // scenes/moving_objects.xml: the paddle's front face reaches z = -0.45 m at 1.06 s.
  const auto scene = compiled_scene("scenes/moving_objects.xml");
  ASSERT_TRUE(scene);
  const Eigen::Vector3d hand(0.0, 1.0, -0.45);
  HandSimulation sim(*scene, hand);
  const double z0_m = sim.world().pose(0).translation().z();
  EXPECT_FALSE(hold(sim, hand, 54).in_contact);  // 0.9 s
  const HandSample& pushed = hold(sim, hand, 24);  // 1.3 s
  ASSERT_TRUE(pushed.in_contact);
  EXPECT_EQ(pushed.contact_object, 0);
  EXPECT_GT(pushed.force_W_N.z(), 8.0);  // towards the user, at the 8.5 N limit
  EXPECT_GT(sim.world().pose(0).translation().z() - z0_m, 0.15);
  EXPECT_FALSE(hold(sim, hand, 42).in_contact);  // 2.0 s: the paddle has gone back
}

}  // namespace
}  // namespace mhd::viewer
