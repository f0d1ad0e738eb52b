// The reaction of the hand's force on the touched objects: all of -F on the one object
// touched, shared by load between two (a box's side and the floor), adding up to -F; none
// without a contact or a force.

#include "proxy/contact_reaction.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mhd {
namespace {

using V = Eigen::Vector3d;

ProxyState touching(std::initializer_list<std::pair<int, V>> planes) {
  ProxyState s;
  for (const auto& [object, normal] : planes) {
    ConstraintPlane& p = s.planes[static_cast<std::size_t>(s.plane_count++)];
    p.normal_W = normal;
    p.triangle.object = object;
  }
  return s;
}

TEST(ContactReaction, OneTouchedObjectTakesAllOfMinusF) {
  const ContactReactions r = contact_reactions(touching({{1, V(-1, 0, 0)}}), V(-2.0, 0.3, 0.0));
  ASSERT_EQ(r.count, 1);
  EXPECT_EQ(r.on[0].object, 1);
  EXPECT_LT((r.on[0].f_W_N - V(2.0, -0.3, 0.0)).norm(), 1e-12);
  // Two planes of the same object (an edge): still one reaction, all of -F.
  const ContactReactions edge = contact_reactions(touching({{1, V(-1, 0, 0)}, {1, V(0, 1, 0)}}), V(-2.0, 1.0, 0.0));
  ASSERT_EQ(edge.count, 1);
  EXPECT_LT((edge.on[0].f_W_N - V(2.0, -1.0, 0.0)).norm(), 1e-12);
}

TEST(ContactReaction, TwoObjectsShareMinusFByTheLoadOnTheirPlanes) {
  // The proxy in the corner of the floor (object 0, normal +y) and a box's -x face
  // (object 1): the hand pushes 3 N into the box and 1 N into the floor.
  const ContactReactions r = contact_reactions(touching({{0, V(0, 1, 0)}, {1, V(-1, 0, 0)}}), V(-3.0, 1.0, 0.0));
  ASSERT_EQ(r.count, 2);
  EXPECT_LT((r.on[0].f_W_N - 0.25 * V(3.0, -1.0, 0.0)).norm(), 1e-12);
  EXPECT_LT((r.on[1].f_W_N - 0.75 * V(3.0, -1.0, 0.0)).norm(), 1e-12);
  EXPECT_LT((r.on[0].f_W_N + r.on[1].f_W_N - V(3.0, -1.0, 0.0)).norm(), 1e-12);
}

TEST(ContactReaction, NoContactOrNoForcePushesNothing) {
  EXPECT_EQ(contact_reactions(ProxyState{}, V(1, 0, 0)).count, 0);
  EXPECT_EQ(contact_reactions(touching({{1, V(-1, 0, 0)}}), V::Zero()).count, 0);
  EXPECT_EQ(contact_reactions(touching({{1, V(-1, 0, 0)}}), V(std::nan(""), 0, 0)).count, 0);
}

}  // namespace
}  // namespace mhd
