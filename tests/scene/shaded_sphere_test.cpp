// scenes/shaded_sphere.xml: force shading through the XML -> compiled scene -> proxy
// path. The same 80-triangle ball with and without shading, stroked alike: the shaded
// one's force keeps to the true sphere's normal, the faceted one's swings at each edge.

#include "support/scene_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace mhd::test {
namespace {

class ShadedSphereScene : public SceneFixture {
 protected:
  struct Stroke {
    double angle_rms_rad = 0;  // force's angle to the true sphere normal at the HIP
    int contact_ticks = 0;
    int ticks = 0;
    std::size_t crossings = 0;
  };

  // Half a tilted great circle at 0.1 m/s, the HIP 2 mm inside the ball's largest
  // inscribed sphere, after coming in from 30 mm outside.
  Stroke stroke(int ball) {
    const Eigen::Vector3d c_W = scene().world.pose(ball).translation();
    const TriangleMesh& mesh = scene().world.shape(ball).mesh();
    double inscribed_m = std::numeric_limits<double>::infinity();
    for (const auto& t : mesh.triangles) {
      const Eigen::Vector3d& a = mesh.vertices_m[t[0]];
      inscribed_m = std::min(
          inscribed_m, std::abs((mesh.vertices_m[t[1]] - a).cross(mesh.vertices_m[t[2]] - a).normalized().dot(a)));
    }
    const double r_m = inscribed_m - 0.002;
    const Eigen::Vector3d u(1, 0, 0);
    const Eigen::Vector3d w(0, std::cos(0.3), std::sin(0.3));
    std::vector<Eigen::Vector3d> path =
        sample_polyline(std::vector<Eigen::Vector3d>{c_W + (r_m + 0.03) * u, c_W + r_m * u}, 0.1, 1000.0);
    const std::size_t approach = path.size();
    for (double phi = 0; phi < std::numbers::pi; phi += 1e-4 / r_m) {
      path.push_back(c_W + r_m * (std::cos(phi) * u + std::sin(phi) * w));
    }
    const TickRecord record = drive(path, 1000.0);
    Stroke s;
    s.crossings = count_crossings(record);
    double sum_sq = 0;
    for (std::size_t i = approach; i < record.size(); ++i) {
      ++s.ticks;
      if (!record[i].in_contact) continue;
      ++s.contact_ticks;
      const Eigen::Vector3d radial = (record[i].p_W_hip - c_W).normalized();
      const Eigen::Vector3d& f = record[i].force_W;
      const double normal = f.dot(radial);
      const double angle = std::atan2((f - normal * radial).norm(), normal);
      sum_sq += angle * angle;
    }
    s.angle_rms_rad = std::sqrt(sum_sq / std::max(1, s.contact_ticks));
    return s;
  }
};

TEST_F(ShadedSphereScene, LoadsWithCornerNormalsForTheShadedObjectsOnly) {
  ASSERT_NO_FATAL_FAILURE(load("scenes/shaded_sphere.xml"));
  EXPECT_NE(scene().world.shading_normals(object("ball_shaded")), nullptr);
  EXPECT_NE(scene().world.shading_normals(object("box_shaded")), nullptr);
  EXPECT_EQ(scene().world.shading_normals(object("ball_faceted")), nullptr);
  EXPECT_EQ(scene().world.shape(object("ball_shaded")).mesh().triangle_count(), 80u);
}

TEST_F(ShadedSphereScene, AStrokeOverTheShadedBallRendersContactThatFeelsRound) {
  ASSERT_NO_FATAL_FAILURE(load("scenes/shaded_sphere.xml"));
  const Stroke shaded = stroke(object("ball_shaded"));
  const Stroke faceted = stroke(object("ball_faceted"));
  std::printf("shaded_sphere.xml: force angle to the sphere normal, rms %.2f deg shaded, %.2f deg faceted\n",
              shaded.angle_rms_rad * 180 / std::numbers::pi, faceted.angle_rms_rad * 180 / std::numbers::pi);
  // The whole stroke is in contact, and nothing is crossed.
  EXPECT_EQ(shaded.contact_ticks, shaded.ticks);
  EXPECT_EQ(faceted.contact_ticks, faceted.ticks);
  EXPECT_GT(shaded.ticks, 1500);
  EXPECT_EQ(shaded.crossings, 0u);
  EXPECT_EQ(faceted.crossings, 0u);
  EXPECT_LT(shaded.angle_rms_rad, faceted.angle_rms_rad / 4);
}

}  // namespace
}  // namespace mhd::test
