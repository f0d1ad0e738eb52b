#include "geometry/object_motion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mhd {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

Pose at(double x, double y, double z, double yaw_deg) {
  return pose_from_xyz_rpy(Eigen::Vector3d(x, y, z), Eigen::Vector3d(0, 0, yaw_deg * kRadPerDeg));
}

double distance(const Pose& a, const Pose& b) { return (a.matrix() - b.matrix()).cwiseAbs().maxCoeff(); }

// The reported velocities must be the derivative of the reported poses: central
// differences of X_WO_at, away from keys, agree with v_W_origin_at and omega_W_at.
void expect_velocity_is_derivative(const ObjectMotion& m, double t_s) {
  const double h = 1e-6;
  const Pose a = m.X_WO_at(t_s - h);
  const Pose b = m.X_WO_at(t_s + h);
  const Eigen::Vector3d v = (b.translation() - a.translation()) / (2 * h);
  const Eigen::AngleAxisd turn(Eigen::Matrix3d(b.linear() * a.linear().transpose()));
  const Eigen::Vector3d w = turn.axis() * turn.angle() / (2 * h);
  EXPECT_LT((v - m.v_W_origin_at(t_s)).norm(), 1e-6) << "t = " << t_s;
  EXPECT_LT((w - m.omega_W_at(t_s)).norm(), 1e-5) << "t = " << t_s;
}

TEST(ObjectMotion, KeyframesPassThroughEveryKeyAndInterpolateBetween) {
  const ObjectMotion m = ObjectMotion::keyframes({{0.0, at(0, 0, 0, 0)}, {1.0, at(0.2, 0, 0, 90)}, {3.0, at(0.2, 0.4, 0, 90)}},
                                                 MotionRepeat::Hold);
  EXPECT_LT(distance(m.X_WO_at(0.0), at(0, 0, 0, 0)), 1e-12);
  EXPECT_LT(distance(m.X_WO_at(1.0), at(0.2, 0, 0, 90)), 1e-12);
  EXPECT_LT(distance(m.X_WO_at(3.0), at(0.2, 0.4, 0, 90)), 1e-12);
  EXPECT_LT(distance(m.X_WO_at(0.5), at(0.1, 0, 0, 45)), 1e-12);  // slerp: half the turn at half time
  EXPECT_LT(distance(m.X_WO_at(2.0), at(0.2, 0.2, 0, 90)), 1e-12);
  EXPECT_NEAR(m.max_speed_mps(), 0.2, 1e-12);
  EXPECT_NEAR(m.max_rate_radps(), 90 * kRadPerDeg, 1e-12);
  expect_velocity_is_derivative(m, 0.3);
  expect_velocity_is_derivative(m, 2.2);
}

TEST(ObjectMotion, HoldStaysAtTheEndsWithZeroVelocity) {
  const ObjectMotion m = ObjectMotion::keyframes({{1.0, at(0, 0, 0, 0)}, {2.0, at(1, 0, 0, 30)}}, MotionRepeat::Hold);
  EXPECT_LT(distance(m.X_WO_at(-5.0), at(0, 0, 0, 0)), 1e-12);
  EXPECT_LT(distance(m.X_WO_at(7.0), at(1, 0, 0, 30)), 1e-12);
  EXPECT_EQ(m.v_W_origin_at(7.0), Eigen::Vector3d::Zero());
  EXPECT_EQ(m.omega_W_at(-5.0), Eigen::Vector3d::Zero());
  EXPECT_GT(m.v_W_origin_at(1.5).norm(), 0.9);  // and moves in between
}

TEST(ObjectMotion, LoopIsContinuousAcrossTheWrap) {
  const ObjectMotion m = ObjectMotion::keyframes(
      {{0.0, at(0, 0, 0, 0)}, {1.0, at(0.3, 0, 0, 60)}, {2.0, at(0, 0, 0, 0)}}, MotionRepeat::Loop);
  EXPECT_LT(distance(m.X_WO_at(1.999999), m.X_WO_at(2.000001)), 1e-5);
  EXPECT_LT(distance(m.X_WO_at(2.5), m.X_WO_at(0.5)), 1e-12);
  EXPECT_LT(distance(m.X_WO_at(-1.5), m.X_WO_at(0.5)), 1e-12);
  expect_velocity_is_derivative(m, 4.7);
}

TEST(ObjectMotion, PingPongPlaysBackwardsWithReversedVelocity) {
  const ObjectMotion m = ObjectMotion::keyframes({{0.0, at(0, 0, 0, 0)}, {1.0, at(0.5, 0, 0, 40)}}, MotionRepeat::PingPong);
  EXPECT_LT(distance(m.X_WO_at(1.25), m.X_WO_at(0.75)), 1e-12);
  EXPECT_LT(distance(m.X_WO_at(2.0), at(0, 0, 0, 0)), 1e-12);
  EXPECT_LT((m.v_W_origin_at(1.5) + m.v_W_origin_at(0.5)).norm(), 1e-12);
  expect_velocity_is_derivative(m, 1.5);
  expect_velocity_is_derivative(m, 2.3);
}

TEST(ObjectMotion, TwistTurnsAboutTheOriginAtConstantRate) {
  const Eigen::Vector3d v(0.1, 0, -0.2);
  const Eigen::Vector3d w(0, std::numbers::pi, 0);  // 180 deg/s about y
  const ObjectMotion m = ObjectMotion::twist(at(1, 1, 0, 0), v, w);
  const Pose X = m.X_WO_at(0.5);
  EXPECT_LT((X.translation() - Eigen::Vector3d(1.05, 1, -0.1)).norm(), 1e-12);
  // A point 1 m along the object's x is carried a quarter turn round y.
  const Eigen::Vector3d p = X * Eigen::Vector3d(1, 0, 0) - X.translation();
  EXPECT_LT((p - Eigen::Vector3d(0, 0, -1)).norm(), 1e-12);
  expect_velocity_is_derivative(m, 0.7);
  expect_velocity_is_derivative(m, -0.3);
}

TEST(ObjectMotion, BadKeysAreRefusedNamingTheKey) {
  auto refused = [](std::vector<PoseKey> keys, MotionRepeat r, const std::string& says) {
    try {
      (void)ObjectMotion::keyframes(std::move(keys), r);
      ADD_FAILURE() << "accepted; expected: " << says;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  };
  refused({{0.0, at(0, 0, 0, 0)}}, MotionRepeat::Hold, "at least two keys");
  refused({{0.0, at(0, 0, 0, 0)}, {0.0, at(1, 0, 0, 0)}}, MotionRepeat::Hold, "motion key 2: time must be later");
  refused({{0.0, at(0, 0, 0, 0)}, {NAN, at(1, 0, 0, 0)}}, MotionRepeat::Hold, "motion key 2: time is not finite");
  refused({{0.0, at(0, 0, 0, 0)}, {1.0, at(1, 0, 0, 0)}}, MotionRepeat::Loop, "motion key 2: a looping motion must end");
  refused({{0.0, at(0, 0, 0, 0)}, {1.0, at(0, 0, 0, 180)}}, MotionRepeat::Hold, "turns 180 degrees");
  Pose sheared = at(0, 0, 0, 0);
  sheared.linear()(0, 1) = 0.3;
  refused({{0.0, at(0, 0, 0, 0)}, {1.0, sheared}}, MotionRepeat::Hold, "not a finite rigid pose");
  EXPECT_THROW((void)ObjectMotion::twist(at(0, 0, 0, 0), Eigen::Vector3d(NAN, 0, 0), Eigen::Vector3d::Zero()),
               std::invalid_argument);
  // The good half: a loop whose last key is its first, and a 179 degree turn, are taken.
  EXPECT_NO_THROW((void)ObjectMotion::keyframes({{0.0, at(0, 0, 0, 0)}, {1.0, at(1, 0, 0, 0)}, {2.0, at(0, 0, 0, 0)}},
                                                MotionRepeat::Loop));
  EXPECT_NO_THROW((void)ObjectMotion::keyframes({{0.0, at(0, 0, 0, 0)}, {1.0, at(0, 0, 0, 179)}}, MotionRepeat::Hold));
}

}  // namespace
}  // namespace mhd
