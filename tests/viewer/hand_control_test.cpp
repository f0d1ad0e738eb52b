// The HIP under the mouse and keys (engine/viewer/hand_control.h): a drag moves it in
// the screen's plane by the pixels' size at its depth, the wheel and keys along the
// view, never behind the eye, and R goes back to the start.

#include "viewer/hand_control.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace mhd::viewer {
namespace {

/// Camera at the origin looking along -z (OpenGL's frame is the world's), 60 deg over 800 px.
HandCamera straight_camera() { return HandCamera{Pose::Identity(), 60.0, 800}; }

void expect_near(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double tol = 1e-12) {
  EXPECT_LT((a - b).norm(), tol) << a.transpose() << " vs " << b.transpose();
}

TEST(HandControl, DragMovesInTheScreenPlaneByThePixelSizeAtTheHipsDepth) {
  HandControl c(Eigen::Vector3d(0.0, 0.0, -2.0), 0.01);
  const HandCamera cam = straight_camera();
  const double mpp = 2.0 * 2.0 * std::tan(30.0 * std::numbers::pi / 180.0) / 800.0;
  EXPECT_NEAR(metres_per_pixel(cam, 2.0), mpp, 1e-15);
  c.apply(InputEvent::drag(50.0, 50.0), cam);  // no button held: nothing
  expect_near(c.p_W_hip_m(), Eigen::Vector3d(0.0, 0.0, -2.0));
  c.apply(InputEvent::press(100.0, 100.0), cam);
  c.apply(InputEvent::drag(200.0, 150.0), cam);
  c.apply(InputEvent::drag(210.0, 130.0), cam);
  expect_near(c.p_W_hip_m(), Eigen::Vector3d(110.0 * mpp, 30.0 * mpp, -2.0));
  c.apply(InputEvent::release(210.0, 130.0), cam);
  c.apply(InputEvent::drag(400.0, 400.0), cam);
  expect_near(c.p_W_hip_m(), Eigen::Vector3d(110.0 * mpp, 30.0 * mpp, -2.0));
}

TEST(HandControl, RightButtonDoesNotDrag) {
  HandControl c(Eigen::Vector3d(0.0, 0.0, -1.0), 0.01);
  c.apply(InputEvent::press(100.0, 100.0, 3), straight_camera());
  c.apply(InputEvent::drag(300.0, 100.0), straight_camera());
  expect_near(c.p_W_hip_m(), Eigen::Vector3d(0.0, 0.0, -1.0));
}

TEST(HandControl, DragFollowsARotatedCamerasAxes) {
  // Camera turned 90 deg about y: it looks along world -x, its right is world -z.
  HandCamera cam = straight_camera();
  cam.X_W_camera.linear() = Eigen::AngleAxisd(std::numbers::pi / 2.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
  HandControl c(Eigen::Vector3d(-1.0, 0.0, 0.0), 0.01);
  c.apply(InputEvent::press(0.0, 0.0), cam);
  c.apply(InputEvent::drag(10.0, 0.0), cam);
  expect_near(c.p_W_hip_m(), Eigen::Vector3d(-1.0, 0.0, -10.0 * metres_per_pixel(cam, 1.0)));
  c.apply(InputEvent::scroll(2), cam);  // away from the user: further along -x
  EXPECT_NEAR(c.p_W_hip_m().x(), -1.02, 1e-12);
}

TEST(HandControl, WheelAndKeysMoveAlongTheViewAndRResets) {
  HandControl c(Eigen::Vector3d(0.1, 0.2, -1.0), 0.01);
  const HandCamera cam = straight_camera();
  c.apply(InputEvent::scroll(3), cam);
  expect_near(c.p_W_hip_m(), Eigen::Vector3d(0.1, 0.2, -1.03));
  c.apply(InputEvent::key_press('s'), cam);
  c.apply(InputEvent::key_press(kKeyPageDown), cam);
  expect_near(c.p_W_hip_m(), Eigen::Vector3d(0.1, 0.2, -1.01));
  c.apply(InputEvent::key_press('W'), cam);
  c.apply(InputEvent::key_press(kKeyPageUp), cam);
  c.apply(InputEvent::key_press('x'), cam);  // not a hand key
  expect_near(c.p_W_hip_m(), Eigen::Vector3d(0.1, 0.2, -1.03));
  c.apply(InputEvent::key_press('r'), cam);
  expect_near(c.p_W_hip_m(), Eigen::Vector3d(0.1, 0.2, -1.0));
  c.apply(InputEvent::scroll(1), cam);
  c.apply(InputEvent::key_press(kKeyHome), cam);
  expect_near(c.p_W_hip_m(), Eigen::Vector3d(0.1, 0.2, -1.0));
}

TEST(HandControl, NeverComesCloserToTheEyeThanTheMinimumDepth) {
  HandControl c(Eigen::Vector3d(0.0, 0.0, -0.5), 0.1);
  const HandCamera cam = straight_camera();
  c.apply(InputEvent::scroll(-20), cam);
  expect_near(c.p_W_hip_m(), Eigen::Vector3d(0.0, 0.0, -HandControl::kMinDepth_m));
  c.apply(InputEvent::key_press('s'), cam);
  expect_near(c.p_W_hip_m(), Eigen::Vector3d(0.0, 0.0, -HandControl::kMinDepth_m));
  c.apply(InputEvent::key_press('w'), cam);
  expect_near(c.p_W_hip_m(), Eigen::Vector3d(0.0, 0.0, -HandControl::kMinDepth_m - 0.1));
}

}  // namespace
}  // namespace mhd::viewer
