// The follow check (the other half of the god-object contract) on hand-built ticks, so it
// does not depend on the proxy: a proxy that stays put while the HIP moves away in free
// space is caught, a proxy on the HIP is not, and a thin sheet held between proxy and
// HIP (the one legitimate force with the HIP in free space) is not.

#include "verification/proxy_drive.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <vector>

namespace mhd::verify {
namespace {

using Eigen::Vector3d;
using mhd::test::make_test_square;

constexpr double kSkin_m = 1e-6;
constexpr double k_N_per_m = 1000.0;

// An open 0.2 m square sheet in z = 0, x and y in [-0.1, 0.1].
SurfaceCrossingOracle sheet() { return SurfaceCrossingOracle(make_test_square(-0.1, 0.1, -0.1, 0.1, 0.0)); }

TickSample tick(const Vector3d& p_W_hip, const Vector3d& proxy_W) {
  TickSample s;
  s.p_W_hip = p_W_hip;
  s.proxy_W = proxy_W;
  s.force_W = k_N_per_m * (proxy_W - p_W_hip);
  s.in_contact = proxy_W != p_W_hip;
  s.path_points = 1;
  s.path_W[0] = proxy_W;
  return s;
}

TEST(FollowCheck, ToleranceTakesTheStiffestMaterial) {
  std::vector<HapticMaterial> materials(3);
  materials[1].stiffness_N_per_m = 2500.0;
  const FollowTolerance t = follow_tolerance(materials);
  EXPECT_EQ(t.gap_m, kFollowTolerance_m);
  EXPECT_EQ(t.stiffness_N_per_m, 2500.0);
  EXPECT_NEAR(t.force_N(), 0.025, 1e-15);
  EXPECT_EQ(follow_tolerance({}, 2e-5).stiffness_N_per_m, 1000.0);
  EXPECT_EQ(to_string(FollowFailureKind::Stuck), "stuck");
}

TEST(FollowCheck, ProxyOnTheHipNeverFails) {
  const SurfaceCrossingOracle oracle = sheet();
  TickRecord records;
  for (int k = 0; k <= 100; ++k) {
    const Vector3d p(-0.2 + 0.004 * k, 0.0, 0.05);
    records.push_back(tick(p, p));
  }
  const FollowCheck check = find_follow_failures(oracle, records, FollowTolerance{});
  EXPECT_TRUE(check.failures.empty());
  EXPECT_EQ(check.max_free_gap_m, 0.0);
}

TEST(FollowCheck, ProxyFrozenWhileTheHipMovesAwayInFreeSpaceFails) {
  const SurfaceCrossingOracle oracle = sheet();
  TickRecord records;
  const Vector3d frozen(0.0, 0.0, 0.02);
  records.push_back(tick(frozen, frozen));
  // The HIP leaves upwards and sideways, 1 mm a tick; the proxy stays.
  for (int k = 1; k <= 30; ++k) records.push_back(tick(frozen + 0.001 * k * Vector3d(1, 0, 1).normalized(), frozen));
  const FollowCheck check = find_follow_failures(oracle, records, FollowTolerance{});
  ASSERT_EQ(check.failures.size(), 30U);
  for (const FollowFailure& f : check.failures) {
    EXPECT_EQ(f.verdict.kind, FollowFailureKind::Stuck);
    EXPECT_EQ(f.previous_proxy_W, frozen);
  }
  EXPECT_EQ(check.failures.front().tick, 1U);
  EXPECT_NEAR(check.max_free_gap_m, 0.030, 1e-12);
  EXPECT_NEAR(check.force_at_max_free_gap_N, 30.0, 1e-9);
}

TEST(FollowCheck, SheetHeldBetweenProxyAndHipIsNotAFailure) {
  const SurfaceCrossingOracle oracle = sheet();
  TickRecord records;
  records.push_back(tick(Vector3d(0.0, 0.0, 0.01), Vector3d(0.0, 0.0, 0.01)));
  // Pushed 40 mm through the sheet and slid along it: the proxy stays on the near side.
  for (int k = 1; k <= 40; ++k) {
    const Vector3d hip(0.001 * k, 0.0, -0.001 * k);
    records.push_back(tick(hip, Vector3d(hip.x(), 0.0, kSkin_m)));
  }
  const FollowCheck held = find_follow_failures(oracle, records, FollowTolerance{});
  EXPECT_TRUE(held.failures.empty());
  EXPECT_EQ(held.max_free_gap_m, 0.0);  // the sheet is always in between

  // Then the HIP goes round the rim (x = 0.1) while the proxy stays: now it fails.
  const Vector3d proxy = records.back().proxy_W;
  records.push_back(tick(Vector3d(0.12, 0.0, 0.0), proxy));
  records.push_back(tick(Vector3d(0.12, 0.0, 0.01), proxy));
  const FollowCheck round = find_follow_failures(oracle, records, FollowTolerance{});
  ASSERT_EQ(round.failures.size(), 2U);
  EXPECT_EQ(round.failures[0].tick, 41U);
  EXPECT_GT(round.max_free_gap_m, 0.07);
}

TEST(FollowCheck, ForceNearTheHipIsJudgedByTheSpringForceOfTheTolerance) {
  const SurfaceCrossingOracle oracle = sheet();
  const Vector3d hip(0.0, 0.0, 0.05);
  const Vector3d near = hip + Vector3d(0.0, 0.0, 0.5 * kFollowTolerance_m);
  const FollowTolerance tolerance;
  EXPECT_FALSE(check_follow(oracle, hip, hip, near, k_N_per_m * (near - hip), tolerance).failed());
  const FollowVerdict damped = check_follow(oracle, hip, hip, near, Vector3d(0.0, 0.0, 0.5), tolerance);
  EXPECT_EQ(damped.kind, FollowFailureKind::Stuck);
  EXPECT_TRUE(damped.hip_in_free_view);
}

TEST(FollowCheck, ForceWithTheHipInFreeViewFailsWhereTheStraightWayWasBlocked) {
  const SurfaceCrossingOracle oracle = sheet();
  // The HIP jumped behind the sheet; the proxy went round the rim but stopped short.
  const Vector3d previous(0.0, 0.0, 0.05);
  const Vector3d hip(0.0, 0.0, -0.05);
  const Vector3d proxy(0.25, 0.0, -0.04);
  const FollowVerdict v = check_follow(oracle, previous, hip, proxy, k_N_per_m * (proxy - hip), FollowTolerance{});
  EXPECT_EQ(v.kind, FollowFailureKind::FreeSpaceForce);
  EXPECT_TRUE(v.hip_in_free_view);
}

TEST(FollowCheck, AWayThatBrushesARimCloserThanTheSkinIsNotAFailureAndIsCounted) {
  const SurfaceCrossingOracle oracle = sheet();
  // From 1 cm above the sheet to under it, past the rim at x = 0.1 by 1 nm: exactly free,
  // but no proxy that keeps a 1 µm skin can take that way straight.
  const Vector3d previous(0.0, 0.0, 0.01);
  const Vector3d hip(0.2, 0.0, -0.01 + 2e-9);
  ASSERT_FALSE(oracle.segment_touches_surface(previous, hip));
  const Vector3d stopped(0.09, 0.0, 1e-6);  // held on the sheet, the HIP behind it
  const FollowVerdict brushed = check_follow(oracle, previous, hip, stopped, k_N_per_m * (stopped - hip), FollowTolerance{});
  EXPECT_FALSE(brushed.failed());
  EXPECT_TRUE(brushed.brushed);
  // The dual: the same way 10 µm above the rim is clear of the skin, and stopping is a failure.
  const Vector3d clear_hip(0.2, 0.0, -0.01 + 2e-5);
  const FollowVerdict stuck = check_follow(oracle, previous, clear_hip, stopped, k_N_per_m * (stopped - clear_hip),
                                           FollowTolerance{});
  EXPECT_EQ(stuck.kind, FollowFailureKind::Stuck);
  EXPECT_FALSE(stuck.brushed);
}

TEST(FollowCheck, TheFaceTheProxyRestsOnIsNotABrush) {
  const SurfaceCrossingOracle oracle = sheet();
  // Resting on the sheet (one skin above it), the HIP lifts off and slides along it just
  // above the skin: a proxy left behind is stuck, whatever the face under it.
  const Vector3d resting(0.0, 0.0, kSkin_m);
  for (const Vector3d& hip : {Vector3d(0.001, 0.0, 0.005), Vector3d(0.05, 0.0, 0.5 * kSkin_m)}) {
    const FollowVerdict v = check_follow(oracle, resting, hip, resting, k_N_per_m * (resting - hip), FollowTolerance{});
    EXPECT_EQ(v.kind, FollowFailureKind::Stuck) << hip.transpose();
    EXPECT_FALSE(v.brushed);
  }
}

}  // namespace
}  // namespace mhd::verify
