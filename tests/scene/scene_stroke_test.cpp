// Scene-level stress: random fast strokes (up to 1 m/s at 1 kHz, random grazing angles)
// over the shipped scenes. The exact oracle checks every move of the proxy; forces must
// stay finite and within the clamp.

#include "support/scene_fixture.h"

#include <gtest/gtest.h>

#include <random>

namespace mhd::test {
namespace {

struct StrokeCase {
  const char* scene;
  int strokes;
};

class FastStrokes : public SceneFixture, public ::testing::WithParamInterface<StrokeCase> {};

TEST_P(FastStrokes, NeverLeaveTheProxyInsideOrBehindTheSurface) {
  ASSERT_NO_FATAL_FAILURE(load(GetParam().scene));
  FastStrokeParams params;
  params.max_speed_m_per_s = 1.0;
  const StrokeSet set = fast_strokes(/*seed=*/20261120, GetParam().strokes, params);
  ASSERT_EQ(static_cast<int>(set.strokes.size()), GetParam().strokes);
  const double limit = scene().proxy.max_force_N;
  std::size_t crossings = 0, inside = 0, contact_ticks = 0;
  for (const Stroke& stroke : set.strokes) {
    const TickRecord record = drive(stroke.p_W_hip, 1000.0);
    for (const auto& crossing : find_crossings(record)) {
      if (++crossings <= 3) {
        ADD_FAILURE() << "pop-through at tick " << crossing.tick << " leg " << crossing.leg << " from "
                      << crossing.from_W.transpose() << " to " << crossing.to_W.transpose();
      }
    }
    inside += count_ticks_inside(record);
    for (const TickSample& tick : record) {
      ASSERT_TRUE(tick.force_W.allFinite());
      ASSERT_LE(tick.force_W.norm(), limit * (1 + 1e-12));
      if (tick.in_contact) ++contact_ticks;
    }
  }
  EXPECT_EQ(crossings, 0U);
  EXPECT_EQ(inside, 0U);
  EXPECT_GT(contact_ticks, static_cast<std::size_t>(GetParam().strokes));  // the strokes really touch
}

INSTANTIATE_TEST_SUITE_P(Scenes, FastStrokes,
                         ::testing::Values(StrokeCase{"scenes/dolphin.xml", 1000}, StrokeCase{"scenes/bunny.xml", 1000},
                                           StrokeCase{"scenes/thin_shell.xml", 1000},
                                           StrokeCase{"scenes/cube_wall.xml", 600},
                                           StrokeCase{"scenes/shaded_sphere.xml", 600},
                                           StrokeCase{"tests/data/scenes/valid/corner_room.xml", 600}),
                         [](const ::testing::TestParamInfo<StrokeCase>& param_info) {
                           return std::filesystem::path(param_info.param.scene).stem().string();
                         });

class CornerStrokes : public SceneFixture {};

TEST_F(CornerStrokes, DivesIntoConcaveCornersSolveThreePlanesAndNeverCross) {
  ASSERT_NO_FATAL_FAILURE(load("tests/data/scenes/valid/corner_room.xml"));
  // The block fills the room's own corner, so the concave triple corners are where it
  // meets two room surfaces. Dive at them from random points in free space, at random
  // speeds, ending 2 to 10 mm behind all three planes.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::vector<Eigen::Vector3d> corners = {{0.06, 0, 0}, {0, 0, 0.06}, {0, 0.06, 0}};
  int three_planes = 0;
  std::size_t crossings = 0;
  for (int k = 0; k < 400; ++k) {
    const Eigen::Vector3d& c = corners[static_cast<std::size_t>(k) % corners.size()];
    const Eigen::Vector3d start = c + Eigen::Vector3d(0.02 + 0.05 * u(rng), 0.02 + 0.05 * u(rng), 0.02 + 0.05 * u(rng));
    const Eigen::Vector3d end = c - Eigen::Vector3d(0.002 + 0.008 * u(rng), 0.002 + 0.008 * u(rng), 0.002 + 0.008 * u(rng));
    const double speed = 0.1 + 0.9 * u(rng);
    const std::vector<Eigen::Vector3d> path = sample_polyline(std::vector<Eigen::Vector3d>{start, end}, speed, 1000.0);
    const TickRecord record = drive(path, 1000.0);
    crossings += count_crossings(record);
    if (!record.empty() && record.back().plane_count == 3) ++three_planes;
  }
  EXPECT_EQ(crossings, 0U);
  EXPECT_GT(three_planes, 300);  // nearly every dive ends wedged in a corner, all three planes active
}

}  // namespace
}  // namespace mhd::test
