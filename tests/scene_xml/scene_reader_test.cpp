// Reading valid scenes: SI conversion, poses, materials, includes, rig and plugins;
// and read_scene_string's own cases (errors that need no file of their own).

#include "geometry/pose.h"
#include "scene_test_support.h"
#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>

#include <map>

#include <string>
#include <variant>
#include <vector>

namespace mhd {
namespace {

namespace fs = std::filesystem;
using test::to_strings;
using Lines = std::vector<std::string>;

constexpr double kTol = 1e-12;
const std::string kFull = "tests/data/scenes/valid/full.xml";

void expect_material(const HapticMaterial& m, double k, double b, double mu_s, double mu_d,
                     bool shading) {
  EXPECT_DOUBLE_EQ(m.stiffness_N_per_m, k);
  EXPECT_DOUBLE_EQ(m.damping_Ns_per_m, b);
  EXPECT_DOUBLE_EQ(m.static_friction, mu_s);
  EXPECT_DOUBLE_EQ(m.dynamic_friction, mu_d);
  EXPECT_EQ(m.force_shading, shading);
}

void expect_vec(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected) {
  EXPECT_TRUE(actual.isApprox(expected, kTol) || (actual - expected).norm() < kTol)
      << "actual " << actual.transpose() << ", expected " << expected.transpose();
}

void expect_rotation(const Pose& X, const Eigen::Matrix3d& expected) {
  EXPECT_LT((X.linear() - expected).norm(), kTol) << "actual\n" << X.linear();
}

class SceneXmlReader : public test::FromSourceRoot {
 protected:
  static SceneDescription read_ok(const fs::path& file) {
    Result<SceneDescription> result = read_scene_file(file);
    EXPECT_EQ(to_strings(result.diagnostics()), Lines{});
    EXPECT_TRUE(result.ok());
    return result.value_or(SceneDescription{});
  }
  /// Diagnostics of an in-memory scene named "mem/scene.xml".
  static Lines errors_of(std::string_view xml) {
    const Result<SceneDescription> result = read_scene_string(xml, "mem/scene.xml");
    EXPECT_FALSE(result.ok());
    return to_strings(result.diagnostics());
  }
  static std::string at(int line, const std::string& message) {
    return "mem/scene.xml:" + std::to_string(line) + ": error: " + message;
  }
};

TEST_F(SceneXmlReader, FullSceneHeaderAndHaptics) {
  const SceneDescription s = read_ok(kFull);
  EXPECT_EQ(s.file, fs::path(kFull));
  EXPECT_EQ(s.name, "test_full");
  ASSERT_TRUE(s.haptics.max_force_N);
  EXPECT_DOUBLE_EQ(*s.haptics.max_force_N, 5.0);
  EXPECT_DOUBLE_EQ(s.haptics.update_rate_Hz, 2000.0);
}

TEST_F(SceneXmlReader, FullSceneNamedMaterialsIncludingLaterAndIncludedOnes) {
  const SceneDescription s = read_ok(kFull);
  ASSERT_EQ(s.materials.size(), 3u);
  expect_material(s.materials.at("skin"), 800, 0.5, 0.4, 0.3, true);
  expect_material(s.materials.at("steel"), 3000, 0, 0, 0, false);
  expect_material(s.materials.at("wood"), 2000, 0, 0, 0, false);
}

TEST_F(SceneXmlReader, FullSceneObjectsInFileOrderWithIncludesInPlace) {
  const SceneDescription s = read_ok(kFull);
  std::vector<std::string> names;
  for (const ObjectDescription& o : s.objects) names.push_back(o.name);
  EXPECT_EQ(names, (std::vector<std::string>{"tetra", "ball", "table", "post", "floor", "big_tetra"}));
}

TEST_F(SceneXmlReader, MeshInMillimetresWithScaleAndRpy) {
  const SceneDescription s = read_ok(kFull);
  ASSERT_GE(s.objects.size(), 1u);
  const ObjectDescription& o = s.objects[0];
  const auto* mesh = std::get_if<MeshSource>(&o.shape);
  ASSERT_NE(mesh, nullptr);
  EXPECT_TRUE(mesh->file.is_absolute());
  EXPECT_EQ(mesh->file, (test::kSourceDir / "tests/data/scenes/valid/assets/tetrahedron.ply").lexically_normal());
  expect_vec(mesh->scale_to_m, {0.001, 0.002, 0.003});
  expect_vec(o.X_WO.translation(), {0.1, 0.2, -0.3});
  // pitch 90 deg: R = Ry(90), x -> -z, z -> x.
  Eigen::Matrix3d Ry;
  Ry << 0, 0, 1, 0, 1, 0, -1, 0, 0;
  expect_rotation(o.X_WO, Ry);
  EXPECT_EQ(o.material_name, "skin");
  expect_material(o.material, 800, 0.5, 0.4, 0.3, true);
  EXPECT_EQ(o.where.file, kFull);
  EXPECT_EQ(o.where.line, 7);
}

TEST_F(SceneXmlReader, SphereWithInlineMaterialAndQuaternion) {
  const SceneDescription s = read_ok(kFull);
  ASSERT_GE(s.objects.size(), 2u);
  const ObjectDescription& o = s.objects[1];
  const auto* sphere = std::get_if<SphereSource>(&o.shape);
  ASSERT_NE(sphere, nullptr);
  EXPECT_DOUBLE_EQ(sphere->radius_m, 0.05);
  EXPECT_EQ(sphere->subdivisions, 3);
  EXPECT_EQ(o.material_name, "");
  expect_material(o.material, 1500, 2, 0.5, 0.25, true);
  expect_vec(o.X_WO.translation(), {0, 0, 0.01});
  // quaternion (0 0 0 2) is normalised to a half turn about z.
  expect_rotation(o.X_WO, Eigen::Vector3d(-1, -1, 1).asDiagonal().toDenseMatrix());
}

TEST_F(SceneXmlReader, BoxAndCylinderInMillimetres) {
  const SceneDescription s = read_ok(kFull);
  ASSERT_GE(s.objects.size(), 4u);
  const auto* box = std::get_if<BoxSource>(&s.objects[2].shape);
  ASSERT_NE(box, nullptr);
  expect_vec(box->size_m, {1.0, 0.5, 0.02});
  expect_material(s.objects[2].material, 2000, 0, 0, 0, false);
  EXPECT_TRUE(s.objects[2].X_WO.isApprox(Pose::Identity()));
  const auto* cylinder = std::get_if<CylinderSource>(&s.objects[3].shape);
  ASSERT_NE(cylinder, nullptr);
  EXPECT_DOUBLE_EQ(cylinder->radius_m, 0.01);
  EXPECT_DOUBLE_EQ(cylinder->height_m, 0.3);
  EXPECT_EQ(cylinder->segments, 16);
  EXPECT_EQ(s.objects[3].material_name, "steel");
}

TEST_F(SceneXmlReader, IncludedFileKeepsItsOwnUnitAndLocation) {
  const SceneDescription s = read_ok(kFull);
  ASSERT_EQ(s.objects.size(), 6u);
  const ObjectDescription& floor = s.objects[4];
  const auto* plane = std::get_if<PlaneSource>(&floor.shape);
  ASSERT_NE(plane, nullptr);
  EXPECT_DOUBLE_EQ(plane->size_x_m, 4.0);
  EXPECT_DOUBLE_EQ(plane->size_y_m, 3.0);
  EXPECT_EQ(floor.where.file, "tests/data/scenes/valid/parts/floor.xml");
  EXPECT_EQ(floor.where.line, 4);

  const ObjectDescription& big = s.objects[5];
  const auto* mesh = std::get_if<MeshSource>(&big.shape);
  ASSERT_NE(mesh, nullptr);
  expect_vec(mesh->scale_to_m, {2, 2, 2});
  EXPECT_EQ(mesh->file, (test::kSourceDir / "tests/data/scenes/valid/assets/tetrahedron.ply").lexically_normal());
  expect_vec(big.X_WO.translation(), {1, 2, 3});
}

TEST_F(SceneXmlReader, RigFramesWithUnitsAndParents) {
  const SceneDescription s = read_ok(kFull);
  ASSERT_EQ(s.rig_frames.size(), 3u);
  // The include (and its frame) comes before <rig> in full.xml.
  const FrameDescription& base = s.rig_frames[0];
  EXPECT_EQ(base.name, "base");
  EXPECT_EQ(base.parent, "is900");
  expect_vec(base.X_PF.translation(), {1, 0, 0});
  const FrameDescription& is900 = s.rig_frames[1];
  EXPECT_EQ(is900.name, "is900");
  EXPECT_EQ(is900.parent, "world");
  expect_vec(is900.X_PF.translation(), {0, 2.624, 0});
  Eigen::Matrix3d Rx;  // roll 90 deg: y -> z
  Rx << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  expect_rotation(is900.X_PF, Rx);
  EXPECT_EQ(is900.where.line, 27);
  const FrameDescription& head = s.rig_frames[2];
  EXPECT_EQ(head.parent, "base");
  expect_vec(head.X_PF.translation(), {0.01, 0, 0});
}

TEST_F(SceneXmlReader, PluginsWithParams) {
  const SceneDescription s = read_ok(kFull);
  ASSERT_EQ(s.plugins.size(), 2u);
  EXPECT_EQ(s.plugins[0].kind, PluginKind::Device);
  EXPECT_EQ(s.plugins[0].name, "sim_phantom");
  EXPECT_EQ(s.plugins[0].params,
            (std::map<std::string, std::string>{{"position_resolution_m", "3e-05"}, {"hand_model", "kinematic"}}));
  EXPECT_EQ(s.plugins[0].where.line, 31);
  EXPECT_EQ(s.plugins[1].kind, PluginKind::Tracker);
  EXPECT_EQ(s.plugins[1].name, "sim_is900");
  EXPECT_TRUE(s.plugins[1].params.empty());
}

TEST_F(SceneXmlReader, RotationMatchesPoseFromXyzRpy) {
  const Result<SceneDescription> r = read_scene_string(R"(<scene version="1">
    <object name="o"><material stiffness_N_per_m="1"/><sphere radius="1"/>
      <pose position="1 2 3" rpy_deg="10 20 30"/></object></scene>)", "x.xml");
  ASSERT_TRUE(r.ok()) << to_strings(r.diagnostics()).front();
  const double d = 3.14159265358979323846 / 180.0;
  const Pose expected = pose_from_xyz_rpy({1, 2, 3}, {10 * d, 20 * d, 30 * d});
  EXPECT_TRUE(r->objects[0].X_WO.isApprox(expected, 1e-12));
}

TEST_F(SceneXmlReader, LinesEndedByALoneCarriageReturnAreCountedAsLines) {
  // XML 1.0 2.11: CR, LF and CR LF all end a line. tinyxml2 counts only LF, so a file
  // with CR line ends put every error on line 1 (found by fuzzing).
  const Result<SceneDescription> r = read_scene_string(
      "<scene version=\"1\">\r<object name=\"a\"><material stiffness_N_per_m=\"-1\"/><sphere radius=\"1\"/></object>\r"
      "<object name=\"b\"><material stiffness_N_per_m=\"1\"/><sphere radius=\"-1\"/></object>\r</scene>\r",
      "cr.xml");
  ASSERT_EQ(r.diagnostics().size(), 2u);
  EXPECT_EQ(r.diagnostics()[0].where.line, 2);
  EXPECT_EQ(r.diagnostics()[1].where.line, 3);
}

TEST_F(SceneXmlReader, PrimitiveDimensionsOutsideOneMicrometreToTenKilometresAreRefused) {
  const Result<SceneDescription> r = read_scene_string(R"(<scene version="1">
    <object name="a"><material stiffness_N_per_m="1"/><box size="1e300 1 1"/></object>
    <object name="b"><material stiffness_N_per_m="1"/><sphere radius="1e-300"/></object>
    <object name="c"><material stiffness_N_per_m="1"/><cylinder radius="0.1" height="2e4"/></object>
    <object name="d"><material stiffness_N_per_m="1"/><plane size="1e4 1e-6"/></object></scene>)", "x.xml");
  const std::vector<std::string> errors = to_strings(r.diagnostics());
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_EQ(errors[0], "x.xml:2: error: attribute 'size' on <box> must be between 1e-6 m and 1e4 m (is 1e+300 m)");
  EXPECT_EQ(errors[1], "x.xml:3: error: attribute 'radius' on <sphere> must be between 1e-6 m and 1e4 m (is 1e-300 m)");
  EXPECT_EQ(errors[2], "x.xml:4: error: attribute 'height' on <cylinder> must be between 1e-6 m and 1e4 m (is 20000 m)");
}

TEST_F(SceneXmlReader, TouchableFacesAreReadAndBothByDefault) {
  const Result<SceneDescription> r = read_scene_string(R"(<scene version="1">
    <object name="a"><material stiffness_N_per_m="1"/><box size="1 1 1"/></object>
    <object name="b" touchable="front"><material stiffness_N_per_m="1"/><box size="1 1 1"/></object>
    <object name="c" touchable="back"><material stiffness_N_per_m="1"/><sphere radius="1"/></object>
    <object name="d" touchable="both"><material stiffness_N_per_m="1"/><plane size="1 1"/></object></scene>)", "x.xml");
  ASSERT_TRUE(r.ok()) << to_strings(r.diagnostics()).front();
  ASSERT_EQ(r->objects.size(), 4u);
  EXPECT_EQ(r->objects[0].touchable, TouchableFaces::Both);
  EXPECT_EQ(r->objects[1].touchable, TouchableFaces::Front);
  EXPECT_EQ(r->objects[2].touchable, TouchableFaces::Back);
  EXPECT_EQ(r->objects[3].touchable, TouchableFaces::Both);
}

TEST_F(SceneXmlReader, TouchableFacesOtherThanTheThreeOrOnAnExactSolidAreRefused) {
  const Result<SceneDescription> r = read_scene_string(R"(<scene version="1">
    <object name="a" touchable="outside"><material stiffness_N_per_m="1"/><box size="1 1 1"/></object>
    <object name="b" touchable=""><material stiffness_N_per_m="1"/><box size="1 1 1"/></object>
    <object name="c" touchable="front"><material stiffness_N_per_m="1"/><sphere radius="1" exact="true"/></object>
    <object name="d" touchable="FRONT"><material stiffness_N_per_m="1"/><box size="1 1 1"/></object></scene>)", "x.xml");
  const std::vector<std::string> errors = to_strings(r.diagnostics());
  ASSERT_EQ(errors.size(), 4u) << ::testing::PrintToString(errors);
  EXPECT_EQ(errors[0], "x.xml:2: error: attribute 'touchable' on object 'a' must be front, back or both (is 'outside')");
  EXPECT_NE(errors[1].find("x.xml:3: error:"), std::string::npos) << errors[1];
  EXPECT_EQ(errors[2], "x.xml:4: error: object 'c' is an exact <sphere>, a solid touched from outside; "
                       "touchable=\"front\" applies to triangles (set exact=\"false\")");
  EXPECT_EQ(errors[3], "x.xml:5: error: attribute 'touchable' on object 'd' must be front, back or both (is 'FRONT')");
}

TEST_F(SceneXmlReader, AQuaternionOfTinyComponentsIsNotAllZeros) {
  const Result<SceneDescription> r = read_scene_string(R"(<scene version="1">
    <object name="o"><material stiffness_N_per_m="1"/><sphere radius="1"/>
      <pose quaternion_wxyz="1e-170 1e-170 0 0"/></object></scene>)", "x.xml");
  ASSERT_TRUE(r.ok()) << to_strings(r.diagnostics()).front();
  const Eigen::Matrix3d R = r->objects[0].X_WO.linear();
  EXPECT_TRUE((R.transpose() * R).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
  EXPECT_TRUE((R * Eigen::Vector3d::UnitY()).isApprox(Eigen::Vector3d::UnitZ(), 1e-12));
}

TEST_F(SceneXmlReader, StringDefaultsAndSceneNameFromStem) {
  const Result<SceneDescription> r = read_scene_string(R"(<?xml version="1.0"?>
<!-- comments are fine -->
<scene version="1">
  <object name="ball"><material stiffness_N_per_m="1000"/><sphere radius="0.1"/></object>
</scene>
)", "somewhere/my_scene.xml");
  ASSERT_TRUE(r.ok());
  const SceneDescription& s = *r;
  EXPECT_EQ(s.name, "my_scene");
  EXPECT_EQ(s.file, fs::path("somewhere/my_scene.xml"));
  EXPECT_FALSE(s.haptics.max_force_N) << "absent: the device's limit";
  EXPECT_DOUBLE_EQ(s.haptics.update_rate_Hz, HapticsSettings{}.update_rate_Hz);
  ASSERT_EQ(s.objects.size(), 1u);
  const auto& sphere = std::get<SphereSource>(s.objects[0].shape);
  EXPECT_DOUBLE_EQ(sphere.radius_m, 0.1);
  EXPECT_EQ(sphere.subdivisions, 4);
  EXPECT_TRUE(s.objects[0].X_WO.isApprox(Pose::Identity()));
  const HapticMaterial defaults;
  expect_material(s.objects[0].material, 1000, defaults.damping_Ns_per_m, defaults.static_friction,
                  defaults.dynamic_friction, defaults.force_shading);
  EXPECT_EQ(s.objects[0].where.file, "somewhere/my_scene.xml");
  EXPECT_EQ(s.objects[0].where.line, 4);
  EXPECT_TRUE(s.rig_frames.empty());
  EXPECT_TRUE(s.plugins.empty());
}

TEST_F(SceneXmlReader, StringResolvesPathsAgainstTheGivenFile) {
  const Result<SceneDescription> r = read_scene_string(R"(<scene version="1" unit="mm">
  <include file="common/materials.xml"/>
  <object name="t" material="skin"><mesh file="assets/tetrahedron.ply"/></object>
</scene>)", "tests/data/scenes/valid/not_on_disk.xml");
  ASSERT_TRUE(r.ok()) << to_strings(r.diagnostics()).front();
  const auto& mesh = std::get<MeshSource>(r->objects[0].shape);
  EXPECT_EQ(mesh.file, (test::kSourceDir / "tests/data/scenes/valid/assets/tetrahedron.ply").lexically_normal());
  expect_vec(mesh.scale_to_m, {0.001, 0.001, 0.001});
}

TEST_F(SceneXmlReader, AbsoluteIncludePath) {
  const std::string materials =
      (test::kSourceDir / "tests/data/scenes/valid/common/materials.xml").string();
  const Result<SceneDescription> r = read_scene_string(
      "<scene version=\"1\"><include file=\"" + materials + "\"/></scene>", "/tmp/x.xml");
  ASSERT_TRUE(r.ok()) << to_strings(r.diagnostics()).front();
  EXPECT_EQ(r->materials.size(), 2u);
}

TEST_F(SceneXmlReader, LenientNumberSyntaxThatXmlSchemaAlsoAccepts) {
  const Result<SceneDescription> r = read_scene_string(R"(<scene version=" 1 " unit=" mm ">
  <object name="c"><material stiffness_N_per_m=" +1e3 " force_shading=" false "/>
    <cylinder radius=".5" height="2." segments="+8"/>
    <pose position="
      1   2
      3"/></object></scene>)", "x.xml");
  ASSERT_TRUE(r.ok()) << to_strings(r.diagnostics()).front();
  const auto& c = std::get<CylinderSource>(r->objects[0].shape);
  EXPECT_DOUBLE_EQ(c.radius_m, 0.0005);
  EXPECT_DOUBLE_EQ(c.height_m, 0.002);
  EXPECT_EQ(c.segments, 8);
  EXPECT_DOUBLE_EQ(r->objects[0].material.stiffness_N_per_m, 1000.0);
  expect_vec(r->objects[0].X_WO.translation(), {0.001, 0.002, 0.003});
}

// --- errors that need no file of their own ------------------------------------------

TEST_F(SceneXmlReader, StringMalformedXmlAndEmptyDocument) {
  EXPECT_EQ(errors_of("<scene version=\"1\">\n  <object name=x/>\n</scene>"),
            (Lines{at(2, "malformed XML: bad attribute in <object> (values need quotes, names "
                         "must be unique within an element)")}));
  EXPECT_EQ(errors_of(""), (Lines{"mem/scene.xml: error: malformed XML: the document is empty"}));
}

TEST_F(SceneXmlReader, StringRootElementChecks) {
  EXPECT_EQ(errors_of("<world version=\"1\"/>"),
            (Lines{at(1, "root element must be <scene>, found <world>")}));
  EXPECT_EQ(errors_of("<scene version=\"1\"/>\n<scene version=\"1\"/>"),
            (Lines{at(2, "unexpected element <scene> after the root element")}));
  EXPECT_EQ(errors_of("<scene version=\"2\"><anything/></scene>"),
            (Lines{at(1, "unsupported scene version '2' (this reader reads version 1)")}));
  EXPECT_EQ(errors_of("<scene version=\"1\" unit=\"cm\" name=\"\"/>"),
            (Lines{at(1, "attribute 'name' on <scene> must not be empty"),
                   at(1, "invalid unit 'cm' on <scene> (expected m or mm)")}));
}

TEST_F(SceneXmlReader, StringObjectStructureErrors) {
  EXPECT_EQ(errors_of(R"(<scene version="1">
  <object name="a"><material stiffness_N_per_m="1"/></object>
  <object name="b"><sphere radius="1"/></object>
  <object name="c" material="m"><material stiffness_N_per_m="1"/><sphere radius="1"/></object>
  <object><material stiffness_N_per_m="1" name="x"/><sphere radius="1"/></object>
  <object name="e"><material stiffness_N_per_m="1"/><sphere radius="1"/>
    <scale value="2"/><pose/><pose/></object>
  <object name="f"><material stiffness_N_per_m="1"/><mesh file="../tests/data/scenes/valid/assets/tetrahedron.ply"/>
    <scale value="2" xyz="1 1 1"/></object>
  <material name="m" stiffness_N_per_m="1"/>
  <object name="g">text<material stiffness_N_per_m="1"><sphere radius="1"/></material></object>
</scene>)"),
            (Lines{at(2, "object 'a' has no shape (expected <mesh>, <plane>, <sphere>, <box>, <cylinder> or <capsule>)"),
                   at(3, "object 'b' has no material (set material=\"NAME\" or add an inline <material>)"),
                   at(4, "object 'c' has both material=\"m\" and an inline <material>"),
                   at(5, "missing required attribute 'name' on <object>"),
                   at(5, "an inline <material> takes no name (define named materials in <scene>)"),
                   at(7, "object 'e' has more than one <pose> (the first is at line 7)"),
                   at(7, "<scale> applies to mesh objects only; object 'e' is a <sphere>"),
                   at(9, "<scale> needs exactly one of 'value' or 'xyz'"),
                   at(11, "unexpected text in <object>"),
                   at(11, "unknown element <sphere> in <material>"),
                   at(11, "object 'g' has no shape (expected <mesh>, <plane>, <sphere>, <box>, <cylinder> or <capsule>)")}));
}

TEST_F(SceneXmlReader, StringAttributeValueErrors) {
  EXPECT_EQ(errors_of(R"(<scene version="1">
  <haptics max_force_N="0" update_rate_Hz="1e999"/>
  <haptics/>
  <material name="m" damping_Ns_per_m="-1" force_shading="yes"/>
  <object name="s" material="m"><sphere radius="1" subdivisions="8"/></object>
  <object name="t" material="m"><sphere radius="1" subdivisions="4.5"/></object>
  <object name="u" material="m"><cylinder radius="1" height="1" segments="2"/></object>
  <object name="v" material="m"><box size="1 -1 1"/>
    <pose rpy_deg="0 0 0" quaternion_wxyz="1 0 0 0"/></object>
  <object name="w" material="m"><plane size="1 1"/><pose quaternion_wxyz="0 0 0 0"/></object>
</scene>)"),
            (Lines{at(2, "attribute 'max_force_N' on <haptics> must be > 0, got 0"),
                   at(2, "number '1e999' for attribute 'update_rate_Hz' on <haptics> is out of range"),
                   at(3, "duplicate <haptics> (first defined at mem/scene.xml:2)"),
                   at(4, "missing required attribute 'stiffness_N_per_m' on <material>"),
                   at(4, "attribute 'damping_Ns_per_m' on <material> must be >= 0, got -1"),
                   at(4, "invalid boolean 'yes' for attribute 'force_shading' on <material> (expected true or false)"),
                   at(5, "attribute 'subdivisions' on <sphere> must be in [0, 7], got 8"),
                   at(6, "invalid integer '4.5' for attribute 'subdivisions' on <sphere>"),
                   at(7, "attribute 'segments' on <cylinder> must be in [3, 4096], got 2"),
                   at(8, "attribute 'size' on <box> must be > 0, got -1"),
                   at(9, "<pose> takes rpy_deg or quaternion_wxyz, not both"),
                   at(10, "attribute 'quaternion_wxyz' on <pose> must not be all zeros")}));
}

TEST_F(SceneXmlReader, ShadingCreaseAngleIsReadInDegreesAndDefaultsToSixty) {
  const Result<SceneDescription> r = read_scene_string(R"(<scene version="1">
  <material name="m" stiffness_N_per_m="1" force_shading="true" shading_crease_deg="45"/>
  <object name="a" material="m"><sphere radius="1"/></object>
  <object name="b"><material stiffness_N_per_m="1" force_shading="true"/><sphere radius="1"/></object>
  <object name="c"><material stiffness_N_per_m="1" shading_crease_deg=" 180 "/><sphere radius="1"/></object>
</scene>)", "x.xml");
  ASSERT_TRUE(r.ok()) << to_strings(r.diagnostics()).front();
  const double deg = 3.14159265358979323846 / 180.0;
  EXPECT_DOUBLE_EQ(r->objects[0].material.force_shading_crease_rad, 45 * deg);
  EXPECT_DOUBLE_EQ(r->objects[1].material.force_shading_crease_rad, 60 * deg);
  EXPECT_DOUBLE_EQ(r->objects[2].material.force_shading_crease_rad, 180 * deg);
}

TEST_F(SceneXmlReader, ShadingCreaseAngleOutsideZeroToHundredEightyDegreesIsRefused) {
  EXPECT_EQ(errors_of(R"(<scene version="1">
  <material name="a" stiffness_N_per_m="1" force_shading="true" shading_crease_deg="-1"/>
  <material name="b" stiffness_N_per_m="1" force_shading="true" shading_crease_deg="181"/>
  <material name="c" stiffness_N_per_m="1" force_shading="true" shading_crease_deg="nan"/>
  <object name="d"><material stiffness_N_per_m="1" shading_crease_deg="sixty"/><sphere radius="1"/></object>
</scene>)"),
            (Lines{at(2, "attribute 'shading_crease_deg' on <material> must be >= 0, got -1"),
                   at(3, "attribute 'shading_crease_deg' on <material> must not exceed 180 (the widest angle two "
                            "normals make), got 181"),
                   at(4, "non-finite number 'nan' for attribute 'shading_crease_deg' on <material>"),
                   at(5, "invalid number 'sixty' for attribute 'shading_crease_deg' on <material>")}));
}

TEST_F(SceneXmlReader, StringIncludeRigAndPluginErrors) {
  EXPECT_EQ(errors_of(R"(<scene version="1">
  <include file="nope.xml"/>
  <rig unit="mm"><frame name="world" parent="world"/><frame name="f"/><object/></rig>
  <plugins><plugin kind="device" name="d"><param name="p" value="1"/><param name="p" value="2"/>
    <param value="3"/></plugin><frame/></plugins>
</scene>)"),
            (Lines{at(2, "included file 'nope.xml' not found (resolved to 'mem/nope.xml')"),
                   at(3, "unknown attribute 'unit' on <rig>"),
                   at(3, "frame name 'world' is reserved"),
                   at(3, "missing required attribute 'parent' on <frame>"),
                   at(3, "unknown element <object> in <rig>"),
                   at(4, "duplicate param 'p' in plugin 'd' (the first is at line 4)"),
                   at(5, "missing required attribute 'name' on <param>"),
                   at(5, "unknown element <frame> in <plugins>")}));
}

TEST_F(SceneXmlReader, ParamBlocksForTheUserThePlannerAndTheServer) {
  const Result<SceneDescription> r = read_scene_string(R"(<scene version="1">
  <simulated_user>
    <param name="seed" value="7"/>
  </simulated_user>
  <planner kind="predictive">
    <param name="max_linear_speed_mps" value="0.3"/>
    <param name="step_angle_deg" value="20"/>
  </planner>
  <server/>
</scene>)", "mem/scene.xml");
  ASSERT_TRUE(r.ok()) << ::testing::PrintToString(to_strings(r.diagnostics()));
  const SceneDescription& s = *r;
  ASSERT_TRUE(s.simulated_user);
  EXPECT_EQ(s.simulated_user->params, (std::map<std::string, std::string>{{"seed", "7"}}));
  EXPECT_EQ(s.simulated_user->param_where.at("seed").line, 3);
  EXPECT_EQ(s.simulated_user->where.line, 2);
  ASSERT_TRUE(s.planner);
  EXPECT_EQ(s.planner->kind, "predictive");
  EXPECT_EQ(s.planner->params.size(), 2u);
  EXPECT_EQ(s.planner->param_where.at("step_angle_deg").line, 7);
  ASSERT_TRUE(s.server);
  EXPECT_TRUE(s.server->params.empty());
}

TEST_F(SceneXmlReader, DoubleHyphenInsideACommentIsRefusedAsXmlDoes) {
  EXPECT_EQ(errors_of(R"(<!-- top level -- here -->
<scene version="1">
  <!-- run it with
       mhd run --duration 5 -->
  <!-- fine - single hyphens -->
  <!-- ends in a hyphen--->
</scene>)"),
            (Lines{at(1, "malformed XML: '--' inside a comment (XML forbids it; write '-' or reword)"),
                   at(4, "malformed XML: '--' inside a comment (XML forbids it; write '-' or reword)"),
                   at(6, "malformed XML: '--' inside a comment (XML forbids it; write '-' or reword)")}));
}

TEST_F(SceneXmlReader, ParamBlockErrors) {
  EXPECT_EQ(errors_of(R"(<scene version="1">
  <planner>
    <param name="a" value="1"/>
    <param name="a" value="2"/>
  </planner>
  <server colour="red"/>
  <server/>
</scene>)"),
            (Lines{at(2, "missing required attribute 'kind' on <planner>"),
                   at(4, "duplicate param 'a' in <planner> (the first is at line 3)"),
                   at(6, "unknown attribute 'colour' on <server>"),
                   at(7, "second <server> (the first is at mem/scene.xml:6)")}));
}

TEST_F(SceneXmlReader, MissingRootFile) {
  const Result<SceneDescription> r = read_scene_file("tests/data/scenes/no_such_scene.xml");
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(to_strings(r.diagnostics()),
            (Lines{"tests/data/scenes/no_such_scene.xml: error: scene file not found"}));
  const Result<SceneDescription> dir = read_scene_file("tests/data/scenes");
  EXPECT_EQ(to_strings(dir.diagnostics()),
            (Lines{"tests/data/scenes: error: scene file is not a regular file"}));
}

}  // namespace
}  // namespace mhd

namespace mhd {
namespace {

// --- exact primitives ------------------------------------------------------------------

TEST(SceneXmlExactPrimitives, ExactIsReadOnEveryPrimitiveAndTheCapsuleIsExactByDefault) {
  const Result<SceneDescription> r = read_scene_string(R"(<scene version="1" unit="mm"><material name="m" stiffness_N_per_m="1000"/>
  <object material="m" name="p"><plane size="100 200" exact="true"/></object>
  <object material="m" name="s"><sphere radius="10" exact="true"/></object>
  <object material="m" name="s2"><sphere radius="10"/></object>
  <object material="m" name="b"><box size="1 2 3" exact="false"/></object>
  <object material="m" name="c"><cylinder radius="5" height="8" exact="true"/></object>
  <object material="m" name="k"><capsule radius="5" length="40" segments="16"/></object>
  <object material="m" name="k2"><capsule radius="5" length="40" exact="false"/></object></scene>)", "x.xml");
  ASSERT_TRUE(r.ok()) << test::to_strings(r.diagnostics()).front();
  const auto& o = r->objects;
  EXPECT_TRUE(std::get<PlaneSource>(o[0].shape).exact);
  EXPECT_TRUE(std::get<SphereSource>(o[1].shape).exact);
  EXPECT_FALSE(std::get<SphereSource>(o[2].shape).exact);
  EXPECT_FALSE(std::get<BoxSource>(o[3].shape).exact);
  EXPECT_TRUE(std::get<CylinderSource>(o[4].shape).exact);
  const auto& k = std::get<CapsuleSource>(o[5].shape);
  EXPECT_TRUE(k.exact);
  EXPECT_DOUBLE_EQ(k.radius_m, 0.005);
  EXPECT_DOUBLE_EQ(k.length_m, 0.04);
  EXPECT_EQ(k.segments, 16);
  EXPECT_FALSE(std::get<CapsuleSource>(o[6].shape).exact);
}

TEST(SceneXmlExactPrimitives, ABadExactOrCapsuleIsRefusedAndAGoodOneAccepted) {
  EXPECT_TRUE(read_scene_string(R"(<scene version="1"><material name="m" stiffness_N_per_m="1000"/><object material="m" name="k"><capsule radius="1" length="1" exact="true"/></object></scene>)",
                                "x.xml").ok());
  EXPECT_FALSE(read_scene_string(R"(<scene version="1"><material name="m" stiffness_N_per_m="1000"/><object material="m" name="s"><sphere radius="1" exact="maybe"/></object></scene>)",
                                 "x.xml").ok());
  EXPECT_FALSE(read_scene_string(R"(<scene version="1"><material name="m" stiffness_N_per_m="1000"/><object material="m" name="k"><capsule radius="1"/></object></scene>)",
                                 "x.xml").ok());
  EXPECT_FALSE(read_scene_string(R"(<scene version="1"><material name="m" stiffness_N_per_m="1000"/><object material="m" name="k"><capsule radius="-1" length="1"/></object></scene>)",
                                 "x.xml").ok());
}

}  // namespace
}  // namespace mhd
