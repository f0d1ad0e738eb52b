// The authority's inbox keeps each rig's newest push on each object, acting for hold_s
// and then no more: a rig that falls silent stops pushing. Refusals and their duals.

#include "sharing/remote_pushes.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace mhd::pushes_test {

SharedPush push_of(int object, std::uint32_t rig, std::uint64_t sequence, double t_s, double f_x_N) {
  SharedPush p;
  p.object = object;
  p.from_rig = rig;
  p.sequence = sequence;
  p.t_s = t_s;
  p.f_W_N = Eigen::Vector3d(f_x_N, 0.0, 0.0);
  return p;
}

std::vector<SharedPush> acting(const RemotePushes& inbox, double now_s) {
  std::vector<SharedPush> out;
  inbox.for_each_acting(now_s, [&](const SharedPush& p) { out.push_back(p); });
  return out;
}

TEST(RemotePushes, TheNewestPushOfEachRigActsUntilItIsHoldOld) {
  RemotePushes inbox(RemotePushSettings{0.05});
  EXPECT_TRUE(inbox.receive(push_of(1, 2, 1, 1.000, 3.0)));
  EXPECT_TRUE(inbox.receive(push_of(1, 2, 2, 1.001, 4.0)));
  EXPECT_FALSE(inbox.receive(push_of(1, 2, 1, 1.000, 9.0)));  // late, older
  EXPECT_TRUE(inbox.receive(push_of(1, 3, 1, 1.001, -1.0)));  // another rig, same object
  EXPECT_TRUE(inbox.receive(push_of(2, 2, 3, 1.001, 0.5)));   // same rig, another object
  auto now = acting(inbox, 1.02);
  ASSERT_EQ(now.size(), 3u);
  EXPECT_EQ(now[0].f_W_N.x(), 4.0);
  EXPECT_EQ(now[1].f_W_N.x(), -1.0);
  EXPECT_EQ(now[2].f_W_N.x(), 0.5);
  EXPECT_EQ(acting(inbox, 1.0505).size(), 3u);  // just under hold_s old: still acting
  EXPECT_TRUE(acting(inbox, 1.0511).empty());  // the senders fell silent
  // A sender heard again pushes again.
  EXPECT_TRUE(inbox.receive(push_of(1, 2, 4, 2.0, 2.0)));
  now = acting(inbox, 2.01);
  ASSERT_EQ(now.size(), 1u);
  EXPECT_EQ(now[0].f_W_N.x(), 2.0);
  EXPECT_EQ(inbox.refused(), 1u);
}

TEST(RemotePushes, BrokenPushesAndAFullTableAreRefused) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  RemotePushes inbox;
  SharedPush p = push_of(0, 1, 1, kNaN, 1.0);
  EXPECT_FALSE(inbox.receive(p));
  p = push_of(0, 1, 1, 0.0, kInf);
  EXPECT_FALSE(inbox.receive(p));
  p = push_of(0, 1, 1, 0.0, 1.0);
  p.p_O_m.z() = kNaN;
  EXPECT_FALSE(inbox.receive(p));
  EXPECT_FALSE(inbox.receive(push_of(-1, 1, 1, 0.0, 1.0)));
  EXPECT_EQ(inbox.refused(), 4u);
  for (int object = 0; object < kMaxRemotePushes; ++object) EXPECT_TRUE(inbox.receive(push_of(object, 1, 1, 0.0, 1.0)));
  EXPECT_FALSE(inbox.receive(push_of(kMaxRemotePushes, 1, 1, 0.0, 1.0)));
  EXPECT_TRUE(inbox.receive(push_of(0, 1, 2, 0.0, 1.0)));  // a known pair still updates
  EXPECT_EQ(inbox.refused(), 5u);
  EXPECT_EQ(acting(inbox, 0.0).size(), static_cast<std::size_t>(kMaxRemotePushes));
}

}  // namespace mhd::pushes_test
