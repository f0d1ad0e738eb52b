// scenes/exact_primitives.xml through XML -> compiled scene -> proxy: each primitive is
// touched as its exact shape (not its tessellation), the force is the spring along the
// true normal, a stroke round the ball is smooth, and the exact oracle finds no crossing.

#include "support/scene_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace mhd::test {
namespace {

class ExactPrimitivesScene : public SceneFixture {
 protected:
  void SetUp() override { ASSERT_NO_FATAL_FAILURE(load("scenes/exact_primitives.xml")); }

  // Comes down along -n onto `on_surface` from 20 mm out to `depth` in, holds still, and
  // returns the last tick; fails on any crossing or tick inside.
  TickSample press(const Eigen::Vector3d& on_surface, const Eigen::Vector3d& n, double depth) {
    std::vector<Eigen::Vector3d> path =
        sample_polyline(std::vector<Eigen::Vector3d>{on_surface + 0.02 * n, on_surface - depth * n}, 0.05, 1000.0);
    for (int i = 0; i < 20; ++i) path.push_back(path.back());
    const TickRecord record = drive(path, 1000.0);
    EXPECT_EQ(count_crossings(record), 0U);
    EXPECT_EQ(count_ticks_inside(record), 0U);
    return record.empty() ? TickSample{} : record.back();
  }
};

TEST_F(ExactPrimitivesScene, EveryPrimitiveIsExactAndKeepsATessellationToDraw) {
  const std::pair<const char*, ExactKind> expected[] = {{"table_top", ExactKind::HalfSpace},
                                                        {"ball", ExactKind::Sphere},
                                                        {"rod", ExactKind::Capsule},
                                                        {"can", ExactKind::Cylinder},
                                                        {"block", ExactKind::Box}};
  for (const auto& [name, kind] : expected) {
    const ExactShape* shape = scene().world.exact_shape(object(name));
    ASSERT_NE(shape, nullptr) << name;
    EXPECT_EQ(shape->kind, kind) << name;
    EXPECT_GT(scene().world.shape(object(name)).mesh().triangle_count(), 0U) << name;
  }
  EXPECT_EQ(scene().world.shape(object("ball")).mesh().triangle_count(), 80U);
  EXPECT_NEAR(scene().world.exact_shape(object("rod"))->half_height_m, 0.05, 1e-12);
}

TEST_F(ExactPrimitivesScene, PressingOnEachShapeGivesTheSpringAlongItsTrueNormal) {
  const double k = scene().materials[0].stiffness_N_per_m;
  const double skin = scene().proxy.skin_m;
  const double depth = 0.003;
  const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  // The ball off its pole, where its 80 facets are furthest from the sphere's normal.
  const Eigen::Vector3d u = Eigen::Vector3d(0.35, 1.0, 0.2).normalized();
  const Eigen::Vector3d ball_c = scene().world.pose(object("ball")).translation();
  struct Case {
    const char* what;
    Eigen::Vector3d on_surface;
    Eigen::Vector3d n;
  };
  const Case cases[] = {
      {"ball", ball_c + 0.04 * u, u},
      {"rod", Eigen::Vector3d(0.03, 0.78, -0.06), up},
      {"rod's cap", Eigen::Vector3d(0.05, 0.765, -0.06) + 0.015 * Eigen::Vector3d(1.0, 1.0, 0.0).normalized(),
       Eigen::Vector3d(1.0, 1.0, 0.0).normalized()},
      {"can", Eigen::Vector3d(0.01, 0.8, 0.045), up},
      {"block", Eigen::Vector3d(0.12, 0.81, -0.03), up},
      {"table", Eigen::Vector3d(0.1, 0.75, 0.06), up},
  };
  for (const Case& c : cases) {
    const TickSample last = press(c.on_surface, c.n, depth);
    ASSERT_TRUE(last.in_contact) << c.what;
    const Eigen::Vector3d expected = k * (depth + skin) * c.n;
    EXPECT_LT((last.force_W - expected).norm(), 1e-3) << c.what << ": " << last.force_W.transpose();
  }
}

TEST_F(ExactPrimitivesScene, AStrokeOverTheBallIsSmoothAndNeverCrosses) {
  const Eigen::Vector3d c = scene().world.pose(object("ball")).translation();
  const double r = 0.04 - 0.003;
  const auto at = [&](double angle) -> Eigen::Vector3d {
    return c + r * Eigen::Vector3d(std::sin(angle), std::cos(angle), 0.0);
  };
  const Eigen::Vector3d first = at(-1.3);
  const Eigen::Vector3d outside = c + (0.04 + 0.02) / r * (first - c);
  std::vector<Eigen::Vector3d> path = sample_polyline(std::vector<Eigen::Vector3d>{outside, first}, 0.05, 1000.0);
  const std::size_t approach = path.size();
  for (double a = -1.3; a <= 1.3; a += 1e-4 / r) path.push_back(at(a));  // 0.1 m/s
  const TickRecord record = drive(path, 1000.0);
  EXPECT_EQ(count_crossings(record), 0U);
  EXPECT_EQ(count_ticks_inside(record), 0U);
  double sum_sq = 0.0;
  std::size_t n = 0;
  for (std::size_t i = approach; i < record.size(); ++i) {
    ASSERT_TRUE(record[i].in_contact) << i;
    const Eigen::Vector3d radial = (record[i].p_W_hip - c).normalized();
    sum_sq += (record[i].force_W - record[i].force_W.dot(radial) * radial).squaredNorm();
    ++n;
  }
  ASSERT_GT(n, 900U);
  EXPECT_LT(std::sqrt(sum_sq / static_cast<double>(n)), 1e-3);  // N rms across the true normal
}

TEST_F(ExactPrimitivesScene, IntoTheCreaseOfTheBallAndTheTableAndOutAgain) {
  const Eigen::Vector3d c = scene().world.pose(object("ball")).translation();
  // Along the table 2 mm deep to just past where the ball touches it (the ball, resting on
  // the table, meets a proxy one skin above it 0.28 mm from its foot), then away and up.
  const Eigen::Vector3d start = c + Eigen::Vector3d(0.08, -0.02, 0.0);
  const Eigen::Vector3d on_table = c + Eigen::Vector3d(0.08, -0.042, 0.0);
  const Eigen::Vector3d crease = c + Eigen::Vector3d(1e-4, -0.042, 0.0);
  const Eigen::Vector3d away = c + Eigen::Vector3d(0.09, 0.02, 0.03);
  const TickRecord record =
      drive(sample_polyline(std::vector<Eigen::Vector3d>{start, on_table, crease, away}, 0.05, 1000.0), 1000.0);
  EXPECT_EQ(count_crossings(record), 0U);
  EXPECT_EQ(count_ticks_inside(record), 0U);
  bool both = false;
  for (const TickSample& s : record) both = both || s.plane_count >= 2;
  EXPECT_TRUE(both);  // held by the ball and the table at once
  ASSERT_FALSE(record.empty());
  EXPECT_FALSE(record.back().in_contact);
  EXPECT_EQ(record.back().force_W, Eigen::Vector3d::Zero());
  EXPECT_EQ(record.back().proxy_W, away);
}

TEST_F(ExactPrimitivesScene, FastStrokesOverTheSceneNeverCrossAnExactShape) {
  const StrokeSet set = fast_strokes(161803, 60);
  ASSERT_GE(set.strokes.size(), 50U);
  std::size_t crossings = 0, inside = 0, contact = 0;
  for (const Stroke& s : set.strokes) {
    const TickRecord record = drive(s.p_W_hip, 1000.0);
    crossings += count_crossings(record);
    inside += count_ticks_inside(record);
    for (const TickSample& t : record) contact += t.in_contact ? 1U : 0U;
  }
  EXPECT_EQ(crossings, 0U);
  EXPECT_EQ(inside, 0U);
  EXPECT_GT(contact, 1000U);  // the strokes did press into the shapes
}

}  // namespace
}  // namespace mhd::test
