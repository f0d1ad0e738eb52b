// A hand pushing a box along the floor through the proxy (docs/proxy.md "Pushable
// objects"): the box is a Bullet rigid body pushed by the reaction of the force the hand
// feels, and its motion is swept like a scripted one. Judged by the exact oracle in each
// object's frame (verify::drive_moving_proxy): the proxy never crosses the box or the
// floor, and goes back to the hand, with no force, when the hand backs off.

#include "proxy/moving_world.h"

#include "proxy_test_rig.h"

#include "geometry/primitive_mesh.h"
#include "verification/moving_drive.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mhd {
namespace {

using V = Eigen::Vector3d;
constexpr double kPushDt_s = test::kProxyTestDt_s;
constexpr double kMass_kg = 0.5;
constexpr double kFriction = 0.4;
constexpr double kSide_m = 0.1;
constexpr double kFrictionForce_N = kFriction * kMass_kg * 9.81;  // 1.96 N

// A y-up floor and a 0.1 m box (centre at the origin's x, z) resting on it; both of the
// default material (1 kN/m, no damping).
struct PushRig {
  CollisionWorld world;
  std::vector<HapticMaterial> materials{HapticMaterial{}, HapticMaterial{}};
  std::vector<std::optional<ObjectMotion>> motions{std::nullopt, std::nullopt};
  std::vector<std::optional<ObjectDynamics>> dynamics{std::nullopt, ObjectDynamics{kMass_kg, kFriction}};
  ProxySettings settings;

  PushRig() {
    Pose X_WF = Pose::Identity();
    X_WF.linear() = Eigen::AngleAxisd(-std::numbers::pi / 2, V::UnitX()).toRotationMatrix();
    world.add_object(test::shape_of(make_plane_mesh(4.0, 4.0)), X_WF);
    Pose X_WB = Pose::Identity();
    X_WB.translation() = V(0.0, kSide_m / 2, 0.0);
    world.add_object(test::shape_of(make_box_mesh(V::Constant(kSide_m))), X_WB);
  }
  template <class Hip>
  verify::MovingDrive drive(Hip&& hip, int n) {
    std::vector<V> path;
    for (int k = 0; k <= n; ++k) path.push_back(hip(k * kPushDt_s));
    return verify::drive_moving_proxy(world, motions, materials, settings, path, 1.0 / kPushDt_s, dynamics);
  }
};

double box_x(const verify::MovingDrive& d, std::size_t tick) { return d.X_WO[tick][1].translation().x(); }

TEST(PushedBox, AHandPushesTheBoxAlongTheFloorNeverEntersItAndIsFreeWhenItBacksOff) {
  PushRig rig;
  // From 30 mm before the box's -x face at mid height: 0.1 m/s along +x for 2 s, a
  // pause, then back at 0.2 m/s for 1.5 s (the box, slowed by friction, stays behind).
  const auto hip = [](double t) {
    const double x = -0.08 + 0.1 * std::min(t, 2.0) - 0.2 * std::clamp(t - 2.2, 0.0, 1.5);
    return V(x, kSide_m / 2, 0.0);
  };
  const verify::MovingDrive d = rig.drive(hip, 3800);
  EXPECT_EQ(d.crossings, 0u);
  EXPECT_EQ(d.inside, 0u);
  EXPECT_EQ(d.not_followed, 0u);
  EXPECT_EQ(d.free_force, 0u);
  EXPECT_GT(d.pushes + d.contact_ticks, 1000u);
  // It was pushed: about as far as the hand went past the face (0.17 m), less the
  // spring's compression.
  EXPECT_GT(box_x(d, 2199), 0.14);
  EXPECT_LT(box_x(d, 2199), 0.18);
  // Sliding, the hand feels the floor's friction through the box: mu m g on average.
  double sum_N = 0.0;
  for (std::size_t k = 1000; k < 2000; ++k) sum_N += d.out[k].force_W.x();
  EXPECT_NEAR(-sum_N / 1000.0, kFrictionForce_N, 0.2 * kFrictionForce_N);
  // Backed off, the box stays, the proxy is at the hand and there is no force.
  const ProxyOutput& last = d.out.back();
  EXPECT_FALSE(last.in_contact);
  EXPECT_EQ(last.force_W, V::Zero());
  EXPECT_EQ(last.proxy_W, hip(3.8));
  EXPECT_NEAR(box_x(d, d.out.size() - 1), box_x(d, 2199), 0.01);
  EXPECT_NEAR(d.X_WO.back()[1].translation().y(), kSide_m / 2, 5e-4) << "the box stays on the floor";
}

TEST(PushedBox, AHandHeldStillAgainstTheBoxBelowFrictionDoesNotMoveIt) {
  PushRig rig;
  // 1 mm into the face: 1 N, half of mu m g.
  const verify::MovingDrive d = rig.drive([](double t) { return V(-0.052 + 0.003 * std::min(t / 0.1, 1.0), kSide_m / 2, 0); }, 1000);
  EXPECT_EQ(d.crossings, 0u);
  ASSERT_TRUE(d.out.back().in_contact);
  EXPECT_NEAR(-d.out.back().force_W.x(), 1.0, 0.05);
  EXPECT_NEAR(box_x(d, d.out.size() - 1), 0.0, 2e-4);
}

// A kinematic hand (the stiffest a user can be) pushing at constant speed V: the box
// starts from rest, so it oscillates about the hand's speed at omega = sqrt(k / m); each
// time it comes to rest it sticks, so with no damping the force keeps swinging by about
// 2 k V / omega (the undamped spring's own limit cycle, not an instability), and with
// damping the swing dies out. Either way the force stays bounded and never grows.
struct SteadyPush {
  std::vector<double> p2p_N;  // peak-to-peak force, per second
  double max_N = 0.0;
  double box_x_m = 0.0;
  std::size_t crossings = 0, inside = 0;
};
SteadyPush push_steadily(double damping_Ns_per_m, double v_mps) {
  PushRig rig;
  for (HapticMaterial& m : rig.materials) m.damping_Ns_per_m = damping_Ns_per_m;
  const verify::MovingDrive d = rig.drive([&](double t) { return V(-0.055 + v_mps * t, kSide_m / 2, 0); }, 5000);
  SteadyPush r;
  r.crossings = d.crossings;
  r.inside = d.inside;
  for (std::size_t s = 0; s < 5; ++s) {
    double lo = 1e9, hi = -1e9;
    for (std::size_t k = s * 1000; k < s * 1000 + 1000; ++k) {
      lo = std::min(lo, d.out[k].force_W.x());
      hi = std::max(hi, d.out[k].force_W.x());
    }
    r.p2p_N.push_back(hi - lo);
  }
  for (const ProxyOutput& o : d.out) r.max_N = std::max(r.max_N, o.force_W.norm());
  r.box_x_m = box_x(d, 4999);
  return r;
}

TEST(PushedBox, PushingSteadilyAtTheDefaultStiffnessStaysBoundedWithoutGrowingOscillation) {
  const double v_mps = 0.05;
  const double swing_N = 2.0 * 1000.0 * v_mps / std::sqrt(1000.0 / kMass_kg);  // 2 k V / omega = 2.2 N
  const SteadyPush undamped = push_steadily(0.0, v_mps);  // the default material
  EXPECT_EQ(undamped.crossings, 0u);
  EXPECT_EQ(undamped.inside, 0u);
  EXPECT_LT(undamped.max_N, kFrictionForce_N + swing_N) << "bounded: the push never runs away";
  for (std::size_t s = 1; s < 5; ++s) {
    EXPECT_LE(undamped.p2p_N[s], std::max(undamped.p2p_N[0], 1.2 * swing_N)) << "second " << s << ": no growth";
  }
  EXPECT_GT(undamped.box_x_m, 0.15) << "the box went with the hand";

  const SteadyPush damped = push_steadily(2.0, v_mps);
  EXPECT_EQ(damped.crossings, 0u);
  EXPECT_LT(damped.p2p_N[4], 0.5 * damped.p2p_N[0]) << "damped, the swing dies out";
  EXPECT_GT(damped.box_x_m, 0.15);
}

}  // namespace
}  // namespace mhd
