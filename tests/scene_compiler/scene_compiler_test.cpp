#include "scene_compiler/scene_compiler.h"

#include "geometry/primitive_mesh.h"
#include "../mesh_io/test_mesh_files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace mhd {
namespace {

using test::TempDir;

ObjectDescription make_object(std::string name, ShapeSource shape, int line, double stiffness = 1000.0) {
  ObjectDescription o;
  o.name = std::move(name);
  o.shape = std::move(shape);
  o.material.stiffness_N_per_m = stiffness;
  o.where = {"scene.xml", line};
  return o;
}

std::size_t count_cache_files(const std::filesystem::path& dir) {
  if (!std::filesystem::exists(dir)) return 0;
  return static_cast<std::size_t>(std::count_if(std::filesystem::directory_iterator(dir), {}, [](const auto& e) {
    return e.path().extension() == ".mhdbvh";
  }));
}

class SceneCompilerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    box_obj_ = dir_ / "box_mm.obj";
    test::write_box_obj(box_obj_, Eigen::Vector3d(-50, -25, -10), Eigen::Vector3d(50, 25, 10));  // mm
    options_.cache_dir = dir_ / "cache";
  }
  MeshSource box_mm() const { return MeshSource{box_obj_, Eigen::Vector3d::Constant(0.001)}; }

  TempDir dir_;
  std::filesystem::path box_obj_;
  CompileOptions options_;
};

TEST_F(SceneCompilerTest, CompilesAMeshAndEveryPrimitive) {
  SceneDescription d;
  d.name = "everything";
  d.file = "scene.xml";
  d.haptics.max_force_N = 3.25;
  d.objects.push_back(make_object("mesh", box_mm(), 10, 100.0));
  d.objects.push_back(make_object("floor", PlaneSource{2.0, 1.0}, 11, 200.0));
  d.objects.push_back(make_object("ball", SphereSource{0.05, 3}, 12, 300.0));
  d.objects.push_back(make_object("brick", BoxSource{Eigen::Vector3d(0.1, 0.2, 0.3)}, 13, 400.0));
  d.objects.push_back(make_object("can", CylinderSource{0.03, 0.1, 24}, 14, 500.0));
  d.objects[2].X_WO = pose_from_xyz_rpy(Eigen::Vector3d(0.1, 0.2, 0.3), Eigen::Vector3d(0.1, 0.2, 0.3));

  const Result<std::unique_ptr<CompiledScene>> r = compile_scene(d, options_);
  ASSERT_TRUE(r.ok()) << (r.diagnostics().empty() ? "" : r.diagnostics().front().to_string());
  EXPECT_TRUE(r.diagnostics().empty());
  const CompiledScene& s = *r.value();
  EXPECT_EQ(s.name, "everything");
  EXPECT_EQ(s.proxy.max_force_N, 3.25);
  ASSERT_EQ(s.world.object_count(), 5);
  ASSERT_EQ(s.materials.size(), 5u);
  ASSERT_EQ(s.object_names.size(), 5u);

  const std::vector<std::size_t> triangles = {12, 2, 20 * 64, 12, 4 * 24};
  std::size_t total = 0;
  for (int i = 0; i < 5; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    EXPECT_EQ(s.object_names[ui], d.objects[ui].name);
    EXPECT_EQ(s.materials[ui].stiffness_N_per_m, d.objects[ui].material.stiffness_N_per_m);
    EXPECT_TRUE(s.world.pose(i).isApprox(d.objects[ui].X_WO));
    EXPECT_EQ(s.world.shape(i).mesh().triangle_count(), triangles[ui]) << d.objects[ui].name;
    EXPECT_EQ(s.world.shape(i).mesh().vertex_normals.size(), s.world.shape(i).mesh().vertices_m.size());
    total += triangles[ui];
  }
  EXPECT_EQ(s.triangle_count, total);

  // The mesh is in metres, the primitives have their sizes.
  const auto mesh_box = s.world.shape(0).bounds();
  EXPECT_NEAR(mesh_box.max().x(), 0.05, 1e-9);
  EXPECT_NEAR(mesh_box.min().z(), -0.01, 1e-9);
  EXPECT_NEAR(s.world.shape(1).bounds().sizes().x(), 2.0, 1e-12);
  EXPECT_NEAR(s.world.shape(2).bounds().max().norm(), 0.05 * std::sqrt(3.0), 0.01);
  EXPECT_NEAR(s.world.shape(3).bounds().sizes().z(), 0.3, 1e-12);
  EXPECT_NEAR(s.world.shape(4).bounds().sizes().z(), 0.1, 1e-12);

  // The BVHs answer queries: the plane's two triangles are found around the origin.
  std::vector<std::uint32_t> hits;
  s.world.shape(1).for_each_triangle_overlapping(
      Eigen::AlignedBox3d(Eigen::Vector3d(-0.01, -0.01, -0.01), Eigen::Vector3d(0.01, 0.01, 0.01)),
      [&](std::uint32_t t) { hits.push_back(t); });
  std::sort(hits.begin(), hits.end());
  EXPECT_EQ(hits, (std::vector<std::uint32_t>{0, 1}));
}

TEST_F(SceneCompilerTest, IdenticalSourcesAreLoadedOnceAndShared) {
  SceneDescription d;
  d.objects.push_back(make_object("a", box_mm(), 1));
  d.objects.push_back(make_object("b", box_mm(), 2));
  MeshSource other_scale = box_mm();
  other_scale.scale_to_m = Eigen::Vector3d(0.001, 0.001, 0.002);
  d.objects.push_back(make_object("c", other_scale, 3));
  // The same file through a different spelling of its path.
  MeshSource same_file = box_mm();
  same_file.file = dir_.path() / "." / "sub" / ".." / "box_mm.obj";
  std::filesystem::create_directories(dir_ / "sub");
  d.objects.push_back(make_object("d", same_file, 4));
  d.objects.push_back(make_object("s1", SphereSource{0.02, 2}, 5));
  d.objects.push_back(make_object("s2", SphereSource{0.02, 2}, 6));
  d.objects.push_back(make_object("s3", SphereSource{0.03, 2}, 7));
  d.objects[1].X_WO.translation() = Eigen::Vector3d(1, 0, 0);

  for (const bool use_cache : {true, false}) {
    SCOPED_TRACE(use_cache);
    options_.use_cache = use_cache;
    const Result<std::unique_ptr<CompiledScene>> r = compile_scene(d, options_);
    ASSERT_TRUE(r.ok());
    const CollisionWorld& w = r.value()->world;
    EXPECT_EQ(&w.shape(0), &w.shape(1));
    EXPECT_EQ(&w.shape(0), &w.shape(3));
    EXPECT_NE(&w.shape(0), &w.shape(2));
    EXPECT_EQ(&w.shape(4), &w.shape(5));
    EXPECT_NE(&w.shape(4), &w.shape(6));
    EXPECT_NEAR(w.shape(2).bounds().max().z(), 0.02, 1e-9);
    EXPECT_TRUE(w.pose(1).translation().isApprox(Eigen::Vector3d(1, 0, 0)));
    EXPECT_EQ(r.value()->triangle_count, 4 * 12 + 3 * 320u);
  }
  // One cache entry per distinct (file, scale).
  EXPECT_EQ(count_cache_files(dir_ / "cache"), 2u);
}

TEST_F(SceneCompilerTest, CacheIsOptional) {
  SceneDescription d;
  d.objects.push_back(make_object("a", box_mm(), 1));
  options_.use_cache = false;
  ASSERT_TRUE(compile_scene(d, options_).ok());
  EXPECT_EQ(count_cache_files(dir_ / "cache"), 0u);

  options_.use_cache = true;
  const Result<std::unique_ptr<CompiledScene>> first = compile_scene(d, options_);
  ASSERT_TRUE(first.ok());
  EXPECT_EQ(count_cache_files(dir_ / "cache"), 1u);
  const Result<std::unique_ptr<CompiledScene>> second = compile_scene(d, options_);  // from the cache
  ASSERT_TRUE(second.ok());
  EXPECT_EQ(second.value()->world.shape(0).mesh().vertices_m, first.value()->world.shape(0).mesh().vertices_m);
  EXPECT_EQ(second.value()->world.shape(0).mesh().triangles, first.value()->world.shape(0).mesh().triangles);
}

TEST_F(SceneCompilerTest, MeshErrorsNameTheObjectTheFileAndTheReason) {
  SceneDescription d;
  d.objects.push_back(make_object("fine", box_mm(), 3));
  const auto missing = dir_ / "missing.stl";
  d.objects.push_back(make_object("ghost", MeshSource{missing, Eigen::Vector3d::Ones()}, 7));
  test::write_text(dir_ / "lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n");
  d.objects.push_back(make_object("wire", MeshSource{dir_ / "lines.obj", Eigen::Vector3d::Ones()}, 9));
  test::write_text(dir_ / "junk.ply", std::string(1000, '\x7f'));
  d.objects.push_back(make_object("junk", MeshSource{dir_ / "junk.ply", Eigen::Vector3d::Ones()}, 11));
  d.objects.push_back(make_object("ghost2", MeshSource{missing, Eigen::Vector3d::Ones()}, 13));

  const Result<std::unique_ptr<CompiledScene>> r = compile_scene(d, options_);
  EXPECT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics().size(), 4u);
  EXPECT_EQ(r.diagnostics()[0].where.file, "scene.xml");
  EXPECT_EQ(r.diagnostics()[0].where.line, 7);
  EXPECT_EQ(r.diagnostics()[0].message, "object 'ghost': mesh file '" + missing.string() + "': file not found");
  EXPECT_EQ(r.diagnostics()[1].where.line, 9);
  EXPECT_TRUE(r.diagnostics()[1].message.starts_with("object 'wire': mesh file '")) << r.diagnostics()[1].message;
  EXPECT_NE(r.diagnostics()[1].message.find("no triangles"), std::string::npos) << r.diagnostics()[1].message;
  EXPECT_EQ(r.diagnostics()[2].where.line, 11);
  EXPECT_NE(r.diagnostics()[2].message.find("junk.ply"), std::string::npos) << r.diagnostics()[2].message;
  // A shared failing source is reported for every object that names it.
  EXPECT_EQ(r.diagnostics()[3].where.line, 13);
  EXPECT_EQ(r.diagnostics()[3].message, "object 'ghost2': mesh file '" + missing.string() + "': file not found");
  EXPECT_NE(r.diagnostics()[0].to_string().find("scene.xml:7"), std::string::npos);
}

TEST_F(SceneCompilerTest, InvalidPrimitivesAndPosesAreDiagnosed) {
  SceneDescription d;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  d.objects.push_back(make_object("flat", PlaneSource{0.0, 1.0}, 1));
  d.objects.push_back(make_object("ball", SphereSource{0.1, 9}, 2));
  d.objects.push_back(make_object("dot", SphereSource{-0.1, 2}, 3));
  d.objects.push_back(make_object("brick", BoxSource{Eigen::Vector3d(1, nan, 1)}, 4));
  d.objects.push_back(make_object("can", CylinderSource{0.1, 0.1, 2}, 5));
  d.objects.push_back(make_object("ok", BoxSource{Eigen::Vector3d(1, 1, 1)}, 6));
  d.objects.push_back(make_object("lost", BoxSource{Eigen::Vector3d(1, 1, 1)}, 7));
  d.objects.back().X_WO.translation().x() = nan;
  d.objects.push_back(make_object("sheared", BoxSource{Eigen::Vector3d(1, 1, 1)}, 8));
  d.objects.back().X_WO.linear()(0, 1) = 0.5;

  const Result<std::unique_ptr<CompiledScene>> r = compile_scene(d, options_);
  EXPECT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics().size(), 7u);
  const std::vector<int> lines = {1, 2, 3, 4, 5, 7, 8};
  const std::vector<std::string> names = {"flat", "ball", "dot", "brick", "can", "lost", "sheared"};
  for (std::size_t i = 0; i < lines.size(); ++i) {
    EXPECT_EQ(r.diagnostics()[i].where.line, lines[i]);
    EXPECT_TRUE(r.diagnostics()[i].message.starts_with("object '" + names[i] + "': ")) << r.diagnostics()[i].message;
  }
  EXPECT_NE(r.diagnostics()[1].message.find("subdivisions"), std::string::npos);
  EXPECT_NE(r.diagnostics()[4].message.find("segments"), std::string::npos);
  EXPECT_NE(r.diagnostics()[5].message.find("pose"), std::string::npos);
}

TEST_F(SceneCompilerTest, ShadedObjectsGetCornerNormalsWithTheirMaterialsCreaseAngle) {
  SceneDescription d;
  d.objects.push_back(make_object("plain", BoxSource{Eigen::Vector3d(0.1, 0.1, 0.1)}, 1));
  d.objects.push_back(make_object("sharp", BoxSource{Eigen::Vector3d(0.1, 0.1, 0.1)}, 2));
  d.objects.push_back(make_object("sharp_too", BoxSource{Eigen::Vector3d(0.1, 0.1, 0.1)}, 3));
  d.objects.push_back(make_object("round", BoxSource{Eigen::Vector3d(0.1, 0.1, 0.1)}, 4));
  for (std::size_t i = 1; i < 4; ++i) d.objects[i].material.force_shading = true;
  d.objects[3].material.force_shading_crease_rad = 2.0;  // above the box's right angles
  const Result<std::unique_ptr<CompiledScene>> r = compile_scene(d, options_);
  ASSERT_TRUE(r.ok());
  const CollisionWorld& world = r.value()->world;
  EXPECT_EQ(world.shading_normals(0), nullptr);  // unshaded: nothing computed
  ASSERT_NE(world.shading_normals(1), nullptr);
  ASSERT_NE(world.shading_normals(3), nullptr);
  EXPECT_EQ(world.shading_normals(1), world.shading_normals(2));  // same shape, same crease: shared
  EXPECT_DOUBLE_EQ(world.shading_normals(1)->crease_angle_rad, r.value()->materials[1].force_shading_crease_rad);
  EXPECT_DOUBLE_EQ(world.shading_normals(3)->crease_angle_rad, 2.0);
  // At a box corner the sharp box keeps the face normal, the round one blends three faces.
  const TriangleRef face{1, 0};
  const Eigen::Vector3d at_corner = world.triangle_W(face)[0];
  EXPECT_TRUE(world.shaded_normal_W(face, at_corner).isApprox(world.face_normal_W(face), 1e-6));
  const TriangleRef round_face{3, 0};
  EXPECT_NEAR(std::abs(world.shaded_normal_W(round_face, at_corner).dot(world.face_normal_W(round_face))),
              1.0 / std::sqrt(3.0), 1e-6);
}

TEST_F(SceneCompilerTest, AShadingCreaseAngleOutsideZeroToPiIsDiagnosed) {
  SceneDescription d;
  d.objects.push_back(make_object("ball", SphereSource{0.1, 1}, 7));
  d.objects[0].material.force_shading = true;
  d.objects[0].material.force_shading_crease_rad = std::numeric_limits<double>::quiet_NaN();
  d.objects.push_back(make_object("cube", BoxSource{Eigen::Vector3d(1, 1, 1)}, 8));
  d.objects[1].material.force_shading_crease_rad = -0.1;
  const Result<std::unique_ptr<CompiledScene>> r = compile_scene(d, options_);
  ASSERT_EQ(r.diagnostics().size(), 2u);
  EXPECT_EQ(r.diagnostics()[0].where.line, 7);
  EXPECT_EQ(r.diagnostics()[0].message, "object 'ball': force shading crease angle must be within [0, pi] rad (got nan rad)");
  EXPECT_EQ(r.diagnostics()[1].where.line, 8);
}

TEST_F(SceneCompilerTest, EmptySceneCompiles) {
  SceneDescription d;
  d.name = "empty";
  const Result<std::unique_ptr<CompiledScene>> r = compile_scene(d, options_);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.value()->world.object_count(), 0);
  EXPECT_EQ(r.value()->triangle_count, 0u);
}

TEST_F(SceneCompilerTest, LargeShapesReportProgress) {
  SceneDescription d;
  d.objects.push_back(make_object("small", SphereSource{0.1, 2}, 1));
  d.objects.push_back(make_object("big", SphereSource{0.1, 7}, 2));  // 327680 triangles
  std::vector<std::pair<std::string, double>> calls;
  options_.progress = [&](std::string_view what, double f) { calls.emplace_back(std::string(what), f); };
  const Result<std::unique_ptr<CompiledScene>> r = compile_scene(d, options_);
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(calls.size(), 2u);
  EXPECT_TRUE(calls[0].first.starts_with("object 'big': building BVH")) << calls[0].first;
  EXPECT_EQ(calls[0].second, 0.0);
  EXPECT_EQ(calls[1].second, 1.0);
}

}  // namespace
}  // namespace mhd

namespace mhd {
namespace {

TEST(SceneCompilerExact, AnExactPrimitiveGetsItsShapeAndATessellatedOneDoesNot) {
  SceneDescription d;
  d.name = "exact";
  d.file = "scene.xml";
  const auto object = [&](const std::string& name, ShapeSource shape) {
    ObjectDescription o;
    o.name = name;
    o.shape = std::move(shape);
    o.X_WO = Pose::Identity();
    d.objects.push_back(std::move(o));
  };
  object("floor", PlaneSource{2.0, 1.0, true});
  object("ball", SphereSource{0.05, 2, true});
  object("faceted", SphereSource{0.05, 2, false});
  object("brick", BoxSource{Eigen::Vector3d(0.1, 0.2, 0.3), true});
  object("can", CylinderSource{0.03, 0.1, 24, true});
  object("rod", CapsuleSource{0.02, 0.1, 16, true});
  CompileOptions options;
  const Result<std::unique_ptr<CompiledScene>> r = compile_scene(d, options);
  ASSERT_TRUE(r.ok()) << (r.diagnostics().empty() ? "" : r.diagnostics().front().to_string());
  const CollisionWorld& w = r.value()->world;
  ASSERT_NE(w.exact_shape(0), nullptr);
  EXPECT_EQ(w.exact_shape(0)->kind, ExactKind::HalfSpace);
  ASSERT_NE(w.exact_shape(1), nullptr);
  EXPECT_EQ(w.exact_shape(1)->radius_m, 0.05);
  EXPECT_EQ(w.exact_shape(2), nullptr);
  ASSERT_NE(w.exact_shape(3), nullptr);
  EXPECT_EQ(w.exact_shape(3)->half_extents_m, Eigen::Vector3d(0.05, 0.1, 0.15));
  ASSERT_NE(w.exact_shape(4), nullptr);
  EXPECT_EQ(w.exact_shape(4)->half_height_m, 0.05);
  ASSERT_NE(w.exact_shape(5), nullptr);
  EXPECT_EQ(w.exact_shape(5)->kind, ExactKind::Capsule);
  EXPECT_EQ(w.exact_shape(5)->half_height_m, 0.05);
  // Every vertex of the capsule's tessellation lies on the exact capsule.
  for (const Eigen::Vector3d& v : w.shape(5).mesh().vertices_m) {
    const double z = std::max(std::abs(v.z()) - 0.05, 0.0);
    EXPECT_NEAR(std::hypot(v.x(), v.y(), z), 0.02, 1e-12);
  }
}

TEST(SceneCompilerExact, ACapsuleWithABadSizeIsRefused) {
  SceneDescription d;
  d.name = "bad";
  d.file = "scene.xml";
  ObjectDescription o;
  o.name = "rod";
  o.shape = CapsuleSource{0.02, -0.1, 16, true};
  d.objects.push_back(o);
  CompileOptions options;
  EXPECT_FALSE(compile_scene(d, options).ok());
  std::get<CapsuleSource>(d.objects[0].shape).length_m = 0.1;
  EXPECT_TRUE(compile_scene(d, options).ok());
}

}  // namespace
}  // namespace mhd
