// Two-pass force shading (Ruspini et al. 1997) through step_proxy(): a coarse sphere
// stroked at constant depth feels round, and a cube keeps its flat faces and sharp edges.

#include "proxy/god_object.h"

#include "proxy_test_rig.h"

#include "geometry/primitive_mesh.h"
#include "geometry/shading_normals.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <vector>

namespace mhd {
namespace {

using V = Eigen::Vector3d;
using test::stiff;
constexpr double kDeg = std::numbers::pi / 180.0;

struct ShadingRig : test::ProxyRig {
  ShadingRig() { settings.max_force_N = 100; }  // compared with k * depth: never clamped
  /// Adds `mesh` with force shading on or off; its corner normals as the scene compiler
  /// gives them.
  void add_shaded(TriangleMesh mesh, bool shading, double crease_rad = 60 * kDeg) {
    HapticMaterial mat = stiff(1000);
    mat.force_shading = shading;
    mat.force_shading_crease_rad = crease_rad;
    add(std::move(mesh), mat);
    const int id = world.object_count() - 1;
    world.set_shading_normals(id, std::make_shared<const ShadingNormals>(
                                      compute_shading_normals(world.shape(id).mesh(), crease_rad)));
  }
};

// Radius of the largest sphere inside a polyhedron centred on the origin.
double insphere_radius_m(const TriangleMesh& m) {
  double r = std::numeric_limits<double>::infinity();
  for (const auto& t : m.triangles) {
    const V& a = m.vertices_m[t[0]];
    const V n = (m.vertices_m[t[1]] - a).cross(m.vertices_m[t[2]] - a).normalized();
    r = std::min(r, std::abs(n.dot(a)));
  }
  return r;
}

struct Ripple {
  double angle_sd_rad = 0;      // spread of the force's angle to the true sphere normal
  double angle_max_rad = 0;
  double tangential_rms_N = 0;  // force across the true sphere normal (zero on a real sphere)
  double normal_mean_N = 0;
  int ticks = 0;
};

// Strokes an icosphere (radius 50 mm, 80 triangles: facets ~20 degrees apart) along a
// tilted great circle, the HIP 2 mm inside the largest inscribed sphere, at 0.1 m/s,
// and measures how far the force strays from the true sphere's normal at the HIP.
Ripple stroke_coarse_sphere(bool shading) {
  ShadingRig rig;
  const TriangleMesh sphere = make_sphere_mesh(0.05, 1);
  const double r_m = insphere_radius_m(sphere) - 0.002;
  rig.add_shaded(sphere, shading);
  const V u(1, 0, 0);
  const V w = V(0, std::cos(0.3), std::sin(0.3));
  auto on_circle = [&](double phi) { return r_m * (std::cos(phi) * u + std::sin(phi) * w); };
  reset_proxy(rig.state, 0.07 * u);
  rig.move(0.07 * u, on_circle(0), 60);
  const double step_rad = 1e-4 / r_m;
  std::vector<double> angles;
  double tangential_sq = 0, normal_sum = 0;
  for (double phi = step_rad; phi < std::numbers::pi; phi += step_rad) {
    const V hip = on_circle(phi);
    const ProxyOutput out = rig.step(hip);
    EXPECT_TRUE(out.in_contact) << "phi " << phi;
    const V radial = hip.normalized();
    const double normal = out.force_W.dot(radial);
    const double tangential = (out.force_W - normal * radial).norm();
    angles.push_back(std::atan2(tangential, normal));
    tangential_sq += tangential * tangential;
    normal_sum += normal;
  }
  Ripple r;
  r.ticks = static_cast<int>(angles.size());
  double mean = 0;
  for (double a : angles) mean += a / r.ticks;
  for (double a : angles) {
    r.angle_sd_rad += (a - mean) * (a - mean) / r.ticks;
    r.angle_max_rad = std::max(r.angle_max_rad, a);
  }
  r.angle_sd_rad = std::sqrt(r.angle_sd_rad);
  r.tangential_rms_N = std::sqrt(tangential_sq / r.ticks);
  r.normal_mean_N = normal_sum / r.ticks;
  return r;
}

TEST(ForceShading, ACoarseSphereStrokedAtConstantDepthFeelsRound) {
  const Ripple faceted = stroke_coarse_sphere(false);
  const Ripple shaded = stroke_coarse_sphere(true);
  std::printf("coarse sphere, 80 triangles: angle to the sphere normal sd %.2f deg (max %.2f), tangential rms "
              "%.3f N unshaded; sd %.2f deg (max %.2f), rms %.3f N shaded; mean normal %.2f / %.2f N\n",
              faceted.angle_sd_rad / kDeg, faceted.angle_max_rad / kDeg, faceted.tangential_rms_N,
              shaded.angle_sd_rad / kDeg, shaded.angle_max_rad / kDeg, shaded.tangential_rms_N,
              faceted.normal_mean_N, shaded.normal_mean_N);
  ASSERT_GT(faceted.ticks, 1000);
  // The facets really are felt without shading: the force swings several degrees.
  EXPECT_GT(faceted.angle_max_rad, 5 * kDeg);
  EXPECT_LT(shaded.angle_sd_rad, faceted.angle_sd_rad / 4);
  EXPECT_LT(shaded.angle_max_rad, faceted.angle_max_rad / 4);
  EXPECT_LT(shaded.tangential_rms_N, faceted.tangential_rms_N / 4);
  // Shading turns the force; it does not soften the surface.
  EXPECT_NEAR(shaded.normal_mean_N, faceted.normal_mean_N, 0.1 * faceted.normal_mean_N);
}

// A stroke 3 mm deep over a cube's top face and off its edge, then back in from the side
// and down it.
std::vector<ProxyOutput> stroke_cube(bool shading, double crease_rad) {
  ShadingRig rig;
  rig.add_shaded(make_box_mesh(V(0.1, 0.1, 0.1)), shading, crease_rad);
  std::vector<ProxyOutput> outs;
  auto go = [&](const V& from, const V& to, int ticks) {
    for (int i = 1; i <= ticks; ++i) outs.push_back(rig.step(from + (to - from) * (double(i) / ticks)));
  };
  reset_proxy(rig.state, V(-0.03, 0.01, 0.07));
  go(V(-0.03, 0.01, 0.07), V(-0.03, 0.01, 0.047), 30);
  go(V(-0.03, 0.01, 0.047), V(0.053, 0.01, 0.047), 830);
  go(V(0.053, 0.01, 0.047), V(0.053, 0.01, 0.04), 70);
  go(V(0.053, 0.01, 0.04), V(0.047, 0.01, 0.04), 60);
  go(V(0.047, 0.01, 0.04), V(0.047, 0.01, 0.0), 400);
  return outs;
}

TEST(ForceShading, ACubeKeepsFlatFacesAndEdgesSharperThanTheCreaseAngle) {
  const std::vector<ProxyOutput> plain = stroke_cube(false, 60 * kDeg);
  const std::vector<ProxyOutput> shaded = stroke_cube(true, 60 * kDeg);
  ASSERT_EQ(plain.size(), shaded.size());
  int on_top = 0, on_side = 0;
  for (std::size_t i = 0; i < plain.size(); ++i) {
    // Faces are flat and the 90-degree edges are creases: shading has nothing to change.
    EXPECT_EQ(shaded[i].force_W, plain[i].force_W) << "tick " << i;
    EXPECT_EQ(shaded[i].proxy_W, plain[i].proxy_W) << "tick " << i;
    if (!plain[i].in_contact) continue;
    const V dir = plain[i].force_W.normalized();
    on_top += dir.isApprox(V(0, 0, 1), 1e-12);
    on_side += dir.isApprox(V(1, 0, 0), 1e-12);
  }
  EXPECT_GT(on_top, 500);   // the stroke felt the top face straight up...
  EXPECT_GT(on_side, 300);  // ...and the side straight out: the edge stayed an edge
  // With a crease angle above 90 degrees the same cube is rounded: the test can tell.
  const std::vector<ProxyOutput> rounded = stroke_cube(true, 100 * kDeg);
  double worst_N = 0;
  for (std::size_t i = 0; i < plain.size(); ++i) worst_N = std::max(worst_N, (rounded[i].force_W - plain[i].force_W).norm());
  EXPECT_GT(worst_N, 0.5);
}

TEST(ForceShading, AFlatFaceWithShadingOnNeedsNoSecondPass) {
  // The shaded goal of a flat face is the contact itself: no extra sweeps per tick.
  auto sweeps = [](bool shading) {
    ShadingRig rig;
    rig.add_shaded(make_box_mesh(V(0.1, 0.1, 0.1)), shading);
    reset_proxy(rig.state, V(0, 0, 0.07));
    rig.move(V(0, 0, 0.07), V(0, 0, 0.046), 30);
    int total = 0;
    for (int i = 1; i <= 100; ++i) total += rig.step(V(1e-4 * i, 0, 0.046)).sweeps;
    return total;
  };
  EXPECT_EQ(sweeps(true), sweeps(false));
}

}  // namespace
}  // namespace mhd
