// One file per failure under tests/data/scenes/malformed/, each checked for the exact,
// complete list of diagnostics the reader gives (file:line: error: message).

#include "scene_test_support.h"
#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace mhd {
namespace {

using test::to_strings;
using Lines = std::vector<std::string>;

const std::string kDir = "tests/data/scenes/malformed/";

class SceneXmlMalformed : public test::FromSourceRoot {
 protected:
  /// Reads kDir + name and returns its diagnostics; the scene must be refused.
  static Lines errors_of(const std::string& name) {
    const Result<SceneDescription> result = read_scene_file(kDir + name);
    EXPECT_FALSE(result.ok()) << name << " was accepted";
    EXPECT_FALSE(result.ok());
    return to_strings(result.diagnostics());
  }
  static std::string at(const std::string& name, int line, const std::string& message) {
    return kDir + name + ":" + std::to_string(line) + ": error: " + message;
  }
};

TEST_F(SceneXmlMalformed, MalformedXmlGivesTinyxmlLine) {
  EXPECT_EQ(errors_of("malformed_xml.xml"),
            (Lines{at("malformed_xml.xml", 3, "malformed XML: <object> has no matching end tag")}));
}

TEST_F(SceneXmlMalformed, UnknownElementsNameTheirParent) {
  EXPECT_EQ(errors_of("unknown_element.xml"),
            (Lines{at("unknown_element.xml", 3, "unknown element <lights> in <scene>"),
                   at("unknown_element.xml", 7, "unknown element <colour> in <object>")}));
}

TEST_F(SceneXmlMalformed, UnknownAttributeGivesTheAttributesLine) {
  EXPECT_EQ(errors_of("unknown_attribute.xml"),
            (Lines{at("unknown_attribute.xml", 4, "unknown attribute 'colour' on <material>")}));
}

TEST_F(SceneXmlMalformed, MissingMeshFile) {
  const std::string resolved =
      (test::kSourceDir / "tests/data/scenes/malformed/no_such_mesh.ply").lexically_normal().string();
  EXPECT_EQ(errors_of("missing_mesh.xml"),
            (Lines{at("missing_mesh.xml", 5,
                      "mesh file 'no_such_mesh.ply' not found (resolved to '" + resolved + "')")}));
}

TEST_F(SceneXmlMalformed, NanAndInfAreBothReported) {
  EXPECT_EQ(errors_of("non_finite.xml"),
            (Lines{at("non_finite.xml", 5, "non-finite number 'nan' for attribute 'radius' on <sphere>"),
                   at("non_finite.xml", 6, "non-finite number 'inf' for attribute 'position' on <pose>")}));
}

TEST_F(SceneXmlMalformed, NegativeStiffness) {
  EXPECT_EQ(errors_of("negative_stiffness.xml"),
            (Lines{at("negative_stiffness.xml", 3,
                      "attribute 'stiffness_N_per_m' on <material> must be > 0, got -800")}));
}

TEST_F(SceneXmlMalformed, ZeroScale) {
  EXPECT_EQ(errors_of("zero_scale.xml"),
            (Lines{at("zero_scale.xml", 6, "attribute 'value' on <scale> must be > 0, got 0")}));
}

TEST_F(SceneXmlMalformed, AbsurdScaleCountsTheUnit) {
  // unit mm (0.001) times 1e-5 is 1e-8 m per mesh unit on z.
  EXPECT_EQ(errors_of("absurd_scale.xml"),
            (Lines{at("absurd_scale.xml", 6,
                      "absurd scale: unit times scale is (0.001 0.001 1e-08) metres per mesh unit, "
                      "outside [1e-06, 1e+06]")}));
}

TEST_F(SceneXmlMalformed, IncludeCycleNamesTheChain) {
  EXPECT_EQ(errors_of("include_cycle_a.xml"),
            (Lines{at("include_cycle_b.xml", 4,
                      "include cycle: " + kDir + "include_cycle_a.xml -> " + kDir +
                          "include_cycle_b.xml -> " + kDir + "include_cycle_a.xml")}));
}

TEST_F(SceneXmlMalformed, DuplicateNamesAcrossIncludes) {
  const std::string main = kDir + "duplicate_names.xml";
  EXPECT_EQ(errors_of("duplicate_names.xml"),
            (Lines{at("duplicate_names_part.xml", 4,
                      "duplicate material name 'skin' (first defined at " + main + ":3)"),
                   at("duplicate_names.xml", 8,
                      "duplicate object name 'ball' (first defined at " + main + ":5)"),
                   at("duplicate_names.xml", 13,
                      "duplicate frame name 'tracker' (first defined at " + main + ":12)")}));
}

TEST_F(SceneXmlMalformed, UnknownMaterialReference) {
  EXPECT_EQ(errors_of("unknown_material.xml"),
            (Lines{at("unknown_material.xml", 4, "object 'ball' uses unknown material 'skn'")}));
}

TEST_F(SceneXmlMalformed, TrailingJunkInANumber) {
  EXPECT_EQ(errors_of("trailing_junk.xml"),
            (Lines{at("trailing_junk.xml", 5,
                      "invalid number '1.5abc' for attribute 'radius' on <sphere>")}));
}

TEST_F(SceneXmlMalformed, WrongVectorArity) {
  EXPECT_EQ(errors_of("wrong_arity.xml"),
            (Lines{at("wrong_arity.xml", 5, "attribute 'size' on <plane> needs 2 numbers, got 3"),
                   at("wrong_arity.xml", 6, "attribute 'position' on <pose> needs 3 numbers, got 2"),
                   at("wrong_arity.xml", 9,
                      "attribute 'quaternion_wxyz' on <frame> needs 4 numbers, got 3")}));
}

TEST_F(SceneXmlMalformed, TwoShapes) {
  EXPECT_EQ(errors_of("two_shapes.xml"),
            (Lines{at("two_shapes.xml", 6,
                      "object 'ball' has more than one shape: <box> after <sphere> at line 5")}));
}

TEST_F(SceneXmlMalformed, MissingVersion) {
  EXPECT_EQ(errors_of("missing_version.xml"),
            (Lines{at("missing_version.xml", 2, "missing required attribute 'version' on <scene>")}));
}

TEST_F(SceneXmlMalformed, DynamicFrictionAboveStatic) {
  EXPECT_EQ(errors_of("dynamic_friction.xml"),
            (Lines{at("dynamic_friction.xml", 3,
                      "dynamic_friction (0.3) must not exceed static_friction (0.1) on <material>")}));
}

TEST_F(SceneXmlMalformed, UnknownPluginKind) {
  EXPECT_EQ(errors_of("unknown_plugin_kind.xml"),
            (Lines{at("unknown_plugin_kind.xml", 4,
                      "unknown plugin kind 'joystick' (expected device, tracker, base, display or link)")}));
}

TEST_F(SceneXmlMalformed, FrameParentCyclesAndUnknownParents) {
  EXPECT_EQ(errors_of("frame_cycle.xml"),
            (Lines{at("frame_cycle.xml", 9, "frame 'orphan' has unknown parent 'nowhere'"),
                   at("frame_cycle.xml", 5, "frame parent cycle: a -> c -> b -> a"),
                   at("frame_cycle.xml", 8, "frame parent cycle: self -> self")}));
}

TEST_F(SceneXmlMalformed, BadTexturesAreRefusedAtEachAttributesLine) {
  EXPECT_EQ(errors_of("bad_texture.xml"),
            (Lines{at("bad_texture.xml", 4, "unknown texture kind 'knit' (expected grating, noise or image)"),
                   at("bad_texture.xml", 8, "attribute 'seed' on <texture> applies to kind noise only, not to kind grating"),
                   at("bad_texture.xml", 7,
                      "attribute 'depth_m' on <texture> must not exceed 0.005 m (deeper relief is a shape: model it as "
                      "geometry), got 0.02")}));
}

TEST_F(SceneXmlMalformed, EveryMalformedFileIsCovered) {
  // A new file under malformed/ needs a test above; this list keeps the two in step.
  // (absurd_*, far_position, slow_/tiny_haptic_rate, stiffness_over_rate: plausible_settings_test.cpp)
  const std::vector<std::string> covered = {
      "absurd_crease_angle.xml", "absurd_material.xml",   "absurd_scale.xml",        "absurd_stiffness.xml",
      "bad_texture.xml",
      "duplicate_names.xml",    "duplicate_names_part.xml", "dynamic_friction.xml",
      "far_position.xml",       "frame_cycle.xml",         "include_cycle_a.xml",
      "include_cycle_b.xml",    "malformed_xml.xml",       "missing_mesh.xml",
      "missing_version.xml",    "negative_stiffness.xml",  "non_finite.xml",
      "slow_haptic_rate.xml",   "stiffness_over_rate.xml", "tiny_haptic_rate.xml",
      "trailing_junk.xml",      "two_shapes.xml",          "unknown_attribute.xml",
      "unknown_element.xml",    "unknown_material.xml",    "unknown_plugin_kind.xml",
      "wrong_arity.xml",        "zero_scale.xml"};
  std::vector<std::string> present;
  for (const auto& entry : std::filesystem::directory_iterator(kDir)) {
    present.push_back(entry.path().filename().string());
  }
  std::sort(present.begin(), present.end());
  EXPECT_EQ(present, covered);
}

}  // namespace
}  // namespace mhd
