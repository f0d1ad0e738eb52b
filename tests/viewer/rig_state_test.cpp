// Display frames to rig states and back, the head convention, and the lock-free
// latest-value slot the haptic side publishes into.

#include "viewer/rig_state.h"
#include "viewer/state_source.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <thread>

namespace mhd::viewer {
namespace {

DisplayFrame sample_frame() {
  DisplayFrame f{};
  f.timestamp_s = 1.5;
  f.p_W_hip_m[0] = 0.1, f.p_W_hip_m[1] = 1.0, f.p_W_hip_m[2] = -0.5;
  f.p_W_proxy_m[0] = 0.1, f.p_W_proxy_m[1] = 1.01, f.p_W_proxy_m[2] = -0.5;
  f.force_W_N[1] = 2.0;
  f.in_contact = 1;
  f.base_x_m = 0.4, f.base_z_m = -0.2, f.base_heading_rad = 0.3;
  f.p_W_head_m[1] = 1.7;
  // A quarter turn about +y, not normalised (the reader normalises).
  f.q_W_head_wxyz[0] = 2.0 * std::cos(M_PI / 4.0);
  f.q_W_head_wxyz[2] = 2.0 * std::sin(M_PI / 4.0);
  return f;
}

TEST(RigState, FromDisplayFrameAndBack) {
  const Result<RigState, std::string> r = rig_state_from_frame(sample_frame());
  ASSERT_TRUE(r.ok()) << r.error_text();
  const RigState& s = *r;
  EXPECT_EQ(s.p_W_hip_m, Eigen::Vector3d(0.1, 1.0, -0.5));
  EXPECT_TRUE(s.in_contact);
  EXPECT_DOUBLE_EQ(s.base.heading_rad, 0.3);
  // Heading pi/2: the head's x (gaze) points along -z.
  EXPECT_TRUE((s.X_W_head.linear() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d(0, 0, -1), 1e-12));
  const DisplayFrame back = display_frame_from_rig_state(s);
  EXPECT_DOUBLE_EQ(back.p_W_proxy_m[1], 1.01);
  EXPECT_NEAR(back.q_W_head_wxyz[0], std::cos(M_PI / 4.0), 1e-12);
  EXPECT_NEAR(back.q_W_head_wxyz[2], std::sin(M_PI / 4.0), 1e-12);
  EXPECT_EQ(back.in_contact, 1);
}

TEST(RigState, NonFiniteOrZeroQuaternionIsRefusedWithTheField) {
  DisplayFrame f = sample_frame();
  f.force_W_N[2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(rig_state_from_frame(f).error(), "display frame: force_W_N[2] is not finite");
  f = sample_frame();
  for (double& q : f.q_W_head_wxyz) q = 0.0;
  const Result<RigState, std::string> r = rig_state_from_frame(f);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error(), "display frame: q_W_head_wxyz has zero norm");
}

TEST(RigState, HeadLookingAtIsRightHandedXForwardYUp) {
  const Pose X = head_looking_at({1.0, 1.7, 1.0}, {1.0, 0.7, 0.0});
  const Eigen::Matrix3d R = X.linear();
  EXPECT_TRUE(R.col(0).isApprox(Eigen::Vector3d(0, -1, -1).normalized(), 1e-12));
  EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
  EXPECT_GT(R.col(1).y(), 0.0);
  EXPECT_NEAR(R.col(2).y(), 0.0, 1e-12) << "no roll: the right axis stays level";
  // Straight down: falls back to looking along -z.
  EXPECT_TRUE(head_looking_at({0, 2, 0}, {0, 0, 0}).linear().col(0).isApprox(Eigen::Vector3d(0, 0, -1), 1e-12));
}

TEST(LatestStateSlot, EmptyUntilPublishedThenNewestWins) {
  LatestStateSlot slot;
  EXPECT_FALSE(slot.latest());
  RigState s;
  for (int i = 1; i <= 5; ++i) {
    s.timestamp_s = i;
    slot.publish(s);
  }
  ASSERT_TRUE(slot.latest());
  EXPECT_EQ(slot.latest()->timestamp_s, 5.0);
  EXPECT_EQ(slot.latest()->timestamp_s, 5.0) << "read again without a new publish: the same state";
  EXPECT_EQ(slot.published(), 5u);
}

TEST(LatestStateSlot, ConcurrentReaderNeverSeesATornOrOlderState) {
  LatestStateSlot slot;
  constexpr int kCount = 200000;
  std::thread writer([&] {
    RigState s;
    for (int i = 1; i <= kCount; ++i) {
      const double v = i;
      s.timestamp_s = v;
      s.p_W_hip_m = Eigen::Vector3d::Constant(v);
      s.force_W_N = Eigen::Vector3d::Constant(-v);
      s.base.x_m = v;
      slot.publish(s);
    }
  });
  double last = 0.0;
  int torn = 0, backwards = 0;
  while (last < kCount) {
    const std::optional<RigState> s = slot.latest();
    if (!s) continue;
    const double v = s->timestamp_s;
    if (s->p_W_hip_m != Eigen::Vector3d::Constant(v) || s->force_W_N != Eigen::Vector3d::Constant(-v) ||
        s->base.x_m != v) {
      ++torn;
    }
    if (v < last) ++backwards;
    last = v;
  }
  writer.join();
  EXPECT_EQ(torn, 0);
  EXPECT_EQ(backwards, 0);
  EXPECT_EQ(last, kCount);
}

}  // namespace
}  // namespace mhd::viewer
