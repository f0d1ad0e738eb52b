// step_proxy must not allocate: it runs in the 1 kHz haptic thread. Counted with
// test::AllocationCounter (its own binary: the counter replaces operator new).

#include "proxy/god_object.h"
#include "proxy/moving_world.h"

#include "geometry/primitive_mesh.h"

#include <algorithm>
#include "geometry/shading_normals.h"

#include "support/allocation_counter.h"

#include <LinearMath/btAlignedAllocator.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <numbers>

#include <utility>

namespace mhd {
namespace {

/// Press in, circle around a 0.1 m sphere 8 mm deep (friction, shading, edges), come out:
/// the allocations step_proxy made, and how many ticks touched.
std::pair<long, int> circle_sphere(const HapticMaterial& mat) {
  TriangleMesh sphere = make_sphere_mesh(0.1, 5);
  compute_vertex_normals(sphere);
  CollisionWorld world;
  world.add_object(std::make_shared<MeshBvh>(std::make_shared<TriangleMesh>(std::move(sphere))), Pose::Identity());
  const std::vector<HapticMaterial> materials{mat};
  const ProxySettings settings;
  ProxyState state;
  reset_proxy(state, Eigen::Vector3d(0, 0, 0.15));
  test::AllocationCounter allocations;
  int contact_ticks = 0;
  for (int i = 0; i < 3000; ++i) {
    const double a = 0.002 * i;
    const double r = i < 2900 ? 0.092 : 0.15;
    const Eigen::Vector3d hip(r * std::sin(a) * std::cos(3 * a), r * std::sin(a) * std::sin(3 * a), r * std::cos(a));
    const ProxyOutput out = step_proxy(world, materials, settings, state, hip, 1e-3);
    if (out.in_contact) ++contact_ticks;
  }
  allocations.stop();
  return {static_cast<long>(allocations.count()), contact_ticks};
}

TEST(GodObjectAllocation, StepProxyWithTexturesAllocatesNothing) {
  HapticMaterial mat;
  mat.static_friction = 0.4;
  mat.dynamic_friction = 0.3;
  for (const TextureKind kind : {TextureKind::Grating, TextureKind::Noise, TextureKind::HeightMap}) {
    HapticTextureSpec spec;
    spec.kind = kind;
    spec.depth_m = 3e-4;
    spec.friction_contrast = 0.5;
    GreyImage image;
    image.width = 3;
    image.height = 2;
    image.grey = {0.0, 0.5, 1.0, 1.0, 0.2, 0.0};
    mat.texture = std::make_shared<HapticTexture>(kind == TextureKind::HeightMap ? HapticTexture::height_map(spec, image)
                                                                                 : HapticTexture::procedural(spec));
    const auto [allocations, contact_ticks] = circle_sphere(mat);
    EXPECT_GT(contact_ticks, 2000);
    EXPECT_EQ(allocations, 0);
  }
}

TEST(GodObjectAllocation, StepProxyAllocatesNothing) {
  TriangleMesh sphere = make_sphere_mesh(0.1, 5);
  compute_vertex_normals(sphere);
  CollisionWorld world;
  world.add_object(std::make_shared<MeshBvh>(std::make_shared<TriangleMesh>(std::move(sphere))), Pose::Identity());
  // Force shading's corner normals, as the scene compiler sets them.
  world.set_shading_normals(0, std::make_shared<const ShadingNormals>(compute_shading_normals(world.shape(0).mesh(), 1.0)));
  HapticMaterial mat;
  mat.static_friction = 0.4;
  mat.dynamic_friction = 0.3;
  mat.damping_Ns_per_m = 1.0;
  mat.force_shading = true;
  const std::vector<HapticMaterial> materials{mat};
  const ProxySettings settings;
  ProxyState state;
  reset_proxy(state, Eigen::Vector3d(0, 0, 0.15));

  test::AllocationCounter allocations;
  int contact_ticks = 0;
  // Press in, circle around the sphere 8 mm deep (friction, shading, edges), come out.
  for (int i = 0; i < 3000; ++i) {
    const double a = 0.002 * i;
    const double r = i < 2900 ? 0.092 : 0.15;
    const Eigen::Vector3d hip(r * std::sin(a) * std::cos(3 * a), r * std::sin(a) * std::sin(3 * a), r * std::cos(a));
    const ProxyOutput out = step_proxy(world, materials, settings, state, hip, 1e-3);
    if (out.in_contact) ++contact_ticks;
  }
  allocations.stop();
  EXPECT_GT(contact_ticks, 2000);
  EXPECT_EQ(allocations.count(), 0);
}

TEST(GodObjectAllocation, MovingObjectsAndTheirCarryAllocateNothing) {
  // A sphere spinning and swinging through the hand: advance() and step_proxy() together.
  TriangleMesh sphere = make_sphere_mesh(0.1, 4);
  compute_vertex_normals(sphere);
  CollisionWorld world;
  world.add_object(std::make_shared<MeshBvh>(std::make_shared<TriangleMesh>(std::move(sphere))), Pose::Identity());
  Pose right = Pose::Identity();
  right.translation() = Eigen::Vector3d(0.05, 0, 0);
  std::vector<std::optional<ObjectMotion>> motions;
  motions.push_back(ObjectMotion::keyframes({{0.0, Pose::Identity()}, {0.5, right}}, MotionRepeat::PingPong));
  MovingWorld moving(world, std::move(motions));
  HapticMaterial mat;
  mat.damping_Ns_per_m = 1.0;
  const std::vector<HapticMaterial> materials{mat};
  const ProxySettings settings;
  ProxyState state;
  moving.place(0.0);
  reset_proxy(state, Eigen::Vector3d(0.13, 0, 0));

  test::AllocationCounter allocations;
  int contact_ticks = 0;
  for (int i = 1; i <= 3000; ++i) {
    (void)moving.advance(1e-3 * i, state, settings.skin_m);
    const ProxyOutput out = step_proxy(moving.world(), materials, settings, state, Eigen::Vector3d(0.13, 0, 0), 1e-3,
                                       moving.twists());
    if (out.in_contact) ++contact_ticks;
  }
  allocations.stop();
  EXPECT_GT(contact_ticks, 500);
  EXPECT_EQ(allocations.count(), 0);
}

// Bullet allocates through btAlignedAlloc (malloc), not operator new: counted here.
std::atomic<long> g_bullet_allocations{0};
std::atomic<bool> g_bullet_counting{false};
void* counting_bullet_alloc(std::size_t size) {
  if (g_bullet_counting.load()) ++g_bullet_allocations;
  return std::malloc(size);
}
void counting_bullet_free(void* p) { std::free(p); }

TEST(GodObjectAllocation, PushingABodyAllocatesNothingOnceItsContactsWereMet) {
  btAlignedAllocSetCustom(counting_bullet_alloc, counting_bullet_free);
  // A y-up floor and a 0.1 m, 0.5 kg box on it; the hand pushes it along +x, backs off,
  // and pushes again.
  CollisionWorld world;
  Pose X_WF = Pose::Identity();
  X_WF.linear() = Eigen::AngleAxisd(-std::numbers::pi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  world.add_object(std::make_shared<MeshBvh>(std::make_shared<TriangleMesh>(make_plane_mesh(4.0, 4.0))), X_WF);
  Pose X_WB = Pose::Identity();
  X_WB.translation() = Eigen::Vector3d(0, 0.05, 0);
  world.add_object(std::make_shared<MeshBvh>(std::make_shared<TriangleMesh>(make_box_mesh(Eigen::Vector3d::Constant(0.1)))),
                   X_WB);
  const std::vector<std::optional<ObjectDynamics>> dynamics{std::nullopt, ObjectDynamics{0.5, 0.4}};
  MovingWorld moving(world, {std::nullopt, std::nullopt}, dynamics);
  const std::vector<HapticMaterial> materials{HapticMaterial{}, HapticMaterial{}};
  const ProxySettings settings;
  ProxyState state;
  const auto hip = [](int i) {  // 0.1 m/s forwards for 1 s, back for 0.5 s, forwards again
    const double t = 1e-3 * i;
    const double x = -0.07 + 0.1 * std::min(t, 1.0) - 0.1 * std::clamp(t - 1.0, 0.0, 0.5) +
                     0.1 * std::clamp(t - 1.5, 0.0, 1.0);
    return Eigen::Vector3d(x, 0.05, 0);
  };
  reset_proxy(state, hip(0));
  int contact_ticks = 0;
  const auto tick = [&](int i) {
    (void)moving.advance(1e-3 * i, state, settings.skin_m);
    const ProxyOutput out = step_proxy(moving.world(), materials, settings, state, hip(i), 1e-3, moving.twists());
    moving.apply_reaction(state, out.force_W);
    if (out.in_contact) ++contact_ticks;
  };
  for (int i = 1; i <= 500; ++i) tick(i);  // the box's first push meets its contacts
  const double x_warm = moving.world().pose(1).translation().x();

  g_bullet_allocations = 0;
  g_bullet_counting = true;
  test::AllocationCounter allocations;
  for (int i = 501; i <= 2500; ++i) tick(i);
  allocations.stop();
  g_bullet_counting = false;
  EXPECT_GT(contact_ticks, 1000);
  EXPECT_GT(moving.world().pose(1).translation().x(), x_warm + 0.05) << "the box was pushed";
  EXPECT_EQ(allocations.count(), 0);
  EXPECT_EQ(g_bullet_allocations.load(), 0);
  g_bullet_counting = true;  // and the counter does see Bullet's allocations
  { const MovingWorld probe(world, {std::nullopt, std::nullopt}, dynamics); }
  g_bullet_counting = false;
  EXPECT_GT(g_bullet_allocations.load(), 0);
}

}  // namespace
}  // namespace mhd
