// The replica renders the authority's state carried on by its twist, exactly, up to its
// horizon and no further; a correction is blended in without a jump and is complete
// after blend_s.

#include "sharing/object_replica.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

namespace mhd::replica_test {

using V = Eigen::Vector3d;

SharedObjectState moving_state(double t_s, const V& p_W, const V& v_W, const V& omega_W) {
  SharedObjectState s;
  s.object = 0;
  s.t_s = t_s;
  s.X_WO.translation() = p_W;
  s.twist_W.v_W_origin_mps = v_W;
  s.twist_W.omega_W_radps = omega_W;
  return s;
}

double angle_between(const Pose& a, const Pose& b) {
  return Eigen::AngleAxisd(a.linear() * b.linear().transpose()).angle();
}

TEST(ObjectReplica, DeadReckoningFollowsAConstantTwistUpToTheHorizonOnly) {
  ReplicaSettings settings;
  settings.blend_s = 0.0;
  settings.max_extrapolation_s = 0.1;
  ObjectReplica replica(Pose::Identity(), settings);
  EXPECT_FALSE(replica.has_state());
  EXPECT_TRUE(std::isinf(replica.age_s(0.0)));
  const V p0(1.0, 0.2, -0.5), v(0.4, 0.0, -0.3), omega(0.0, 2.0, 0.0);
  replica.accept(moving_state(1.0, p0, v, omega), 1.02);
  EXPECT_NEAR(replica.age_s(1.02), 0.02, 1e-12);
  for (const double dt_s : {0.0, 0.01, 0.05, 0.099}) {
    const Pose X = replica.X_WO_at(1.0 + dt_s);
    EXPECT_LT((X.translation() - (p0 + v * dt_s)).norm(), 1e-12) << dt_s;
    EXPECT_NEAR(angle_between(X, Pose::Identity()), 2.0 * dt_s, 1e-9) << dt_s;
    EXPECT_LT((replica.twist_at(1.0 + dt_s).v_W_origin_mps - v).norm(), 1e-12);
  }
  // Past the horizon the object holds where dead reckoning left it, still.
  const Pose X_held = replica.X_WO_at(1.1);
  for (const double t_s : {1.15, 2.0, 100.0}) {
    EXPECT_LT((replica.X_WO_at(t_s).translation() - X_held.translation()).norm(), 1e-12);
    EXPECT_LT(angle_between(replica.X_WO_at(t_s), X_held), 1e-12);
    EXPECT_EQ(replica.twist_at(t_s).v_W_origin_mps.norm(), 0.0);
    EXPECT_EQ(replica.twist_at(t_s).omega_W_radps.norm(), 0.0);
  }
}

TEST(ObjectReplica, ACorrectionIsBlendedInWithoutAJumpAndCompletes) {
  ReplicaSettings settings;
  settings.blend_s = 0.03;
  ObjectReplica replica(Pose::Identity(), settings);
  replica.accept(moving_state(0.0, V::Zero(), V(1.0, 0.0, 0.0), V::Zero()), 0.0);
  // The authority says the object stopped 5 cm further on, turned by 0.3 rad.
  SharedObjectState stopped = moving_state(0.05, V(0.15, 0.0, 0.0), V::Zero(), V::Zero());
  stopped.X_WO.linear() = Eigen::AngleAxisd(0.3, V::UnitY()).toRotationMatrix();
  const Pose before = replica.X_WO_at(0.06);
  replica.accept(stopped, 0.06);
  const Pose at_accept = replica.X_WO_at(0.06);
  EXPECT_LT((at_accept.translation() - before.translation()).norm(), 1e-12);
  EXPECT_LT(angle_between(at_accept, before), 1e-9);
  // Every step of the blend is a fraction of the whole, in order.
  double last_m = (at_accept.translation() - stopped.X_WO.translation()).norm();
  const double total_m = last_m;
  for (int k = 1; k <= 30; ++k) {
    const double t_s = 0.06 + 0.001 * k;
    const double gap_m = (replica.X_WO_at(t_s).translation() - stopped.X_WO.translation()).norm();
    EXPECT_LE(gap_m, last_m + 1e-12);
    EXPECT_LT(last_m - gap_m, total_m / 30.0 + 1e-9);  // the gap spread evenly
    last_m = gap_m;
  }
  EXPECT_LT((replica.X_WO_at(0.09).translation() - stopped.X_WO.translation()).norm(), 1e-12);
  EXPECT_LT(angle_between(replica.X_WO_at(0.09), stopped.X_WO), 1e-9);
  // While it blends, the replica moves, and says so (damping sees the motion).
  EXPECT_GT(replica.twist_at(0.07).v_W_origin_mps.x(), 0.5);
  EXPECT_EQ(replica.twist_at(0.1).v_W_origin_mps.norm(), 0.0);
}

TEST(ObjectReplica, TheFirstStateIsBlendedInFromTheScenesPose) {
  Pose X_WO_0 = Pose::Identity();
  X_WO_0.translation() = V(0.0, 0.2, 0.0);
  ObjectReplica replica(X_WO_0, ReplicaSettings{});
  EXPECT_LT((replica.X_WO_at(0.5).translation() - X_WO_0.translation()).norm(), 1e-12);
  replica.accept(moving_state(0.5, V(0.01, 0.2, 0.0), V::Zero(), V::Zero()), 0.5);
  EXPECT_LT((replica.X_WO_at(0.5).translation() - X_WO_0.translation()).norm(), 1e-12);
  EXPECT_NEAR(replica.X_WO_at(1.0).translation().x(), 0.01, 1e-12);
}

}  // namespace mhd::replica_test
