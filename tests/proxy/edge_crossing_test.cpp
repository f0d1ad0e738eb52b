// The proxy crossing convex edges of a fine mesh: off the face it held, it goes straight
// to the HIP's foot on the face beyond in one swept leg, and that leg, being swept against
// everything, stops at whatever is in its way.

#include "proxy/god_object.h"

#include "proxy_test_rig.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mhd {
namespace {

using V = Eigen::Vector3d;

using test::quad;
using test::stiff;
using Rig = test::ProxyRig;

// A strip of facets 0.6 mm wide along x, curved like a 100 mm sphere (z = -x^2 / 2R):
// the facets of a 1M-triangle sphere, which a stroke at 0.5 m/s crosses about once a tick.
constexpr double kFacet_m = 0.0006;
constexpr int kHalfFacets = 60;
constexpr double kRadius_m = 0.1;

double arc_z(double x) { return -x * x / (2.0 * kRadius_m); }

TriangleMesh arc_strip() {
  TriangleMesh m;
  for (int i = -kHalfFacets; i <= kHalfFacets; ++i) {
    const double x = i * kFacet_m;
    m.vertices_m.push_back(V(x, -0.01, arc_z(x)));
    m.vertices_m.push_back(V(x, 0.01, arc_z(x)));
  }
  for (std::uint32_t i = 0; i < 2 * kHalfFacets; ++i) {
    const std::uint32_t a = 2 * i;  // (x_i, -y), then (x_i, +y), (x_i+1, -y), (x_i+1, +y)
    m.triangles.push_back({a, a + 2, a + 3});
    m.triangles.push_back({a, a + 3, a + 1});
  }
  return m;
}

// The facet under x, and the proxy's distance from its plane.
int facet_of(double x) { return static_cast<int>(std::floor(x / kFacet_m)); }
double gap_to_facet(const V& p) {
  const int k = facet_of(p.x());
  const V a(k * kFacet_m, 0, arc_z(k * kFacet_m));
  const V b((k + 1) * kFacet_m, 0, arc_z((k + 1) * kFacet_m));
  const V n = V(-(b.z() - a.z()), 0, b.x() - a.x()).normalized();
  return n.dot(p - a);
}

TEST(EdgeCrossing, AStrokeOverAFineConvexMeshSweepsAtMostThreeTimesATick) {
  Rig rig;
  rig.settings.max_force_N = 100;
  rig.add(arc_strip(), stiff(1000));
  auto under = [](double x) { return V(x, 0, arc_z(x) - 0.002); };
  const double x0 = -0.03;
  reset_proxy(rig.state, V(x0, 0, 0.01));
  rig.move(V(x0, 0, 0.01), under(x0), 20);
  int crossings = 0;
  int last_facet = facet_of(rig.state.proxy_W.x());
  for (int i = 1; i <= 120; ++i) {  // 0.5 mm a tick: 60 mm over about 100 edges
    const auto out = rig.step(under(x0 + 5e-4 * i));
    ASSERT_TRUE(out.in_contact) << "tick " << i;
    ASSERT_FALSE(out.budget_exhausted) << "tick " << i;
    // Resting on the facet under it, one skin above, as a sweep-by-sweep motion would.
    ASSERT_NEAR(gap_to_facet(out.proxy_W), rig.settings.skin_m, 1e-9) << "tick " << i;
    // Two sweeps of the world: the slide off the face it rested on, the leg onto the next
    // face; not a sweep towards the HIP and another slide after it. The face it rested
    // on, and a coplanar twin it stops beside, are found at once.
    EXPECT_LE(out.sweeps - out.sweeps_at_once, 2) << "tick " << i;
    const int facet = facet_of(out.proxy_W.x());
    crossings += facet != last_facet ? 1 : 0;
    last_facet = facet;
  }
  EXPECT_GE(crossings, 80);  // the stroke did cross the edges it is about
}

// Face A at z = 0 for x <= 0; past the ridge at x = 0, face B slopes down at 0.1 rad.
TriangleMesh ridge() {
  const double drop = 0.05 * std::tan(0.1);
  TriangleMesh a = quad(V(-0.05, -0.05, 0), V(0, -0.05, 0), V(0, 0.05, 0), V(-0.05, 0.05, 0));
  a.vertices_m.insert(a.vertices_m.end(), {V(0, -0.05, 0), V(0.05, -0.05, -drop), V(0.05, 0.05, -drop),
                                           V(0, 0.05, 0)});
  a.triangles.push_back({4, 5, 6});
  a.triangles.push_back({4, 6, 7});
  return a;
}

const V kNormalB = V(std::sin(0.1), 0, std::cos(0.1));

// Where the proxy rests over B for a HIP under it: the HIP's foot on B's plane, one skin out.
V foot_on_b(const V& hip, double skin_m) { return hip - (kNormalB.dot(hip) - skin_m) * kNormalB; }

// Resting on A just before the ridge, then one tick takes the HIP past it, under B.
ProxyOutput cross_the_ridge(Rig& rig, const V& hip_past_W) {
  const V hip_before(-0.0002, 0, -0.002);
  reset_proxy(rig.state, V(-0.0002, 0, 0.005));
  const auto pressed = rig.move(V(-0.0002, 0, 0.005), hip_before, 10);
  EXPECT_NEAR(pressed.proxy_W.z(), rig.settings.skin_m, 1e-12);
  return rig.step(hip_past_W);
}

TEST(EdgeCrossing, OffAFacePastItsEdgeTheProxyGoesToTheHipsFootOnTheFaceBeyond) {
  Rig rig;
  rig.settings.max_force_N = 100;
  rig.add(ridge(), stiff(1000));
  const V hip(0.0003, 0, -0.002);
  const auto out = cross_the_ridge(rig, hip);
  EXPECT_TRUE(out.proxy_W.isApprox(foot_on_b(hip, rig.settings.skin_m), 1e-9)) << out.proxy_W.transpose();
  EXPECT_EQ(out.plane_count, 1);
  EXPECT_EQ(out.sweeps - out.sweeps_at_once, 2);
}

// True when the segment p -> q passes through the triangle (a, b, c).
bool crosses(const V& p, const V& q, const V& a, const V& b, const V& c) {
  const V n = (b - a).cross(c - a);
  const double dp = n.dot(p - a);
  const double dq = n.dot(q - a);
  if (dp * dq > 0.0 || dp == dq) return false;
  const V x = p + dp / (dp - dq) * (q - p);
  return n.dot((b - a).cross(x - a)) >= 0 && n.dot((c - b).cross(x - b)) >= 0 && n.dot((a - c).cross(x - c)) >= 0;
}

TEST(EdgeCrossing, ALegToTheFaceBeyondStopsAtWhatIsInItsWay) {
  // A small plate hangs 25 um over B, beside the HIP: the straight leg from the ridge to
  // the HIP's foot on B passes through it, the drop straight towards the HIP does not.
  Rig rig;
  rig.settings.max_force_N = 100;
  rig.add(ridge(), stiff(1000));
  const double plate_z = -2.5e-5;
  const TriangleMesh plate =
      quad(V(0.00035, -0.0002, plate_z), V(0.0006, -0.0002, plate_z), V(0.0006, 0.0002, plate_z),
           V(0.00035, 0.0002, plate_z));
  rig.add(plate, stiff(1000));
  const V hip(0.0003, 0, -0.002);
  const auto out = cross_the_ridge(rig, hip);
  ASSERT_FALSE(out.budget_exhausted);
  // No leg of the tick's path passes through the plate or the ridge.
  const TriangleMesh surface = ridge();
  bool stopped_on_plate = false;
  for (int k = 1; k < rig.state.path_points; ++k) {
    const V& p = rig.state.path_W[static_cast<std::size_t>(k - 1)];
    const V& q = rig.state.path_W[static_cast<std::size_t>(k)];
    for (const TriangleMesh* m : {&plate, &surface}) {
      for (const auto& t : m->triangles) {
        ASSERT_FALSE(crosses(p, q, m->vertices_m[t[0]], m->vertices_m[t[1]], m->vertices_m[t[2]]))
            << "leg " << k << ": " << p.transpose() << " -> " << q.transpose();
      }
    }
    stopped_on_plate |= std::abs(q.z() - (plate_z + rig.settings.skin_m)) < 1e-12 && q.x() > 0.00035;
  }
  // The leg met the plate from above and stopped on it; from there the proxy slid off
  // the plate's edge and reached B under it, where the HIP's foot is.
  EXPECT_TRUE(stopped_on_plate);
  EXPECT_TRUE(out.proxy_W.isApprox(foot_on_b(hip, rig.settings.skin_m), 1e-9)) << out.proxy_W.transpose();
}

}  // namespace
}  // namespace mhd
