// A box on a floor, pushed through RigidBodyWorld: static friction holds it below
// mu m g and lets it go above (both halves), it accelerates as F - mu m g = m a
// (inertia), and, let go, it slides to a stop (friction), at any haptic rate.

#include "dynamics/rigid_body_world.h"

#include "geometry/primitive_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace mhd {
namespace {

using V = Eigen::Vector3d;
constexpr double kMass_kg = 0.5;
constexpr double kFriction = 0.4;
constexpr double kG_mps2 = 9.81;
constexpr double kSide_m = 0.1;
constexpr double kFrictionForce_N = kFriction * kMass_kg * kG_mps2;  // 1.962 N

std::shared_ptr<const MeshBvh> shape_of(TriangleMesh mesh) {
  return std::make_shared<MeshBvh>(std::make_shared<TriangleMesh>(std::move(mesh)));
}

// A y-up floor (the plane turned from +z to +y) and a 0.1 m box resting on it.
struct BoxOnFloor {
  CollisionWorld world;
  std::vector<std::optional<ObjectDynamics>> dynamics;
  std::unique_ptr<RigidBodyWorld> physics;
  double t_s = 0.0;

  explicit BoxOnFloor(const RigidBodySettings& settings = {}, double friction = kFriction) {
    Pose X_WF = Pose::Identity();
    X_WF.linear() = Eigen::AngleAxisd(-std::numbers::pi / 2, V::UnitX()).toRotationMatrix();
    world.add_object(shape_of(make_plane_mesh(4.0, 4.0)), X_WF);
    Pose X_WB = Pose::Identity();
    X_WB.translation() = V(0.0, kSide_m / 2, 0.0);
    world.add_object(shape_of(make_box_mesh(V::Constant(kSide_m))), X_WB);
    dynamics = {std::nullopt, ObjectDynamics{kMass_kg, friction}};
    const bool flags[] = {true, false};
    physics = std::make_unique<RigidBodyWorld>(world, dynamics, flags, settings);
  }
  // Runs the haptic clock for duration_s at rate_Hz, pushing with f_W_N at the box's
  // -x face centre (its centre's height: no torque) every tick.
  void push(const V& f_W_N, double duration_s, double rate_Hz = 1000.0) {
    const int ticks = static_cast<int>(std::lround(duration_s * rate_Hz));
    for (int k = 0; k < ticks; ++k) {
      t_s += 1.0 / rate_Hz;
      (void)physics->advance(t_s);
      const V p_W = physics->X_WO(1) * V(-kSide_m / 2, 0, 0);
      physics->apply_force(1, f_W_N, p_W);
    }
  }
  V centre() const { return physics->X_WO(1).translation(); }
};

TEST(RigidBodyWorld, ABoxRestsOnTheFloor) {
  BoxOnFloor box;
  box.push(V::Zero(), 0.5);
  EXPECT_NEAR(box.centre().y(), kSide_m / 2, 2e-4);
  EXPECT_LT((box.centre() - V(0, kSide_m / 2, 0)).head<1>().norm(), 1e-5);
  EXPECT_LT(box.physics->v_W_origin_mps(1).norm(), 1e-3);
}

TEST(RigidBodyWorld, StaticFrictionHoldsTheBoxBelowMuMgAndLetsItGoAbove) {
  BoxOnFloor below;
  below.push(V::Zero(), 0.2);
  const V start = below.centre();
  below.push(V(0.8 * kFrictionForce_N, 0, 0), 1.0);
  EXPECT_LT((below.centre() - start).norm(), 2e-4) << "held by static friction";

  BoxOnFloor above;
  above.push(V::Zero(), 0.2);
  above.push(V(1.2 * kFrictionForce_N, 0, 0), 1.0);
  // a = 0.2 mu g = 0.78 m/s^2: 0.39 m in 1 s.
  EXPECT_GT(above.centre().x() - start.x(), 0.3) << "slides once the push exceeds mu m g";
}

// Bullet's iterative (PGS) friction comes out a few per cent above Coulomb's (3-7 % at
// the 1 ms step with a 0.1 m box): 10 % is what the tests hold it to.
constexpr double kFrictionTolerance = 0.10;

// F - mu m g = m a, at the 1 kHz haptic rate and at one the physics step does not divide.
void expect_inertia(const RigidBodySettings& settings, double rate_Hz) {
  BoxOnFloor box(settings);
  box.push(V::Zero(), 0.2, rate_Hz);
  const double x0 = box.centre().x();
  const double F_N = 2.0 * kFrictionForce_N;
  const double a_mps2 = (F_N - kFrictionForce_N) / kMass_kg;  // 3.92 m/s^2
  box.push(V(F_N, 0, 0), 0.5, rate_Hz);
  EXPECT_NEAR(box.centre().x() - x0, 0.5 * a_mps2 * 0.25, kFrictionTolerance * 0.5 * a_mps2 * 0.25);
  EXPECT_NEAR(box.physics->v_W_origin_mps(1).x(), a_mps2 * 0.5, kFrictionTolerance * a_mps2 * 0.5);
  EXPECT_NEAR(box.centre().y(), kSide_m / 2, 5e-4) << "slides flat, neither lifts nor sinks";
}

TEST(RigidBodyWorld, APushAcceleratesTheBoxByFMinusFrictionOverMass) {
  expect_inertia(RigidBodySettings{}, 1000.0);
}

TEST(RigidBodyWorld, ThePhysicsStepIsDecoupledFromTheHapticRate) {
  RigidBodySettings four_ms;
  four_ms.step_s = 4e-3;
  expect_inertia(four_ms, 1000.0);  // four haptic ticks per physics step
  expect_inertia(RigidBodySettings{}, 3000.0);  // three ticks per step, forces held between
}

TEST(RigidBodyWorld, LetGoTheBoxSlidesToAStop) {
  BoxOnFloor box;
  box.push(V::Zero(), 0.2);
  box.push(V(3.0 * kFrictionForce_N, 0, 0), 0.3);  // a = 2 mu g
  const double v0 = box.physics->v_W_origin_mps(1).x();
  const double x0 = box.centre().x();
  ASSERT_GT(v0, 1.0);
  box.push(V::Zero(), 1.0);
  EXPECT_LT(box.physics->v_W_origin_mps(1).norm(), 1e-3) << "stopped";
  const double expected_m = v0 * v0 / (2.0 * kFriction * kG_mps2);
  EXPECT_NEAR(box.centre().x() - x0, expected_m, kFrictionTolerance * expected_m);

  BoxOnFloor ice(RigidBodySettings{}, 0.0);  // and without friction it keeps going
  ice.push(V::Zero(), 0.1);
  ice.push(V(1.0, 0, 0), 0.2);
  ice.push(V::Zero(), 0.5);
  EXPECT_NEAR(ice.physics->v_W_origin_mps(1).x(), 1.0 * 0.2 / kMass_kg, 0.01);
}

TEST(RigidBodyWorld, AThrownBodyFliesAtItsSetVelocityAndAnUnthrownOneStaysPut) {
  CollisionWorld world;
  world.add_object(shape_of(make_box_mesh(V::Constant(kSide_m))), Pose::Identity());
  world.add_object(shape_of(make_box_mesh(V::Constant(kSide_m))), Pose(Eigen::Translation3d(V(0.0, 1.0, 0.0))));
  const std::optional<ObjectDynamics> d[] = {ObjectDynamics{kMass_kg, kFriction}, ObjectDynamics{kMass_kg, kFriction}};
  const bool flags[] = {false, false};
  RigidBodySettings weightless;
  weightless.gravity_W_mps2.setZero();
  RigidBodyWorld physics(world, d, flags, weightless);
  const V v_W_mps(0.3, 0.0, -0.2);
  const V omega_W_radps(0.0, 0.0, std::numbers::pi);  // 180 deg/s
  physics.set_velocity(0, v_W_mps, omega_W_radps);
  physics.set_velocity(1, V(std::nan(""), 0, 0), V::Zero());  // ignored
  EXPECT_TRUE(physics.v_W_origin_mps(0).isApprox(v_W_mps));
  for (int k = 1; k <= 500; ++k) (void)physics.advance(1e-3 * k);
  EXPECT_TRUE(physics.v_W_origin_mps(0).isApprox(v_W_mps, 1e-6));
  EXPECT_TRUE(physics.omega_W_radps(0).isApprox(omega_W_radps, 1e-6));
  EXPECT_LT((physics.X_WO(0).translation() - 0.5 * v_W_mps).norm(), 1e-6);
  const double turned_rad = Eigen::AngleAxisd(physics.X_WO(0).linear()).angle();
  EXPECT_NEAR(turned_rad, std::numbers::pi / 2, 1e-3);
  EXPECT_LT((physics.X_WO(1).translation() - V(0.0, 1.0, 0.0)).norm(), 1e-9);  // never thrown
  EXPECT_EQ(physics.v_W_origin_mps(1), V::Zero());
}

TEST(RigidBodyWorld, RefusesANonPositiveOrNonFiniteMassAndANegativeFriction) {
  CollisionWorld world;
  world.add_object(shape_of(make_box_mesh(V::Constant(kSide_m))), Pose::Identity());
  const bool flags[] = {false};
  for (const ObjectDynamics bad : {ObjectDynamics{0.0, 0.5}, ObjectDynamics{-1.0, 0.5},
                                   ObjectDynamics{std::numeric_limits<double>::quiet_NaN(), 0.5},
                                   ObjectDynamics{1.0, -0.1}, ObjectDynamics{1.0, std::numeric_limits<double>::infinity()}}) {
    const std::optional<ObjectDynamics> d[] = {bad};
    EXPECT_THROW(RigidBodyWorld(world, d, flags), std::invalid_argument);
  }
  const std::optional<ObjectDynamics> good[] = {ObjectDynamics{0.2, 0.0}};
  const RigidBodyWorld ok(world, good, flags);
  EXPECT_TRUE(ok.is_body(0));
  EXPECT_FALSE(ok.is_body(1));
}

}  // namespace
}  // namespace mhd
