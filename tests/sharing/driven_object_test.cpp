// A driven object (a replica) goes where drive() puts it and carries the proxy it meets,
// as any moving object does; it is out of the bodies' physics, and only a driven object
// can be driven.

#include "geometry/primitive_mesh.h"
#include "proxy/moving_world.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace mhd::driven_test {

using V = Eigen::Vector3d;

std::shared_ptr<const MeshBvh> shape_of(TriangleMesh mesh) {
  return std::make_shared<MeshBvh>(std::make_shared<TriangleMesh>(std::move(mesh)));
}

CollisionWorld two_boxes() {
  CollisionWorld world;
  world.add_object(shape_of(make_box_mesh(V::Constant(0.2))), Pose::Identity());
  Pose X_WO = Pose::Identity();
  X_WO.translation() = V(2.0, 0.0, 0.0);
  world.add_object(shape_of(make_box_mesh(V::Constant(0.2))), X_WO);
  return world;
}

TEST(DrivenObject, ItGoesWhereItIsDrivenAndCarriesTheProxyItMeets) {
  const bool driven[2] = {true, false};
  MovingWorld moving(two_boxes(), std::vector<std::optional<ObjectMotion>>(2), {}, std::span<const bool>(driven, 2));
  EXPECT_TRUE(moving.moves());
  ProxyState proxy;
  reset_proxy(proxy, V(0.3, 0.0, 0.0));  // 0.2 m beyond the box's +x face
  for (int k = 1; k <= 40; ++k) {
    Pose X_WO = Pose::Identity();
    X_WO.translation() = V(0.01 * k, 0.0, 0.0);
    moving.drive(0, X_WO, ObjectTwist{V(10.0, 0.0, 0.0), V::Zero()});
    (void)moving.advance(0.001 * k, proxy, 1e-6);
    EXPECT_EQ(moving.world().pose(0).translation().x(), 0.01 * k);
    EXPECT_EQ(moving.twists()[0].v_W_origin_mps.x(), 10.0);
    // Never inside: the face at 0.01 k + 0.1 pushes the proxy on once it reaches it.
    EXPECT_GE(proxy.proxy_W.x(), 0.01 * k + 0.1 - 1e-9) << k;
  }
  EXPECT_GT(proxy.proxy_W.x(), 0.45);
  // The other object is not driven: drive() leaves it.
  moving.drive(1, Pose::Identity(), ObjectTwist{});
  (void)moving.advance(0.05, proxy, 1e-6);
  EXPECT_EQ(moving.world().pose(1).translation().x(), 2.0);
}

TEST(DrivenObject, ADrivenObjectHasNoMotionOrDynamicsBesides) {
  const bool driven[2] = {true, false};
  std::vector<std::optional<ObjectMotion>> motions(2);
  motions[0] = ObjectMotion::twist(Pose::Identity(), V::UnitX(), V::Zero());
  EXPECT_THROW(MovingWorld(two_boxes(), motions, {}, std::span<const bool>(driven, 2)), std::invalid_argument);
  const std::vector<std::optional<ObjectDynamics>> dynamics{ObjectDynamics{}, std::nullopt};
  EXPECT_THROW(MovingWorld(two_boxes(), std::vector<std::optional<ObjectMotion>>(2), dynamics,
                           std::span<const bool>(driven, 2)),
               std::invalid_argument);
  const bool one[1] = {true};
  EXPECT_THROW(MovingWorld(two_boxes(), std::vector<std::optional<ObjectMotion>>(2), {}, std::span<const bool>(one, 1)),
               std::invalid_argument);
  // The dual: a body beside a driven object; the driven one is out of the physics.
  const std::vector<std::optional<ObjectDynamics>> other_is_body{std::nullopt, ObjectDynamics{}};
  const MovingWorld both(two_boxes(), std::vector<std::optional<ObjectMotion>>(2), other_is_body,
                         std::span<const bool>(driven, 2));
  ASSERT_NE(both.physics(), nullptr);
  EXPECT_FALSE(both.physics()->is_body(0));
  EXPECT_TRUE(both.physics()->is_body(1));
}

}  // namespace mhd::driven_test
