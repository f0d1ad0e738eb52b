// The stress run end to end on small compiled scenes: the real proxy comes out clean,
// the same run with the proxy replaced by the HIP does not, and its reproducer replays
// the failure. Plus the stroke generator's promises (free starts, speed, determinism)
// and feature finding.

#include "stress/stress_run.h"

#include "collision/mesh_bvh.h"
#include "scene_compiler/scene_compiler.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>

namespace mhd::stress {
namespace {

using Eigen::Vector3d;

// A 200 mm box at hand height (friction, damping) and an open 300 mm sheet beside it.
std::unique_ptr<CompiledScene> box_and_sheet() {
  SceneDescription d;
  d.name = "stress_test";
  ObjectDescription box;
  box.name = "box";
  box.shape = BoxSource{Vector3d(0.2, 0.2, 0.2)};
  box.X_WO.translation() = Vector3d(0.0, 1.0, -0.5);
  box.material.stiffness_N_per_m = 2000.0;
  box.material.damping_Ns_per_m = 1.0;
  box.material.static_friction = 0.2;
  box.material.dynamic_friction = 0.15;
  d.objects.push_back(box);
  ObjectDescription sheet;
  sheet.name = "sheet";
  sheet.shape = PlaneSource{0.3, 0.3};
  sheet.X_WO.translation() = Vector3d(0.4, 1.0, -0.5);
  d.objects.push_back(sheet);
  CompileOptions options;
  options.use_cache = false;
  CompileResult r = compile_scene(d, options);
  EXPECT_TRUE(r.ok());
  return std::move(r.scene);
}

StressSettings small_run(std::size_t strokes) {
  StressSettings s;
  s.strokes = strokes;
  s.seed = 7;
  s.chain_length = 4;
  return s;
}

TEST(StressRun, RealProxyOnABoxIsCleanAndStrokesReachEveryKind) {
  const auto scene = box_and_sheet();
  ASSERT_TRUE(scene);
  const verify::SurfaceCrossingOracle oracle(scene->world);
  const ObjectStressReport r = stress_object(*scene, oracle, 0, name_key("stress_test/box"), small_run(300));
  EXPECT_EQ(r.strokes, 300U);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.ridges, 12U);
  EXPECT_EQ(r.corners, 8U);
  EXPECT_EQ(r.creases, 0U);
  EXPECT_TRUE(r.clean()) << r.failing_strokes << " failing strokes";
  EXPECT_EQ(r.inside_ticks, 0U);
  EXPECT_EQ(r.crossing_ticks, 0U);
  EXPECT_EQ(r.inside_engine_ticks, 0U);
  EXPECT_GT(r.engine_checks, 0U);
  EXPECT_EQ(r.worst_penetration_m, 0.0);
  EXPECT_GT(r.contact_ticks, r.ticks / 10);
  EXPECT_GT(r.max_hip_depth_m, 0.05);  // through strokes push the HIP deep
  EXPECT_GE(r.max_plane_count, 2);     // edges and corners were pressed
  for (StrokeKind k : {StrokeKind::Through, StrokeKind::Poke, StrokeKind::Graze, StrokeKind::Ridge, StrokeKind::Vertex,
                       StrokeKind::Random}) {
    EXPECT_GT(r.strokes_by_kind[static_cast<std::size_t>(k)], 0U) << to_string(k);
  }
  EXPECT_EQ(r.strokes_by_kind[static_cast<std::size_t>(StrokeKind::Crease)], 0U);  // the box has none
}

TEST(StressRun, RealProxyOnAnOpenSheetIsClean) {
  const auto scene = box_and_sheet();
  ASSERT_TRUE(scene);
  const verify::SurfaceCrossingOracle oracle(scene->world);
  const ObjectStressReport r = stress_object(*scene, oracle, 1, name_key("stress_test/sheet"), small_run(200));
  EXPECT_FALSE(r.closed);
  EXPECT_EQ(r.ridges, 4U);  // the rims
  EXPECT_TRUE(r.clean()) << r.failing_strokes << " failing strokes";
  EXPECT_GT(r.contact_ticks, 0U);
}

TEST(StressRun, HipUsedAsProxyFailsAndItsReproducerReplaysIt) {
  const auto scene = box_and_sheet();
  ASSERT_TRUE(scene);
  const verify::SurfaceCrossingOracle oracle(scene->world);
  StressSettings settings = small_run(40);
  settings.tamper = [](const Vector3d& hip_W, ProxyState& state, ProxyOutput& out) {
    state.proxy_W = hip_W;
    state.path_points = 1;
    state.path_W[0] = hip_W;
    state.plane_count = 0;
    out.proxy_W = hip_W;
  };
  const std::uint64_t key = name_key("stress_test/box");
  const ObjectStressReport r = stress_object(*scene, oracle, 0, key, settings);
  EXPECT_FALSE(r.clean());
  EXPECT_GT(r.failing_strokes, 10U);
  EXPECT_GT(r.inside_ticks, 0U);
  EXPECT_GT(r.crossing_ticks, 0U);
  EXPECT_GT(r.inside_engine_ticks, 0U);
  EXPECT_GT(r.worst_penetration_m, 0.01);
  ASSERT_FALSE(r.failures.empty());

  const StrokeFailure& first = r.failures.front();
  std::FILE* log = std::tmpfile();
  ASSERT_NE(log, nullptr);
  const ObjectStressReport replay = replay_stroke(*scene, oracle, 0, key, settings, first.stroke, log);
  std::rewind(log);
  std::string text;
  char buffer[4096];
  while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, log)) text.append(buffer, n);
  std::fclose(log);
  ASSERT_FALSE(replay.failures.empty());
  const StrokeFailure& again = replay.failures.back();
  EXPECT_EQ(again.stroke, first.stroke);
  EXPECT_EQ(again.tick, first.tick);
  EXPECT_EQ(again.hip_W, first.hip_W);
  EXPECT_NE(text.find("stroke " + std::to_string(first.stroke) + ":"), std::string::npos);
  EXPECT_NE(text.find("YES"), std::string::npos);
}

TEST(StressStrokes, FreeStartsBoundedSpeedAndDeterminism) {
  const auto scene = box_and_sheet();
  ASSERT_TRUE(scene);
  const verify::SurfaceCrossingOracle oracle(scene->world);
  const ObjectSurface surface = make_object_surface(scene->world, 0, true);
  const StressStrokeParams params;
  const StressStrokeGenerator gen(scene->world, oracle, surface, params);
  const double max_step = params.max_speed_m_per_s / params.rate_Hz * (1.0 + 1e-9);
  std::optional<Vector3d> last;
  int continued = 0;
  for (std::size_t i = 0; i < 200; ++i) {
    const StressStroke s = gen.make(3, 99, i, last);
    ASSERT_GE(s.hip_W.size(), 2U);
    EXPECT_TRUE(gen.start_is_free(s.start_W));
    EXPECT_EQ(s.hip_W[s.connector_samples], s.start_W);
    EXPECT_LE(s.speed_m_per_s, params.max_speed_m_per_s);
    const double duration = static_cast<double>(s.hip_W.size() - s.connector_samples) / params.rate_Hz;
    EXPECT_GE(duration, 0.05);
    if (s.continues) {
      EXPECT_LE((s.hip_W.front() - *last).norm(), max_step);
      ++continued;
    } else {
      EXPECT_EQ(s.connector_samples, 0U);
    }
    for (std::size_t k = 1; k < s.hip_W.size(); ++k) ASSERT_LE((s.hip_W[k] - s.hip_W[k - 1]).norm(), max_step);
    const StressStroke again = gen.make(3, 99, i, last);
    EXPECT_EQ(again.hip_W, s.hip_W);
    EXPECT_NE(gen.make(4, 99, i, last).hip_W, s.hip_W);
    last = s.hip_W.back();
  }
  EXPECT_GT(continued, 100);  // near a 200 mm box, most strokes can continue
}

TEST(StressStrokes, FeaturesOfAConcaveFold) {
  // A floor facing +z and a wall facing +x meeting along the y axis: one concave edge,
  // four open rims, and two corners where the crease meets two rims.
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices_m = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
  mesh->triangles = {{0, 2, 1}, {0, 1, 3}};
  CollisionWorld world;
  world.add_object(std::make_shared<MeshBvh>(mesh), Pose::Identity());
  const ObjectSurface s = make_object_surface(world, 0, false);
  ASSERT_EQ(s.creases.size(), 1U);
  EXPECT_EQ(s.ridges.size(), 4U);
  EXPECT_EQ(s.corners.size(), 2U);
  EXPECT_TRUE(s.creases[0].out_W.isApprox(Vector3d(1, 0, 1).normalized()));
  EXPECT_NEAR(std::abs((s.creases[0].b_W - s.creases[0].a_W).normalized().y()), 1.0, 1e-12);
  for (const SurfaceFeature& rim : s.ridges) {
    // Each rim's free direction points away from its triangle's centroid, in its plane.
    const Vector3d mid = 0.5 * (rim.a_W + rim.b_W);
    EXPECT_GT(rim.out_W.dot(mid - Vector3d(0.25, 0.25, 0.25)), 0.0);
  }
}

}  // namespace
}  // namespace mhd::stress
