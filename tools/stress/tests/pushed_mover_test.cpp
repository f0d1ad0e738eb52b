// PushedMover (pushed_mover.h) alone: a thrown floating body flies at its throw, the
// hand-held frame the strokes follow keeps up with it when it is slower than a hand and
// trails it at the hand's top speed when it is faster (both halves), and a restart puts
// the body back and throws it again.

#include "stress/pushed_mover.h"

#include "stress_test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

namespace mhd::stress {
namespace {

using Eigen::Vector3d;

std::unique_ptr<CompiledScene> floating_cube() {
  SceneDescription d;
  d.name = "pushed_mover_test";
  ObjectDescription o;
  o.name = "cube";
  o.shape = BoxSource{Vector3d::Constant(0.1)};
  o.X_WO.translation() = Vector3d(0.0, 1.0, -0.5);
  d.objects.push_back(o);
  return test::compile_uncached(d);
}

constexpr double kDt_s = 1e-3;

// Advances `ticks` ticks with the proxy far away (nothing pushes).
void fly(PushedMover& mover, int ticks, double& t_s) {
  ProxyState proxy;
  reset_proxy(proxy, Vector3d(5.0, 5.0, 5.0));
  for (int k = 0; k < ticks; ++k) {
    t_s += kDt_s;
    (void)mover.advance(t_s, proxy, 1e-6, ProxyOutput{});
  }
}

TEST(PushedMover, TheHandFrameKeepsUpWithASlowBodyAndTrailsAFastOne) {
  const auto scene = floating_cube();
  ASSERT_TRUE(scene);
  const Vector3d p_W_start(0.0, 1.0, -0.5);
  for (const double throw_mps : {0.4, 3.0}) {
    SCOPED_TRACE(throw_mps);
    PushedBodyParams params;
    params.hand_speed_mps = 1.5;
    PushedMover mover(*scene, 0, ObjectTwist{Vector3d(throw_mps, 0.0, 0.0), Vector3d::Zero()}, params, kDt_s);
    double t_s = 0.0;
    fly(mover, 200, t_s);
    const Vector3d p_W_body = mover.world().pose(0).translation();
    EXPECT_NEAR(p_W_body.x(), throw_mps * 0.2, 1e-6);  // weightless: it keeps its throw
    EXPECT_NEAR(p_W_body.y(), 1.0, 1e-9);
    EXPECT_NEAR(mover.twists()[0].v_W_origin_mps.x(), throw_mps, 1e-9);
    const double hand_x_m = mover.X_WO_at(t_s).translation().x();
    if (throw_mps < params.hand_speed_mps) {
      EXPECT_NEAR(hand_x_m, p_W_body.x(), 1e-6);
    } else {
      EXPECT_NEAR(hand_x_m, params.hand_speed_mps * 0.2, 1e-6);
    }
    EXPECT_TRUE(mover.X_WO_at(0.0).translation().isApprox(p_W_start));
    EXPECT_NEAR(mover.X_WO_at(0.1).translation().x(), std::min(throw_mps, params.hand_speed_mps) * 0.1, 1e-6);

    mover.restart(t_s);  // back at the start, thrown again, its clock from t_s
    EXPECT_TRUE(mover.world().pose(0).translation().isApprox(p_W_start));
    fly(mover, 100, t_s);
    EXPECT_NEAR(mover.world().pose(0).translation().x(), throw_mps * 0.1, 1e-6);
  }
}

}  // namespace
}  // namespace mhd::stress
