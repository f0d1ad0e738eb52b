// The checker must be able to fail: a "proxy" that is really the HIP, one that jumps
// over an object in one tick, one whose path dips behind a sheet, are all caught; a
// proxy that keeps its skin is not. Both halves: a proxy that stays put while the HIP
// moves away in free space, or that renders a force with the HIP in free view, is a
// follow failure; a sheet held between proxy and HIP is not.

#include "stress/popthrough_check.h"

#include "collision/mesh_bvh.h"
#include "geometry/primitive_mesh.h"
#include "verification/stroke_set.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <memory>
#include <vector>

namespace mhd::stress {
namespace {

using Eigen::Vector3d;

// A stand-in proxy on the HIP itself with no force (so it always "follows"): one tick to p.
TickVerdict at_hip(PopThroughChecker& checker, const Vector3d& p, bool in_contact) {
  return checker.check_tick(p, {}, p, Vector3d::Zero(), in_contact);
}

// A closed 0.2 m box at the origin (object 0) and an open 0.2 m sheet in z = 0 centred
// on x = 0.5 (object 1).
struct BoxAndSheet {
  CollisionWorld world;
  std::unique_ptr<verify::SurfaceCrossingOracle> oracle;
  BoxAndSheet() {
    world.add_object(std::make_shared<MeshBvh>(std::make_shared<TriangleMesh>(make_box_mesh({0.2, 0.2, 0.2}))),
                     Pose::Identity());
    Pose X_WS = Pose::Identity();
    X_WS.translation() = Vector3d(0.5, 0.0, 0.0);
    world.add_object(std::make_shared<MeshBvh>(std::make_shared<TriangleMesh>(make_plane_mesh(0.2, 0.2))), X_WS);
    oracle = std::make_unique<verify::SurfaceCrossingOracle>(world);
  }
};

TEST(PopThroughChecker, HipUsedAsProxyIsCaughtInsideAndCrossing) {
  const BoxAndSheet s;
  ASSERT_TRUE(s.oracle->is_closed(0));
  ASSERT_FALSE(s.oracle->is_closed(1));
  PopThroughChecker checker(s.world, *s.oracle, EngineContainment::Every);
  // 1.5 m/s at 1 kHz straight through the box (no sample lands on a face).
  const std::array<Vector3d, 2> corners{Vector3d(-0.3, 0.01, 0.02), Vector3d(0.3, 0.01, 0.02)};
  const std::vector<Vector3d> hip = verify::sample_polyline(corners, 1.5, 1000.0);
  EXPECT_FALSE(checker.check_reset(hip.front()).failed());
  int crossed = 0, inside = 0, inside_engine = 0, expected_inside = 0;
  double worst = 0.0;
  for (const Vector3d& p : hip) {
    const TickVerdict v = at_hip(checker, p, true);  // the broken proxy sits on the HIP
    crossed += v.crossed ? 1 : 0;
    inside += v.inside ? 1 : 0;
    inside_engine += v.inside_engine ? 1 : 0;
    EXPECT_TRUE(v.engine_checked);
    expected_inside += std::abs(p.x()) < 0.1 ? 1 : 0;
    worst = std::max(worst, v.penetration_m);
  }
  EXPECT_EQ(crossed, 2);  // in through x = -0.1, out through x = +0.1
  EXPECT_GT(expected_inside, 100);
  EXPECT_EQ(inside, expected_inside);
  EXPECT_EQ(inside_engine, expected_inside);
  EXPECT_NEAR(worst, 0.08, 0.002);  // deepest: 80 mm from the z = 0.1 face
}

TEST(PopThroughChecker, OneTickJumpOverAnObjectIsCaught) {
  const BoxAndSheet s;
  PopThroughChecker checker(s.world, *s.oracle);
  (void)checker.check_reset(Vector3d(-0.3, 0.0, 0.0));
  const TickVerdict v = at_hip(checker, Vector3d(0.3, 0.0, 0.0), false);
  EXPECT_TRUE(v.crossed);
  EXPECT_FALSE(v.inside);  // both ends outside: only the segment test sees it
  EXPECT_TRUE(v.failed());
  EXPECT_EQ(v.leg, -1);
  ASSERT_TRUE(v.hit.has_value());
  EXPECT_EQ(v.hit->where.object, 0);
  EXPECT_NEAR(v.penetration_m, 0.4, 1e-9);  // behind the x = -0.1 face it entered through
}

TEST(PopThroughChecker, PathDippingBehindASheetIsCaught) {
  const BoxAndSheet s;
  PopThroughChecker checker(s.world, *s.oracle);
  (void)checker.check_reset(Vector3d(0.5, 0.0, 0.05));
  // Ends where it started, but its second waypoint is behind the sheet.
  const std::array<Vector3d, 3> path{Vector3d(0.5, 0.0, 0.05), Vector3d(0.51, 0.0, -0.01), Vector3d(0.52, 0.0, 0.05)};
  const TickVerdict dip = checker.check_tick(path.back(), path, path.back(), Vector3d::Zero(), false);
  EXPECT_TRUE(dip.crossed);
  EXPECT_FALSE(dip.inside);  // the sheet has no inside
  EXPECT_EQ(dip.leg, 0);     // leaving path point 0
  EXPECT_NEAR(dip.penetration_m, 0.0, 1e-12);
  // Ending behind it: 10 mm deep.
  const TickVerdict behind = at_hip(checker, Vector3d(0.52, 0.0, -0.01), false);
  EXPECT_TRUE(behind.crossed);
  EXPECT_NEAR(behind.penetration_m, 0.01, 1e-9);
}

TEST(PopThroughChecker, ProxyKeepingItsSkinPassesAndTouchingFails) {
  const BoxAndSheet s;
  PopThroughChecker checker(s.world, *s.oracle, EngineContainment::Every);
  (void)checker.check_reset(Vector3d(-0.05, 0.0, 0.2));
  // Down to 1 µm above the top face, slide along it, leave.
  for (const Vector3d& p : {Vector3d(-0.05, 0.0, 0.100001), Vector3d(0.0, 0.03, 0.100001),
                            Vector3d(0.05, 0.05, 0.100001), Vector3d(0.05, 0.05, 0.3)}) {
    const TickVerdict v = at_hip(checker, p, true);
    EXPECT_FALSE(v.failed()) << p.transpose();
  }
  const TickVerdict touch = at_hip(checker, Vector3d(0.05, 0.05, 0.1), true);
  EXPECT_TRUE(touch.crossed);
  EXPECT_TRUE(touch.inside);  // on a closed surface counts as inside
  EXPECT_NEAR(touch.penetration_m, 0.0, 1e-12);
}

TEST(PopThroughChecker, EngineContainmentFollowsItsPolicy) {
  const BoxAndSheet s;
  PopThroughChecker off(s.world, *s.oracle, EngineContainment::Off);
  PopThroughChecker contact(s.world, *s.oracle, EngineContainment::Contact);
  for (PopThroughChecker* c : {&off, &contact}) (void)c->check_reset(Vector3d(-0.3, 0.0, 0.0));
  EXPECT_FALSE(at_hip(off, Vector3d(0.0, 0.0, 0.0), true).engine_checked);
  const TickVerdict free_tick = at_hip(contact, Vector3d(-0.25, 0.0, 0.0), false);
  EXPECT_FALSE(free_tick.engine_checked);
  const TickVerdict contact_tick = at_hip(contact, Vector3d(0.0, 0.0, 0.0), true);
  EXPECT_TRUE(contact_tick.engine_checked);
  EXPECT_TRUE(contact_tick.inside_engine);
  EXPECT_TRUE(contact_tick.inside);
  // Every third allowed tick.
  PopThroughChecker sparse(s.world, *s.oracle, EngineContainment::Every, 3);
  (void)sparse.check_reset(Vector3d(-0.3, 0.0, 0.0));
  std::vector<bool> asked;
  for (int k = 1; k <= 7; ++k) {
    asked.push_back(at_hip(sparse, Vector3d(-0.3 + 0.001 * k, 0.0, 0.0), false).engine_checked);
  }
  EXPECT_EQ(asked, (std::vector<bool>{true, false, false, true, false, false, true}));
}

// The sheet (object 1) spans x in [0.4, 0.6], y in [-0.1, 0.1] at z = 0.
constexpr double kSkin_m = 1e-6;
constexpr double kStiffness_N_per_m = 1000.0;  // the checker's default tolerance stiffness

Vector3d spring(const Vector3d& proxy, const Vector3d& hip) { return kStiffness_N_per_m * (proxy - hip); }

TEST(FollowCheck, ProxyStuckWhileTheHipMovesAwayInFreeSpaceFails) {
  const BoxAndSheet s;
  PopThroughChecker checker(s.world, *s.oracle);
  const Vector3d stuck(0.5, 0.0, 0.05);
  (void)checker.check_reset(stuck);
  for (int k = 1; k <= 20; ++k) {
    const Vector3d hip = stuck + Vector3d(0.0, 0.0, 0.001 * k);  // up, away from the sheet
    const TickVerdict v = checker.check_tick(hip, {}, stuck, spring(stuck, hip), false);
    EXPECT_FALSE(v.popped_through());
    EXPECT_TRUE(v.follow_failed) << k;
    EXPECT_TRUE(v.failed());
    EXPECT_EQ(v.follow_kind, verify::FollowFailureKind::Stuck);
    EXPECT_NEAR(v.follow_gap_m, 0.001 * k, 1e-12);
    EXPECT_TRUE(v.hip_in_free_view);
    EXPECT_NEAR(v.force_N, k * 1.0, 1e-9);
  }
}

TEST(FollowCheck, SheetHeldBetweenProxyAndHipIsNotAFollowFailure) {
  const BoxAndSheet s;
  PopThroughChecker checker(s.world, *s.oracle);
  (void)checker.check_reset(Vector3d(0.5, 0.0, 0.05));
  // The HIP pushed through the sheet, up to 40 mm behind it, and sliding there.
  for (int k = 1; k <= 40; ++k) {
    const Vector3d hip(0.5 + 0.0005 * k, 0.0, -0.001 * k);
    const Vector3d proxy(hip.x(), 0.0, kSkin_m);
    const TickVerdict v = checker.check_tick(hip, {}, proxy, spring(proxy, hip), true);
    EXPECT_FALSE(v.failed()) << k;
    EXPECT_FALSE(v.hip_in_free_view);
    EXPECT_GT(v.follow_gap_m, 0.0);
  }
}

TEST(FollowCheck, HipRoundTheRimOrBackOnTheProxysSideWhileTheProxyIsHeldFails) {
  const BoxAndSheet s;
  PopThroughChecker checker(s.world, *s.oracle);
  (void)checker.check_reset(Vector3d(0.59, 0.0, 0.01));
  const Vector3d held(0.599, 0.0, kSkin_m);
  const Vector3d behind(0.599, 0.0, -0.01);
  const TickVerdict pressed = checker.check_tick(behind, {}, held, spring(held, behind), true);
  EXPECT_FALSE(pressed.failed());
  // Past the rim, level with the sheet: nothing between proxy and HIP any more.
  const Vector3d round_rim(0.62, 0.0, 0.0);
  const TickVerdict rim = checker.check_tick(round_rim, {}, held, spring(held, round_rim), true);
  EXPECT_TRUE(rim.follow_failed);
  EXPECT_EQ(rim.follow_kind, verify::FollowFailureKind::Stuck);
  EXPECT_TRUE(rim.hip_in_free_view);
  // Back above the sheet, on the proxy's side.
  const Vector3d above(0.55, 0.0, 0.01);
  const TickVerdict back = checker.check_tick(above, {}, held, spring(held, above), true);
  EXPECT_TRUE(back.follow_failed);
  EXPECT_FALSE(back.popped_through());
}

TEST(FollowCheck, ForceWithTheHipInFreeViewFailsEvenWhereTheWayWasBlocked) {
  const BoxAndSheet s;
  PopThroughChecker checker(s.world, *s.oracle);
  (void)checker.check_reset(Vector3d(0.5, 0.0, 0.05));
  // The HIP jumps behind the sheet (the straight way crosses it); the proxy goes round
  // the rim without crossing but stops 250 mm short, in free view of the HIP.
  const Vector3d hip(0.5, 0.0, -0.05);
  const Vector3d proxy(0.75, 0.0, -0.04);
  const TickVerdict v = checker.check_tick(hip, {}, proxy, spring(proxy, hip), true);
  EXPECT_FALSE(v.crossed);
  EXPECT_TRUE(v.follow_failed);
  EXPECT_EQ(v.follow_kind, verify::FollowFailureKind::FreeSpaceForce);
  EXPECT_NEAR(v.follow_gap_m, std::sqrt(0.25 * 0.25 + 0.01 * 0.01), 1e-12);
}

TEST(FollowCheck, WithinTheToleranceIsFollowingAndAForceAboveItIsNot) {
  const BoxAndSheet s;
  PopThroughChecker checker(s.world, *s.oracle);
  (void)checker.check_reset(Vector3d(-0.3, 0.0, 0.0));
  const Vector3d hip(-0.29, 0.0, 0.0);
  const Vector3d near_hip = hip + Vector3d(0.0, 0.0, 0.5 * verify::kFollowTolerance_m);
  EXPECT_FALSE(checker.check_tick(hip, {}, near_hip, spring(near_hip, hip), false).failed());
  // Same place, a 1 N force (damping, say) in free space.
  const TickVerdict pushed = checker.check_tick(hip, {}, near_hip, Vector3d(0.0, 0.0, 1.0), false);
  EXPECT_TRUE(pushed.follow_failed);
  EXPECT_EQ(pushed.follow_kind, verify::FollowFailureKind::Stuck);
  // A looser tolerance lets a 20 µm gap pass.
  PopThroughChecker loose(s.world, *s.oracle, EngineContainment::Contact, 1, verify::FollowTolerance{5e-5, 1000.0});
  (void)loose.check_reset(Vector3d(-0.3, 0.0, 0.0));
  const Vector3d off = hip + Vector3d(0.0, 2e-5, 0.0);
  EXPECT_FALSE(loose.check_tick(hip, {}, off, spring(off, hip), false).failed());
}

}  // namespace
}  // namespace mhd::stress
