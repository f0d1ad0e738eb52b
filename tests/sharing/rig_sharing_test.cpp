// One rig's part in sharing objects (RigSharing), two rigs wired back to back with no
// link between them: the authority's states move the replica, and the replica's push
// moves the authority's body; states from rigs that may not speak are ignored; a stale
// replica's force fades and comes back; and declarations the scene check refuses throw.

#include "geometry/primitive_mesh.h"
#include "proxy/moving_world.h"
#include "sharing/rig_sharing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace mhd::rig_sharing_test {

using V = Eigen::Vector3d;

constexpr int kFloor = 0, kBox = 1;
constexpr std::uint32_t kBoxId = 7;
constexpr double kDt_s = 0.001;

std::shared_ptr<const MeshBvh> shape_of(TriangleMesh mesh) {
  return std::make_shared<MeshBvh>(std::make_shared<TriangleMesh>(std::move(mesh)));
}

// A 0.4 m box resting on a floor at y = 0, its centre at the origin's x, z.
CollisionWorld box_on_floor() {
  CollisionWorld world;
  Pose X_WF = Pose::Identity();
  X_WF.linear() = Eigen::AngleAxisd(-std::numbers::pi / 2, V::UnitX()).toRotationMatrix();
  world.add_object(shape_of(make_plane_mesh(8.0, 8.0)), X_WF);
  Pose X_WO = Pose::Identity();
  X_WO.translation() = V(0.0, 0.2, 0.0);
  world.add_object(shape_of(make_box_mesh(V::Constant(0.4))), X_WO);
  return world;
}

std::vector<SharedObjectDeclaration> the_box(std::initializer_list<std::uint32_t> rigs) {
  SharedObjectDeclaration d;
  d.object = kBox;
  d.id = kBoxId;
  for (const std::uint32_t r : rigs) d.rigs[static_cast<std::size_t>(d.rig_count++)] = r;
  return {d};
}

// One rig: its sharing and its world, the box a body (authority) or driven (replica).
struct Rig {
  RigSharing sharing;
  MovingWorld moving;
  ProxyState proxy;
  std::vector<HapticMaterial> materials{2};
  ProxySettings settings;

  Rig(std::uint32_t rig_id, const CollisionWorld& world)
      : sharing(rig_id, the_box({1, 2}), world), moving(world_of(sharing, world)) {
    reset_proxy(proxy, V(0.0, 0.2, 0.5));  // 0.3 m in front of the box's +z face
    settings.max_force_N = 8.5;
  }

  static MovingWorld world_of(const RigSharing& sharing, const CollisionWorld& world) {
    const std::vector<char> replica = sharing.replicas(2);
    const bool driven[2] = {replica[0] != 0, replica[1] != 0};
    std::vector<std::optional<ObjectDynamics>> dynamics{std::nullopt, ObjectDynamics{1.0, 0.4}};
    if (driven[kBox]) dynamics[kBox].reset();
    return MovingWorld(world, std::vector<std::optional<ObjectMotion>>(2), dynamics, std::span<const bool>(driven, 2));
  }

  // One tick with the hand at p_W_hip: what the haptic tick does, in its order.
  V tick(double t_s, const V& p_W_hip) {
    sharing.before_move(t_s, moving);
    (void)moving.advance(t_s, proxy, settings.skin_m);
    const ProxyOutput out = step_proxy(moving.world(), materials, settings, proxy, p_W_hip, kDt_s, moving.twists());
    const V force_W = out.force_W * sharing.force_gain(t_s, kDt_s, proxy, out.force_W);
    moving.apply_reaction(proxy, force_W);
    sharing.after_render(t_s, proxy, force_W, moving);
    return force_W;
  }

  [[nodiscard]] V p_W_box() const { return moving.world().pose(kBox).translation(); }
};

// Hands the outbox of `from` to `to`, as a link of no delay would.
void deliver(const Rig& from, Rig& to, double now_s) {
  for (const SharingMessage& m : from.sharing.outbox()) {
    if (m.kind == SharingMessage::Kind::State) {
      to.sharing.receive_state(m.object_id, m.state, now_s);
    } else {
      to.sharing.receive_push(m.object_id, m.push);
    }
  }
}

TEST(RigSharing, TheFirstRigListedHoldsTheObjectAndTheOthersRenderReplicas) {
  const CollisionWorld world = box_on_floor();
  const RigSharing one(1, the_box({1, 2}), world);
  const RigSharing two(2, the_box({1, 2}), world);
  EXPECT_TRUE(one.holds(kBox));
  EXPECT_FALSE(two.holds(kBox));
  EXPECT_EQ(one.replicas(2), (std::vector<char>{0, 0}));
  EXPECT_EQ(two.replicas(2), (std::vector<char>{0, 1}));
  EXPECT_FALSE(one.holds(kFloor));  // not shared
}

TEST(RigSharing, ThePushOfTheReplicasUserMovesTheAuthoritysBoxAndTheReplicaFollows) {
  const CollisionWorld world = box_on_floor();
  Rig one(1, world), two(2, world);
  // Rig 2's hand goes 5 cm into the box's +z face and stays: 50 N at 1000 N/m, clamped
  // to 8.5 N, past the friction of 0.4 x 1 kg x g = 3.9 N. Rig 1's hand stays away.
  bool pushed = false;
  for (int k = 1; k <= 1500; ++k) {
    const double t_s = k * kDt_s;
    (void)one.tick(t_s, V(0.0, 0.2, 0.6));
    deliver(one, two, t_s);
    const V f_W = two.tick(t_s, two.p_W_box() + V(0.0, 0.0, 0.15));
    deliver(two, one, t_s);
    if (f_W.norm() > 5.0) pushed = true;
    // The replica never strays from the authority's box by more than a tick's motion.
    ASSERT_LT((two.p_W_box() - one.p_W_box()).norm(), 0.01) << k;
  }
  EXPECT_TRUE(pushed);
  EXPECT_LT(one.p_W_box().z(), -0.2);  // pushed along -z by rig 2's user alone
  EXPECT_GT(one.sharing.counters().pushes_kept, 1000u);
  EXPECT_GT(two.sharing.counters().states_obeyed, 1400u);
  EXPECT_EQ(one.sharing.counters().states_obeyed, 0u);
  EXPECT_EQ(two.sharing.counters().states_sent, 0u);
}

TEST(RigSharing, WithoutTheReplicasPushTheSameHandLeavesTheAuthoritysBox) {
  // The dual: the pushes are what moved it. Rig 2 pushes as before, nothing delivered.
  const CollisionWorld world = box_on_floor();
  Rig one(1, world), two(2, world);
  for (int k = 1; k <= 1500; ++k) {
    const double t_s = k * kDt_s;
    (void)one.tick(t_s, V(0.0, 0.2, 0.6));
    deliver(one, two, t_s);
    (void)two.tick(t_s, two.p_W_box() + V(0.0, 0.0, 0.15));
  }
  EXPECT_LT((one.p_W_box() - V(0.0, 0.2, 0.0)).norm(), 1e-3);
  EXPECT_GT(two.sharing.counters().pushes_sent, 1000u);
}

TEST(RigSharing, ALetGoIsSaidOnceAndThenNothingIsSent) {
  const CollisionWorld world = box_on_floor();
  Rig two(2, world);
  int pushes_while_away = 0;
  for (int k = 1; k <= 300; ++k) {
    const double t_s = k * kDt_s;
    // In the box for 0.1 s, then 0.3 m away.
    (void)two.tick(t_s, k <= 100 ? V(0.0, 0.2, 0.17) : V(0.0, 0.2, 0.6));
    if (k > 150) pushes_while_away += static_cast<int>(two.sharing.outbox().size());
  }
  EXPECT_EQ(pushes_while_away, 0);
  const std::uint64_t sent = two.sharing.counters().pushes_sent;
  EXPECT_GT(sent, 50u);
  EXPECT_LT(sent, 120u);  // the pushes while in contact, and one zero
}

TEST(RigSharing, StatesFromRigsThatMayNotSpeakAndPushesForObjectsHeldElsewhereAreIgnored) {
  const CollisionWorld world = box_on_floor();
  RigSharing two(2, the_box({1, 2}), world);
  SharedObjectState s;
  s.authority_rig = 3;  // not on the box's list
  s.sequence = 1;
  s.t_s = 0.01;
  s.X_WO.translation() = V(1.0, 0.2, 0.0);
  two.receive_state(kBoxId, s, 0.01);
  s.authority_rig = 1;
  two.receive_state(kBoxId + 1, s, 0.01);  // an id this scene does not share
  EXPECT_EQ(two.counters().states_obeyed, 0u);
  EXPECT_EQ(two.counters().states_ignored, 1u);
  EXPECT_EQ(two.counters().unknown_object, 1u);
  // The replica's holder gets pushes; a rig that holds nothing does not.
  two.receive_push(kBoxId, SharedPush{-1, 1, 1, 0.01, V(1.0, 0.0, 0.0), V::Zero()});
  EXPECT_EQ(two.counters().pushes_ignored, 1u);
  // The authority obeys its own rigs' pushes, never a push "from itself".
  RigSharing one(1, the_box({1, 2}), world);
  one.receive_push(kBoxId, SharedPush{-1, 1, 1, 0.01, V(1.0, 0.0, 0.0), V::Zero()});
  one.receive_push(kBoxId, SharedPush{-1, 2, 1, 0.01, V(1.0, 0.0, 0.0), V::Zero()});
  EXPECT_EQ(one.counters().pushes_ignored, 1u);
  EXPECT_EQ(one.counters().pushes_kept, 1u);
  // A state for the object the rig holds is never obeyed, not even one of a later term
  // from a rig that may hold it: this rig runs the object's body for the whole run.
  s.authority_rig = 2;
  s.epoch = 5;
  one.receive_state(kBoxId, s, 0.01);
  EXPECT_EQ(one.counters().states_obeyed, 0u);
  EXPECT_EQ(one.counters().states_ignored, 1u);
  EXPECT_TRUE(one.holds(kBox));
}

TEST(RigSharing, AStaleReplicasForceFadesOutAndFreshStatesBringItBack) {
  const CollisionWorld world = box_on_floor();
  Rig one(1, world), two(2, world);
  std::vector<double> force_N;
  for (int k = 1; k <= 1200; ++k) {
    const double t_s = k * kDt_s;
    (void)one.tick(t_s, V(0.0, 0.2, 0.6));
    // The link is cut over [0.3, 0.7) s.
    if (t_s < 0.3 || t_s >= 0.7) deliver(one, two, t_s);
    // Rig 2's hand rests 1 mm inside the face: about 1 N, too little to move the box.
    force_N.push_back(two.tick(t_s, V(0.0, 0.2, 0.199)).norm());
  }
  EXPECT_NEAR(force_N[250], 1.0, 0.3);       // fresh: the full force
  EXPECT_LT(force_N[300 + 200 + 10], 1e-9);  // stale for 0.1 s, faded for 0.1 s: none
  EXPECT_NEAR(force_N[700 + 150], 0.5 * force_N[250], 0.2);  // half way back in 0.3 s
  EXPECT_NEAR(force_N[1150], force_N[250], 0.05);            // and all the way
}

TEST(RigSharing, DeclarationsTheSceneCheckRefusesThrow) {
  const CollisionWorld world = box_on_floor();
  EXPECT_THROW(RigSharing(3, the_box({1, 2}), world), std::invalid_argument);  // not on the list
  std::vector<SharedObjectDeclaration> twice = the_box({1, 2});
  twice.push_back(twice.front());
  EXPECT_THROW(RigSharing(1, twice, world), std::invalid_argument);
  std::vector<SharedObjectDeclaration> outside = the_box({1, 2});
  outside[0].object = 2;
  EXPECT_THROW(RigSharing(1, outside, world), std::invalid_argument);
  std::vector<SharedObjectDeclaration> no_rigs = the_box({});
  EXPECT_THROW(RigSharing(1, no_rigs, world), std::invalid_argument);
  EXPECT_NO_THROW(RigSharing(2, the_box({1, 2}), world));  // the dual: a good one
}

}  // namespace mhd::rig_sharing_test
