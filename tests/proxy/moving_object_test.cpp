// Moving objects and the proxy (docs/proxy.md "Moving objects"), judged by the exact
// oracle in each object's own frame: relative to a moving object the proxy's motion over
// a tick is the chord from where it was (in the object's old pose) to where it is carried
// (in the new pose), then the legs of its step; none of them may touch the surface.
// Both halves: a surface that reaches the proxy pushes it (and the hand feels it), and a
// surface that leaves gives the proxy back to the hand with zero force.

#include "proxy/moving_world.h"

#include "proxy_test_rig.h"

#include "geometry/primitive_mesh.h"
#include "verification/moving_drive.h"
#include "verification/surface_crossing_oracle.h"

#include <gtest/gtest.h>

#include <numbers>

namespace mhd {
namespace {

using V = Eigen::Vector3d;
constexpr double kMovingDt_s = test::kProxyTestDt_s;
constexpr double kSkin_m = 1e-6;

Pose at_x(double x) {
  Pose X = Pose::Identity();
  X.translation() = V(x, 0, 0);
  return X;
}

struct MovingRig {
  TriangleMesh box = make_box_mesh(V::Constant(0.1));
  CollisionWorld world;
  std::vector<HapticMaterial> materials;
  ProxySettings settings;
  std::vector<std::optional<ObjectMotion>> motions;

  MovingRig() { settings.max_force_N = 1e6; }
  void add(TriangleMesh mesh, std::optional<ObjectMotion> motion, const HapticMaterial& mat = test::stiff(1000.0)) {
    world.add_object(test::shape_of(std::move(mesh)), motion ? motion->X_WO_at(0.0) : Pose::Identity());
    motions.push_back(std::move(motion));
    materials.push_back(mat);
  }
};

// Steps `rig` through hip(t) for n ticks from t = 0, every object following its motion,
// judged by verify::drive_moving_proxy.
template <class Hip>
verify::MovingDrive drive(MovingRig& rig, Hip&& hip, int n) {
  std::vector<V> path;
  for (int k = 0; k <= n; ++k) path.push_back(hip(k * kMovingDt_s));
  return verify::drive_moving_proxy(rig.world, rig.motions, rig.materials, rig.settings, path, 1.0 / kMovingDt_s);
}

TEST(MovingObject, AnApproachingFacePushesTheProxyAndLetsItGoWhenItLeaves) {
  // A 0.1 m box comes at the still hand at 0.5 m/s along +x, stops with its face 10 mm
  // past the hand, and goes back. Its face (x = centre + 0.05) reaches x = 0 at 0.26 s.
  MovingRig rig;
  rig.add(rig.box, ObjectMotion::keyframes({{0.0, at_x(-0.2)}, {0.32, at_x(-0.04)}, {0.5, at_x(-0.04)}, {0.82, at_x(-0.2)}},
                                           MotionRepeat::Hold));
  const V hip(0, 0.01, 0.02);
  const verify::MovingDrive d = drive(rig, [&](double) { return hip; }, 1000);
  EXPECT_EQ(d.crossings, 0u);
  EXPECT_EQ(d.inside, 0u);
  EXPECT_EQ(d.not_followed, 0u);
  EXPECT_EQ(d.free_force, 0u);
  EXPECT_GT(d.pushes, 0u);
  // Held at 0.4 s: the proxy rides the face 10 mm out, and the hand is pushed by k * 10 mm.
  const ProxyOutput& held = d.out[399];
  EXPECT_TRUE(held.in_contact);
  EXPECT_NEAR(held.proxy_W.x(), 0.01 + kSkin_m, 2e-6);
  EXPECT_NEAR(held.force_W.x(), 1000.0 * 0.01, 0.01);
  EXPECT_LT(held.force_W.tail<2>().norm(), 1e-6);
  // Before the face arrives and after it has left: at the hand, no force.
  EXPECT_FALSE(d.out[200].in_contact);
  EXPECT_EQ(d.out[200].force_W, V::Zero());
  EXPECT_EQ(d.out.back().proxy_W, hip);
  EXPECT_EQ(d.out.back().force_W, V::Zero());
}

TEST(MovingObject, AProxyPressedOnATurningBoxRidesItAndNeverEntersIt) {
  // The box spins at 180 deg/s about z; the hand presses 5 mm into its top face.
  MovingRig rig;
  rig.add(rig.box, ObjectMotion::twist(Pose::Identity(), V::Zero(), V(0, 0, std::numbers::pi)));
  // The hand comes down from 20 mm above in 0.1 s, then stays 5 mm deep.
  auto hip = [](double t) { return V(0.02, 0.01, 0.07 - 0.25 * std::min(t, 0.1)); };
  const verify::MovingDrive d = drive(rig, hip, 2000);
  EXPECT_EQ(d.crossings, 0u);
  EXPECT_EQ(d.inside, 0u);
  for (std::size_t k = 150; k < d.out.size(); ++k) {
    ASSERT_TRUE(d.out[k].in_contact) << "tick " << k;
    EXPECT_NEAR(d.out[k].force_W.z(), 1000.0 * 0.005, 1e-3) << "tick " << k;
  }
}

TEST(MovingObject, ASpinningBoxsCornersSweepPastAHandBesideIt) {
  // The hand 60 mm from the spin axis: the box's faces (50 mm) miss it, its corners
  // (70.7 mm) sweep through it twice a turn. The proxy is pushed round by each corner,
  // and between corners it is back at the hand with zero force.
  MovingRig rig;
  rig.add(rig.box, ObjectMotion::twist(Pose::Identity(), V::Zero(), V(0, 0, std::numbers::pi)));
  const V hip(0.06, 0.0, 0.0);
  const verify::MovingDrive d = drive(rig, [&](double) { return hip; }, 2000);
  EXPECT_EQ(d.crossings, 0u);
  EXPECT_EQ(d.inside, 0u);
  EXPECT_EQ(d.not_followed, 0u);
  EXPECT_EQ(d.free_force, 0u);
  std::size_t contact = 0;
  for (const ProxyOutput& o : d.out) contact += o.in_contact ? 1 : 0;
  EXPECT_GT(contact, 100u);
  EXPECT_LT(contact, 1900u);
}

TEST(MovingObject, AProxySqueezedAgainstAStillWallStaysOutOfTheWall) {
  // A still box (the wall) at x in [0.02, 0.12], a moving box coming at the hand from
  // -x: the proxy is pushed to the wall and held there; the squeeze is reported.
  MovingRig rig;
  rig.add(rig.box, ObjectMotion::keyframes({{0.0, at_x(-0.2)}, {0.4, at_x(0.0)}}, MotionRepeat::Hold));
  TriangleMesh wall = make_box_mesh(V::Constant(0.1));
  for (V& v : wall.vertices_m) v.x() += 0.07;
  rig.add(wall, std::nullopt);
  const V hip(0.0, 0.0, 0.0);
  const verify::MovingDrive d = drive(rig, [&](double) { return hip; }, 500);
  EXPECT_GT(d.squeezes, 0u);
  // The wall is never crossed (the moving box may have to overlap the proxy: reported).
  const verify::SurfaceCrossingOracle wall_oracle(wall);
  for (const ProxyOutput& o : d.out) EXPECT_FALSE(wall_oracle.point_inside_closed_mesh(o.proxy_W));
  for (std::size_t k = 1; k < d.out.size(); ++k) {
    ASSERT_FALSE(wall_oracle.segment_touches_surface(d.out[k - 1].proxy_W, d.out[k].proxy_W)) << "tick " << k;
  }
}

TEST(MovingObject, DampingActsOnTheVelocityRelativeToTheSurface) {
  // The box's face (normal +x) at x = -0.15. A hand held 5 mm inside the face as it moves
  // at 0.1 m/s, moving with it, feels the spring alone; a hand
  // pushing into the still face at 0.1 m/s feels the spring plus b * v.
  HapticMaterial damped = test::stiff(1000.0);
  damped.damping_Ns_per_m = 5.0;
  const double v = 0.1;
  MovingRig moving;
  moving.add(moving.box, ObjectMotion::twist(at_x(-0.2), V(v, 0, 0), V::Zero()), damped);
  // The face comes at the still hand for 0.1 s (reaching 5 mm past it), then the hand
  // moves with it.
  const verify::MovingDrive with_face = drive(moving, [&](double t) { return V(-0.145 + v * std::max(t - 0.1, 0.0), 0, 0); }, 200);
  const ProxyOutput riding = with_face.out.back();
  ASSERT_TRUE(riding.in_contact);
  EXPECT_NEAR(riding.force_W.x(), 1000.0 * 0.005, 1e-3);  // spring only
  EXPECT_EQ(with_face.crossings, 0u);

  MovingRig still;
  still.add(still.box, std::nullopt, damped);
  still.world.set_pose(0, at_x(-0.2));
  const verify::MovingDrive into_face = drive(still, [&](double t) { return V(-0.145 - v * t, 0, 0); }, 200);
  const ProxyOutput pressing = into_face.out.back();
  ASSERT_TRUE(pressing.in_contact);
  EXPECT_NEAR(pressing.force_W.x(), 1000.0 * 0.015 + 5.0 * v, 0.02);  // spring and damper
}

}  // namespace
}  // namespace mhd
