// The proxy on exact primitives: it stays on the analytic surface, the force is the
// spring along the true normal, sliding is smooth where a tessellation ripples, and it
// goes back to the hand when the hand leaves. Each leg of every tick is judged
// analytically (distance of the segment from the sphere's centre, height above the floor).

#include "geometry/primitive_mesh.h"
#include "proxy_test_rig.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace mhd::test {
namespace {

constexpr double kR = 0.05;
constexpr double kK = 1000.0;

ExactShape exact_sphere() { return ExactShape{ExactKind::Sphere, kR, 0.0, Eigen::Vector3d::Zero()}; }
ExactShape exact_floor() { return ExactShape{ExactKind::HalfSpace, 0.0, 0.0, Eigen::Vector3d::Zero()}; }

Pose at(const Eigen::Vector3d& p) {
  Pose X = Pose::Identity();
  X.translation() = p;
  return X;
}

// Least distance from c to the segment [a, b].
double segment_distance(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((c - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - c).norm();
}

struct ExactRig : ProxyRig {
  Eigen::Vector3d centre_W = Eigen::Vector3d::Zero();
  bool has_floor = false;
  double worst_sphere_gap_m = 1.0;  // least distance of any leg from the sphere's surface
  double worst_floor_gap_m = 1.0;   // least height of any leg above the floor

  ExactRig() { settings.max_force_N = 100.0; }
  void add_sphere(const Eigen::Vector3d& c, bool exact, int subdivisions = 3) {
    centre_W = c;
    add(make_sphere_mesh(kR, subdivisions), stiff(kK), at(c));
    if (exact) world.set_exact_shape(world.object_count() - 1, exact_sphere());
  }
  void add_floor(bool exact) {
    has_floor = true;
    add(make_plane_mesh(1.0, 1.0), stiff(kK));
    if (exact) world.set_exact_shape(world.object_count() - 1, exact_floor());
  }
  ProxyOutput tick(const Eigen::Vector3d& hip) {
    const ProxyOutput out = step(hip);
    for (int i = 0; i + 1 < state.path_points; ++i) {
      const auto& a = state.path_W[static_cast<std::size_t>(i)];
      const auto& b = state.path_W[static_cast<std::size_t>(i + 1)];
      worst_sphere_gap_m = std::min(worst_sphere_gap_m, segment_distance(a, b, centre_W) - kR);
      if (has_floor) worst_floor_gap_m = std::min({worst_floor_gap_m, a.z(), b.z()});
    }
    return out;
  }
  ProxyOutput line(const Eigen::Vector3d& from, const Eigen::Vector3d& to, int steps) {
    ProxyOutput out;
    for (int i = 1; i <= steps; ++i) out = tick(from + (to - from) * (double(i) / steps));
    return out;
  }
};

TEST(ExactSphereProxy, PressedInTheProxyStaysOnTheAnalyticSurfaceAndTheForceIsRadial) {
  ExactRig rig;
  rig.add_sphere(Eigen::Vector3d::Zero(), true);
  const Eigen::Vector3d u = Eigen::Vector3d(0.3, -0.2, 1.0).normalized();
  const double depth = 0.004;
  rig.line(Eigen::Vector3d(0.01, 0.0, 0.12), (kR - depth) * u, 200);
  const ProxyOutput out = rig.tick((kR - depth) * u);
  EXPECT_GE(rig.worst_sphere_gap_m, -1e-9);  // no leg entered the sphere
  EXPECT_NEAR(out.proxy_W.norm(), kR, 2e-6);
  EXPECT_LT((out.proxy_W.normalized() - u).norm(), 1e-7);
  // k x penetration (plus the skin) along the radial normal.
  EXPECT_NEAR(out.force_W.dot(u), kK * depth, kK * 2e-6);
  EXPECT_LT((out.force_W - out.force_W.dot(u) * u).norm(), 1e-4);
}

// Tangential force (across the true normal at the HIP) over a slow stroke round the
// sphere at constant depth: rms in N.
double tangential_ripple(bool exact) {
  ExactRig rig;
  rig.add_sphere(Eigen::Vector3d::Zero(), exact, 2);
  const double depth = 0.003;
  const auto on_arc = [&](double angle) {
    return Eigen::Vector3d((kR - depth) * std::sin(angle), 0.0, (kR - depth) * std::cos(angle));
  };
  rig.line(Eigen::Vector3d(0.0, 0.0, 0.1), on_arc(-0.6), 100);
  double sum2 = 0.0;
  const int n = 1200;
  for (int i = 0; i <= n; ++i) {
    const Eigen::Vector3d hip = on_arc(-0.6 + 1.2 * i / n);
    const ProxyOutput out = rig.tick(hip);
    const Eigen::Vector3d u = hip.normalized();
    sum2 += (out.force_W - out.force_W.dot(u) * u).squaredNorm();
  }
  EXPECT_GE(rig.worst_sphere_gap_m, exact ? -1e-9 : -1.0);
  return std::sqrt(sum2 / (n + 1));
}

TEST(ExactSphereProxy, SlidingRoundTheExactSphereHasNoRippleWhereTheTessellatedOneHasMuch) {
  const double exact_N = tangential_ripple(true);
  const double faceted_N = tangential_ripple(false);
  RecordProperty("exact_rms_N", std::to_string(exact_N));
  RecordProperty("faceted_rms_N", std::to_string(faceted_N));
  EXPECT_LT(exact_N, 1e-3);
  EXPECT_GT(faceted_N, 0.05);
  EXPECT_GT(faceted_N, 50.0 * exact_N);
}

TEST(ExactSphereProxy, LeavingTheSphereTheProxyGoesBackToTheHandWithExactlyZeroForce) {
  ExactRig rig;
  rig.add_sphere(Eigen::Vector3d::Zero(), true);
  rig.line(Eigen::Vector3d(0.0, 0.0, 0.1), Eigen::Vector3d(0.0, 0.0, 0.045), 100);
  ASSERT_TRUE(rig.tick(Eigen::Vector3d(0.0, 0.0, 0.045)).in_contact);
  const Eigen::Vector3d away(0.08, 0.01, 0.06);
  const ProxyOutput out = rig.line(Eigen::Vector3d(0.0, 0.0, 0.045), away, 100);
  EXPECT_EQ(out.proxy_W, away);
  EXPECT_EQ(out.force_W, Eigen::Vector3d::Zero());
  EXPECT_FALSE(out.in_contact);
  EXPECT_GE(rig.worst_sphere_gap_m, -1e-9);
}

// A sphere sunk 1 cm into a floor; the hand pushes into the crease between them, where
// the proxy is held by both, then slides out. Never a leg into either.
void crease(bool exact_floor_shape) {
  ExactRig rig;
  rig.add_floor(exact_floor_shape);
  rig.add_sphere(Eigen::Vector3d(0.0, 0.0, 0.04), true);
  const Eigen::Vector3d deep(0.025, 0.0, -0.001);  // inside both solids
  rig.line(Eigen::Vector3d(0.1, 0.0, 0.03), deep, 300);
  const ProxyOutput in = rig.tick(deep);
  EXPECT_EQ(in.plane_count, 2);
  EXPECT_GE((in.proxy_W - rig.centre_W).norm(), kR);
  EXPECT_GE(in.proxy_W.z(), 0.0);
  EXPECT_GT(in.force_W.x(), 0.0);  // pushed out of the crease, away from the sphere
  EXPECT_GT(in.force_W.z(), 0.0);  // and up off the floor
  const Eigen::Vector3d out_there(0.12, 0.03, 0.02);
  const ProxyOutput out = rig.line(deep, out_there, 300);
  EXPECT_EQ(out.proxy_W, out_there);
  EXPECT_EQ(out.force_W, Eigen::Vector3d::Zero());
  EXPECT_GE(rig.worst_sphere_gap_m, -1e-9);
  EXPECT_GE(rig.worst_floor_gap_m, 0.0);
}

TEST(ExactSphereProxy, InTheCreaseWithAnExactFloorBothHoldAndNeitherIsCrossed) { crease(true); }
TEST(ExactSphereProxy, InTheCreaseWithAMeshFloorBothHoldAndNeitherIsCrossed) { crease(false); }

TEST(ExactFloorProxy, TheInfinitePlaneHoldsFarBeyondItsTessellationAndLetsGoAbove) {
  ExactRig rig;
  rig.add_floor(true);  // tessellated as a 1 m square; exact, it has no edge
  const Eigen::Vector3d far(40.0, -25.0, 0.05);
  rig.state = ProxyState{};
  (void)rig.tick(far);
  const ProxyOutput in = rig.line(far, far + Eigen::Vector3d(0.01, 0.0, -0.053), 100);
  EXPECT_NEAR(in.proxy_W.z(), 0.0, 2e-6);
  EXPECT_GE(rig.worst_floor_gap_m, 0.0);
  EXPECT_NEAR(in.force_W.z(), kK * 0.003, kK * 2e-6);
  const ProxyOutput out = rig.line(far + Eigen::Vector3d(0.01, 0.0, -0.003), far, 50);
  EXPECT_EQ(out.proxy_W, far);
  EXPECT_EQ(out.force_W, Eigen::Vector3d::Zero());
}

}  // namespace
}  // namespace mhd::test
