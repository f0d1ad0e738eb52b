// The per-eye cameras: eyes ipd apart along the head's right, looking along its gaze,
// and the projection that the render test checks pixels against.

#include "viewer/rig_state.h"
#include "viewer/stereo_views.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace mhd::viewer {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(StereoViews, EyesSitIpdApartAlongTheHeadsRight) {
  // A head at 1.6 m facing -z (heading pi/2): its right (forward x up) is +x.
  const Pose X_W_head = head_looking_at({0.0, 1.6, 0.0}, {0.0, 1.6, -1.0});
  ViewGeometry g;
  g.ipd_m = 0.064;
  const std::vector<EyeView> views = eye_views(X_W_head, g);
  ASSERT_EQ(views.size(), 2u);
  EXPECT_EQ(views[0].eye, Eye::Left);
  EXPECT_EQ(views[1].eye, Eye::Right);
  EXPECT_TRUE(views[0].X_W_camera.translation().isApprox(Eigen::Vector3d(-0.032, 1.6, 0.0), 1e-12));
  EXPECT_TRUE(views[1].X_W_camera.translation().isApprox(Eigen::Vector3d(0.032, 1.6, 0.0), 1e-12));
  // OpenGL camera: looks along its -z, which is the gaze; its x is the head's right.
  for (const EyeView& v : views) {
    EXPECT_TRUE((v.X_W_camera.linear() * -Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d(0, 0, -1), 1e-12));
    EXPECT_TRUE((v.X_W_camera.linear() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d(1, 0, 0), 1e-12));
    EXPECT_TRUE((v.X_W_camera.linear() * Eigen::Vector3d::UnitY()).isApprox(Eigen::Vector3d(0, 1, 0), 1e-12));
  }
  EXPECT_EQ(views[0].viewport_x, 0);
  EXPECT_EQ(views[1].viewport_x, 800);
  EXPECT_EQ(views[0].width, 800);
}

TEST(StereoViews, HeadingRotatesTheEyesWithTheHead) {
  // The simulated user's head convention: heading h about +y, forward (cos h, 0, -sin h).
  const double h = 0.7;
  Pose X_W_head = Pose::Identity();
  X_W_head.linear() = Eigen::AngleAxisd(h, Eigen::Vector3d::UnitY()).toRotationMatrix();
  X_W_head.translation() = Eigen::Vector3d(1.0, 1.7, 2.0);
  const std::vector<EyeView> views = eye_views(X_W_head, ViewGeometry{});
  const Eigen::Vector3d forward(std::cos(h), 0.0, -std::sin(h));
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitY());
  EXPECT_TRUE((views[1].X_W_camera.translation() - views[0].X_W_camera.translation()).isApprox(0.064 * right, 1e-12));
  EXPECT_TRUE((views[0].X_W_camera.linear() * -Eigen::Vector3d::UnitZ()).isApprox(forward, 1e-12));
}

TEST(StereoViews, MonoHasOneCentredEyeOverTheWholeWidth) {
  ViewGeometry g;
  g.stereo = false;
  const Pose X_W_head = head_looking_at({0.0, 1.6, 0.0}, {0.0, 1.6, -1.0});
  const std::vector<EyeView> views = eye_views(X_W_head, g);
  ASSERT_EQ(views.size(), 1u);
  EXPECT_EQ(views[0].width, 1600);
  EXPECT_TRUE(views[0].X_W_camera.translation().isApprox(Eigen::Vector3d(0.0, 1.6, 0.0), 1e-12));
}

TEST(StereoViews, NearPointHasCrossedParallaxOfFocalTimesIpdOverDepth) {
  const Pose X_W_head = head_looking_at({0.0, 1.6, 0.0}, {0.0, 1.6, -1.0});
  ViewGeometry g;
  g.fov_y_deg = 90.0;
  g.width = 1600;
  g.height = 800;
  const std::vector<EyeView> views = eye_views(X_W_head, g);
  const double focal_px = 400.0 / std::tan(0.25 * kPi);
  for (const double depth_m : {0.3, 0.5, 2.0}) {
    Eigen::Vector2d left, right;
    ASSERT_TRUE(project_to_pixel(views[0], {0.0, 1.6, -depth_m}, left));
    ASSERT_TRUE(project_to_pixel(views[1], {0.0, 1.6, -depth_m}, right));
    // In its own half, the left eye sees the point right of where the right eye sees it.
    const double parallax_px = (left.x() - views[0].viewport_x) - (right.x() - views[1].viewport_x);
    EXPECT_NEAR(parallax_px, focal_px * 0.064 / depth_m, 1e-9) << depth_m;
    EXPECT_NEAR(left.y(), 400.0, 1e-9);
  }
  Eigen::Vector2d pixel;
  EXPECT_FALSE(project_to_pixel(views[0], {0.0, 1.6, 1.0}, pixel)) << "behind the eye";
}

TEST(StereoViews, PerspectiveMatchesGluPerspective) {
  const Eigen::Matrix4d P = perspective(60.0, 2.0, 0.1, 10.0);
  const double f = 1.0 / std::tan(kPi / 6.0);
  EXPECT_NEAR(P(0, 0), f / 2.0, 1e-12);
  EXPECT_NEAR(P(1, 1), f, 1e-12);
  // Points on the near and far planes map to depth -1 and +1.
  const Eigen::Vector4d n = P * Eigen::Vector4d(0, 0, -0.1, 1);
  const Eigen::Vector4d fa = P * Eigen::Vector4d(0, 0, -10.0, 1);
  EXPECT_NEAR(n.z() / n.w(), -1.0, 1e-12);
  EXPECT_NEAR(fa.z() / fa.w(), 1.0, 1e-12);
}

}  // namespace
}  // namespace mhd::viewer
