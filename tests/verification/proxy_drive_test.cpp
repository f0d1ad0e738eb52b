#include "verification/proxy_drive.h"
#include "verification/stroke_set.h"
#include "mesh_io/mesh_loader.h"
#include "mesh_io/test_mesh_files.h"
#include "test_meshes.h"

using namespace mhd::test;  // hand-made meshes

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace mhd::verify {
namespace {

using Eigen::Vector3d;

struct BoxWorld {
  CollisionWorld world;
  std::vector<HapticMaterial> materials;
  ProxySettings settings;
  BoxWorld() {
    auto mesh = std::make_shared<const TriangleMesh>(make_test_box({-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1}));
    world.add_object(std::make_shared<const MeshBvh>(mesh), pose_from_xyz_rpy(Vector3d(0.0, 0.0, 0.05),
                                                                                Vector3d(0.1, 0.2, 0.3)));
    materials.resize(1);
  }
};

TEST(DriveProxy, RecordsEveryTickAndAContinuousPath) {
  const BoxWorld box;
  const SurfaceCrossingOracle oracle(box.world);
  const StrokeSet set = make_anchor_strokes(oracle, 77, 10);
  for (const Stroke& stroke : set.strokes) {
    const TickRecord records = drive_proxy(box.world, box.materials, box.settings, stroke.p_W_hip, 1000.0);
    ASSERT_EQ(records.size(), stroke.p_W_hip.size());
    std::size_t contact = 0;
    for (std::size_t k = 0; k < records.size(); ++k) {
      const TickSample& s = records[k];
      EXPECT_EQ(s.p_W_hip, stroke.p_W_hip[k]);
      ASSERT_GE(s.path_points, 1);
      ASSERT_LE(s.path_points, kMaxProxyPath);
      // The path ends where the proxy ends.
      EXPECT_EQ(s.path_W[static_cast<std::size_t>(s.path_points - 1)], s.proxy_W);
      EXPECT_LE(s.force_W.norm(), box.settings.max_force_N * (1.0 + 1e-12));
      if (s.in_contact) ++contact;
    }
    // 5 mm approach + 50 mm slide at 0.5 mm per tick, on a box face or past its edge
    // (contact starts once the HIP is behind the surface, not within the proxy's skin).
    EXPECT_GE(contact, 10U);
    EXPECT_EQ(count_crossings(oracle, records), 0U);
    EXPECT_EQ(count_ticks_inside(oracle, records), 0U);
  }
}

TEST(DriveProxy, AFrontOnlySheetHoldsTheHandInFrontAndLetsItOutFromBehind) {
  // A 20 cm sheet in z = 0 facing +z, touchable from the front. The hand comes down
  // through it from above (held on it, pushed back up, no crossing), goes round its edge
  // to below, then rises through it from behind: the proxy follows the hand all the way,
  // with no force, and that move is no crossing either. Both sides: the same rise is held.
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices_m = {{-0.1, -0.1, 0}, {0.1, -0.1, 0}, {0.1, 0.1, 0}, {-0.1, 0.1, 0}};
  mesh->triangles = {{0, 1, 2}, {0, 2, 3}};
  std::vector<Vector3d> down, rise;
  for (int k = 0; k <= 100; ++k) down.emplace_back(0.0, 0.0, 0.02 - 0.0004 * k);  // to 2 cm below
  // Round the edge at x = 0.15, then in under the middle, then up to 2 cm above.
  const std::vector<Vector3d> corners = {{0.0, 0.0, 0.02}, {0.15, 0.0, 0.02}, {0.15, 0.0, -0.02},
                                         {0.0, 0.0, -0.02}, {0.0, 0.0, 0.02}};
  for (std::size_t c = 0; c + 1 < corners.size(); ++c) {
    for (int k = 0; k < 100; ++k) rise.push_back(corners[c] + (corners[c + 1] - corners[c]) * (k / 100.0));
  }
  rise.push_back(corners.back());
  for (const TouchableFaces faces : {TouchableFaces::Front, TouchableFaces::Both}) {
    SCOPED_TRACE(std::string(touchable_faces_name(faces)));
    CollisionWorld world;
    const int id = world.add_object(std::make_shared<const MeshBvh>(mesh), Pose::Identity());
    world.set_touchable(id, faces);
    const std::vector<HapticMaterial> materials(1);
    const ProxySettings settings;
    const SurfaceCrossingOracle oracle(world);

    const TickRecord pressed = drive_proxy(world, materials, settings, down, 1000.0);
    EXPECT_GE(pressed.back().proxy_W.z(), 0.0);
    EXPECT_GT(pressed.back().force_W.z(), 0.0);
    EXPECT_EQ(count_crossings(oracle, pressed), 0U);

    const TickRecord risen = drive_proxy(world, materials, settings, rise, 1000.0);
    EXPECT_EQ(count_crossings(oracle, risen), 0U);
    // Under the middle, on the way up: in front of the sheet's back there is nothing.
    const TickSample& under = risen[330];
    ASSERT_LT(under.p_W_hip.z(), 0.0);
    // Held: the hand 2 cm above, its proxy under the sheet (both sides touchable only).
    EXPECT_EQ(count_held_ticks(oracle, risen) > 0, faces == TouchableFaces::Both);
    EXPECT_EQ(count_held_ticks(oracle, pressed), 0U);  // pressing in from the front is no hold
    // Taken as where a next stroke starts, the last tick starts it behind the sheet (both
    // sides touchable only); the first, its proxy at the hand, starts none behind.
    const std::vector<std::size_t> starts = {0, risen.size() - 1};
    EXPECT_EQ(count_strokes_starting_behind(oracle, risen, starts), faces == TouchableFaces::Both ? 1U : 0U);
    EXPECT_EQ(count_strokes_starting_behind(oracle, risen, std::vector<std::size_t>{0}), 0U);
    if (faces == TouchableFaces::Front) {
      EXPECT_EQ(risen.back().proxy_W, risen.back().p_W_hip);
      EXPECT_EQ(risen.back().force_W, Vector3d::Zero());
      for (const TickSample& s : risen) EXPECT_LT((s.proxy_W - s.p_W_hip).norm(), 1e-9);
    } else {
      EXPECT_LT(risen.back().proxy_W.z(), 0.0);  // held under the sheet
      EXPECT_LT(risen.back().force_W.z(), 0.0);
    }
  }
}

TEST(DriveProxy, AFrontOnlyScanFileWithTrianglesWoundTheWrongWayHoldsTheHandOnEveryOne) {
  // A scan's sheet (40 x 40 quads of 1 mm, facing +z) written with every fifth triangle
  // wound the wrong way, as files from some tools come, and touched from the front only.
  // The hand comes down through the sheet at points over many triangles, the flipped ones
  // among them. Judged by the sheet as made (every triangle facing +z): the proxy never
  // crosses the front and is held on top every time.
  test::TempDir dir;
  const TriangleMesh made = test::sheet_mesh(40);
  TriangleMesh written = made;
  for (std::size_t t = 0; t < written.triangles.size(); t += 5) std::swap(written.triangles[t][1], written.triangles[t][2]);
  test::write_binary_ply(dir / "scan.ply", written);
  const auto loaded = load_mesh_file(dir / "scan.ply", Vector3d::Ones());
  ASSERT_TRUE(loaded.ok()) << loaded.error_text();
  CollisionWorld world;
  const int id = world.add_object(std::make_shared<const MeshBvh>(std::make_shared<const TriangleMesh>(loaded->mesh)),
                                  Pose::Identity());
  world.set_touchable(id, TouchableFaces::Front);
  const PlacedMesh truth{&made, Pose::Identity(), TouchableFaces::Front};
  const SurfaceCrossingOracle oracle(std::span<const PlacedMesh>(&truth, 1));
  const std::vector<HapticMaterial> materials(1);
  const ProxySettings settings;
  std::size_t crossings = 0, held = 0, strokes = 0;
  for (int j = 0; j < 12; ++j) {
    for (int i = 0; i < 12; ++i) {
      // 12 x 12 points about 0.8 mm apart, off the grid's lines.
      const Vector3d above(0.015 + 0.00083 * i, 0.015 + 0.00079 * j, 0.004);
      std::vector<Vector3d> down;
      for (int k = 0; k <= 160; ++k) down.push_back(above - Vector3d(0, 0, 0.00005 * k));  // to 4 mm below
      const TickRecord records = drive_proxy(world, materials, settings, down, 1000.0);
      crossings += count_crossings(oracle, records);
      held += records.back().proxy_W.z() >= 0.0 && records.back().force_W.z() > 0.0 ? 1 : 0;
      ++strokes;
    }
  }
  EXPECT_EQ(crossings, 0U);
  EXPECT_EQ(held, strokes);
}

TEST(DriveProxy, FastStrokesDoNotPopThrough) {
  const BoxWorld box;
  const SurfaceCrossingOracle oracle(box.world);
  const StrokeSet set = make_fast_strokes(oracle, 78, 50);
  std::size_t crossings = 0, inside = 0;
  for (const Stroke& stroke : set.strokes) {
    const TickRecord records = drive_proxy(box.world, box.materials, box.settings, stroke.p_W_hip, 1000.0);
    crossings += count_crossings(oracle, records);
    inside += count_ticks_inside(oracle, records);
  }
  EXPECT_EQ(crossings, 0U);
  EXPECT_EQ(inside, 0U);
}

TEST(DriveProxy, AProxyThatFollowsTheHipIsCaught) {
  const BoxWorld box;
  const SurfaceCrossingOracle oracle(box.world);
  const Stroke stroke = make_anchor_strokes(oracle, 79, 1).strokes.front();
  TickRecord records(stroke.p_W_hip.size());
  for (std::size_t k = 0; k < records.size(); ++k) {
    records[k].p_W_hip = records[k].proxy_W = records[k].path_W[0] = stroke.p_W_hip[k];
    records[k].path_points = 1;
  }
  // In through the face on the way down, out again on the retract (or past an edge).
  EXPECT_GE(count_crossings(oracle, records), 2U);
  EXPECT_GT(count_ticks_inside(oracle, records), 100U);
}

TEST(DriveProxy, EmptyPathGivesEmptyRecord) {
  const BoxWorld box;
  EXPECT_TRUE(drive_proxy(box.world, box.materials, box.settings, {}, 1000.0).empty());
  const std::vector<Vector3d> one{Vector3d(0.5, 0.5, 0.5)};
  EXPECT_THROW((void)drive_proxy(box.world, box.materials, box.settings, one, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace mhd::verify
