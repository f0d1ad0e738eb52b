// Force shading keeps the god-object's contract (docs/proxy.md): the shaded goal is only
// a goal, filtered by the real surface, so the proxy never crosses a surface and ends at
// the HIP whenever it can see it. Judged by the exact oracle (tools/verification, CGAL)
// on random strokes over a coarse sphere (with and without friction), a cube and an open
// hemisphere touched from both sides, its rim included.

#include "proxy/god_object.h"

#include "proxy_test_rig.h"

#include "geometry/primitive_mesh.h"
#include "geometry/shading_normals.h"
#include "verification/proxy_drive.h"
#include "verification/surface_crossing_oracle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

namespace mhd {
namespace {

using V = Eigen::Vector3d;
constexpr double kRate_Hz = 1.0 / test::kProxyTestDt_s;

// Random strokes round a shape of radius ~50 mm at the origin: from 90 mm out, in along a
// random direction to `depth` behind the surface, a slide to a nearby direction, and
// out again. With `from_inside`, every other stroke comes from the centre instead (an
// open shape's inner side), reached from below round the rim.
std::vector<V> strokes(std::uint64_t seed, int count, double surface_m, bool from_inside) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g;
  std::vector<V> path{V(0, 0, 0.09)};
  auto go = [&](const V& to, double speed_mps) {
    const V from = path.back();
    const int n = std::max(1, static_cast<int>(std::ceil((to - from).norm() / (speed_mps / kRate_Hz))));
    for (int i = 1; i <= n; ++i) path.push_back(from + (to - from) * (double(i) / n));
  };
  for (int k = 0; k < count; ++k) {
    V d = V(g(rng), g(rng), g(rng)).normalized();
    const bool inside = from_inside && k % 2 == 1;
    if (inside) d.z() = std::abs(d.z()) + 0.2, d.normalize();  // the hemisphere's cap
    V d2 = (d + 0.5 * V(g(rng), g(rng), g(rng))).normalized();
    if (inside) d2.z() = std::abs(d2.z()) + 0.2, d2.normalize();
    const double depth = 0.001 + 0.014 * u(rng);
    const double speed = 0.05 + 0.45 * u(rng);
    if (inside) {
      go(V(0.09, 0, 0.09), 1.0);  // round the rim, underneath, up into the bowl
      go(V(0.09, 0, -0.03), 1.0);
      go(V(0, 0, -0.03), 1.0);
      go(V::Zero(), 1.0);
      go((surface_m + depth) * d, speed);
      go((surface_m + depth) * d2, speed);
      go(V::Zero(), speed);
      go(V(0, 0, -0.03), 1.0);
      go(V(0.09, 0, -0.03), 1.0);
      go(V(0.09, 0, 0.09), 1.0);
    } else {
      go(0.09 * d, 1.0);
      go((surface_m - depth) * d, speed);
      go((surface_m - depth) * d2, speed);
      go(0.09 * d2, speed);
    }
  }
  return path;
}

struct Verdict {
  std::size_t crossings = 0;
  std::size_t follow_failures = 0;
  std::size_t contact_ticks = 0;
  std::size_t ticks = 0;
};

Verdict judge(TriangleMesh mesh, const HapticMaterial& material, const std::vector<V>& path) {
  test::ProxyRig rig;
  rig.add(std::move(mesh), material);
  rig.world.set_shading_normals(0, std::make_shared<const ShadingNormals>(compute_shading_normals(
                                       rig.world.shape(0).mesh(), material.force_shading_crease_rad)));
  const verify::SurfaceCrossingOracle oracle(rig.world);
  const verify::TickRecord rec = verify::drive_proxy(rig.world, rig.materials, rig.settings, path, kRate_Hz);
  Verdict v;
  v.ticks = rec.size();
  v.crossings = verify::count_crossings(oracle, rec);
  v.follow_failures =
      verify::find_follow_failures(oracle, rec, verify::follow_tolerance(rig.materials)).failures.size();
  for (const auto& s : rec) v.contact_ticks += s.in_contact;
  return v;
}

HapticMaterial shaded(double static_mu = 0, double dynamic_mu = 0) {
  HapticMaterial m;
  m.stiffness_N_per_m = 1000;
  m.force_shading = true;
  m.static_friction = static_mu;
  m.dynamic_friction = dynamic_mu;
  return m;
}

void expect_contract(const Verdict& v, const char* what) {
  EXPECT_EQ(v.crossings, 0u) << what;
  EXPECT_EQ(v.follow_failures, 0u) << what;
  EXPECT_GT(v.contact_ticks, v.ticks / 10) << what;  // the strokes really push in
}

TEST(ForceShadingContract, OnACoarseSphereTheShadedProxyNeverCrossesAndFollows) {
  const std::vector<V> path = strokes(17, 150, 0.05, false);
  expect_contract(judge(make_sphere_mesh(0.05, 1), shaded(), path), "frictionless");
  expect_contract(judge(make_sphere_mesh(0.05, 1), shaded(0.4, 0.3), path), "with friction");
}

TEST(ForceShadingContract, OnACubeTheShadedProxyNeverCrossesAndFollows) {
  HapticMaterial rounded = shaded();
  rounded.force_shading_crease_rad = 100 * std::numbers::pi / 180;  // edges shaded too
  const std::vector<V> path = strokes(18, 150, 0.04, false);
  expect_contract(judge(make_box_mesh(V(0.08, 0.08, 0.08)), shaded(), path), "sharp edges");
  expect_contract(judge(make_box_mesh(V(0.08, 0.08, 0.08)), rounded, path), "rounded edges");
}

TEST(ForceShadingContract, OnAnOpenHemisphereFromBothSidesTheShadedProxyNeverCrossesAndFollows) {
  // The upper half of a coarse icosphere: an open, two-sided shell with a rim.
  const TriangleMesh sphere = make_sphere_mesh(0.05, 1);
  TriangleMesh cap;
  cap.vertices_m = sphere.vertices_m;
  for (const auto& t : sphere.triangles) {
    const V centroid = (sphere.vertices_m[t[0]] + sphere.vertices_m[t[1]] + sphere.vertices_m[t[2]]) / 3;
    if (centroid.z() > 0) cap.triangles.push_back(t);
  }
  expect_contract(judge(cap, shaded(), strokes(19, 150, 0.05, true)), "open hemisphere");
}

}  // namespace
}  // namespace mhd
