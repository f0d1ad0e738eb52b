// <texture> in a material: what the reader makes of each kind, and the exact message,
// at file:line, for each bad value.

#include "scene_test_support.h"
#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mhd {
namespace {

using test::to_strings;
using Lines = std::vector<std::string>;

// Relative image files resolve against this file's folder, which holds the test images.
const std::string kFile = "tests/data/textures/scene.xml";

/// A scene with a named material whose <texture> is `texture_line`, on line 3.
std::string scene_with(const std::string& texture_line) {
  return "<scene version=\"1\">\n"
         "  <material name=\"m\" stiffness_N_per_m=\"1000\" static_friction=\"0.5\" dynamic_friction=\"0.4\">\n"
         "    " + texture_line + "\n"
         "  </material>\n"
         "  <object name=\"o\" material=\"m\"><box size=\"1 1 1\"/></object>\n"
         "</scene>\n";
}

class TextureReader : public test::FromSourceRoot {
 protected:
  static HapticTextureSpec spec_of(const std::string& texture_line) {
    const Result<SceneDescription> r = read_scene_string(scene_with(texture_line), kFile);
    EXPECT_TRUE(r.ok()) << ::testing::PrintToString(to_strings(r.diagnostics()));
    if (!r.ok() || !r->objects[0].material.texture_spec) return {};
    EXPECT_EQ(r->materials.at("m").texture_spec.has_value(), true);
    return *r->objects[0].material.texture_spec;
  }
  static Lines errors_of(const std::string& texture_line) {
    const Result<SceneDescription> r = read_scene_string(scene_with(texture_line), kFile);
    EXPECT_FALSE(r.ok());
    return to_strings(r.diagnostics());
  }
  static std::string at(int line, const std::string& message) {
    return kFile + ":" + std::to_string(line) + ": error: " + message;
  }
};

TEST_F(TextureReader, GratingTakesPeriodDepthDirectionProjectionAndFrictionContrast) {
  const HapticTextureSpec s = spec_of(
      "<texture kind=\"grating\" depth_m=\"0.0002\" period_m=\"0.002\" direction=\"0 2\" projection=\"zx\" "
      "friction_contrast=\"0.25\"/>");
  EXPECT_EQ(s.kind, TextureKind::Grating);
  EXPECT_EQ(s.depth_m, 0.0002);
  EXPECT_EQ(s.period_m, 0.002);
  EXPECT_EQ(s.direction_uv, Eigen::Vector2d(0, 2));
  EXPECT_EQ(s.projection, TextureProjection::Zx);
  EXPECT_EQ(s.friction_contrast, 0.25);
}

TEST_F(TextureReader, NoiseTakesItsBandAndSeedAndDefaultsTheLongestWavelength) {
  const HapticTextureSpec s = spec_of("<texture kind=\"noise\" depth_m=\"0.0003\" period_m=\"0.001\" seed=\"99\"/>");
  EXPECT_EQ(s.kind, TextureKind::Noise);
  EXPECT_EQ(s.seed, 99U);
  EXPECT_EQ(s.max_period_m, 4 * s.period_m);
  EXPECT_EQ(s.projection, TextureProjection::Xy);
  const HapticTextureSpec t =
      spec_of("<texture kind=\"noise\" depth_m=\"0.0003\" period_m=\"0.001\" max_period_m=\"0.01\"/>");
  EXPECT_EQ(t.max_period_m, 0.01);
}

TEST_F(TextureReader, ImageResolvesItsFileAgainstTheSceneFile) {
  const HapticTextureSpec s =
      spec_of("<texture kind=\"image\" depth_m=\"0.0005\" file=\"four_by_two.png\" size_m=\"0.008 0.004\"/>");
  EXPECT_EQ(s.kind, TextureKind::HeightMap);
  EXPECT_EQ(s.image_file, (test::kSourceDir / "tests/data/textures/four_by_two.png").lexically_normal());
  EXPECT_EQ(s.image_size_m, Eigen::Vector2d(0.008, 0.004));
}

TEST_F(TextureReader, AnInlineMaterialTakesATextureToo) {
  const std::string xml =
      "<scene version=\"1\">\n"
      "  <object name=\"o\"><box size=\"1 1 1\"/>\n"
      "    <material stiffness_N_per_m=\"1000\"><texture kind=\"grating\" depth_m=\"0.0001\" period_m=\"0.003\"/></material>\n"
      "  </object>\n"
      "</scene>\n";
  const Result<SceneDescription> r = read_scene_string(xml, kFile);
  ASSERT_TRUE(r.ok()) << ::testing::PrintToString(to_strings(r.diagnostics()));
  ASSERT_TRUE(r->objects[0].material.texture_spec.has_value());
  EXPECT_EQ(r->objects[0].material.texture_spec->period_m, 0.003);
}

TEST_F(TextureReader, BadValuesAreRefusedAtTheirLine) {
  EXPECT_EQ(errors_of("<texture kind=\"knit\" depth_m=\"0.0001\"/>"),
            (Lines{at(3, "unknown texture kind 'knit' (expected grating, noise or image)")}));
  EXPECT_EQ(errors_of("<texture kind=\"grating\" depth_m=\"0.01\" period_m=\"0.002\"/>"),
            (Lines{at(3, "attribute 'depth_m' on <texture> must not exceed 0.005 m (deeper relief is a shape: "
                         "model it as geometry), got 0.01")}));
  EXPECT_EQ(errors_of("<texture kind=\"grating\" depth_m=\"0.0001\" period_m=\"0.00001\"/>"),
            (Lines{at(3, "attribute 'period_m' on <texture> must be within [0.0001, 1] m, got 1e-05")}));
  EXPECT_EQ(errors_of("<texture kind=\"grating\" depth_m=\"0.0001\" period_m=\"0.002\" direction=\"0 0\"/>"),
            (Lines{at(3, "attribute 'direction' on <texture> must not be \"0 0\"")}));
  EXPECT_EQ(errors_of("<texture kind=\"grating\" depth_m=\"0.0001\" period_m=\"0.002\" seed=\"3\"/>"),
            (Lines{at(3, "attribute 'seed' on <texture> applies to kind noise only, not to kind grating")}));
  EXPECT_EQ(errors_of("<texture kind=\"noise\" depth_m=\"0.0001\" period_m=\"0.002\" max_period_m=\"0.001\"/>"),
            (Lines{at(3, "attribute 'max_period_m' on <texture> must not be below period_m (0.002), got 0.001")}));
  EXPECT_EQ(errors_of("<texture kind=\"grating\" depth_m=\"0.0001\" period_m=\"0.002\" friction_contrast=\"1.5\"/>"),
            (Lines{at(3, "attribute 'friction_contrast' on <texture> must not exceed 1 (friction stays >= 0), got 1.5")}));
  EXPECT_EQ(errors_of("<texture kind=\"grating\" depth_m=\"0.0001\" period_m=\"0.002\" projection=\"xz\"/>"),
            (Lines{at(3, "attribute 'projection' on <texture> must be xy, yz or zx (the object-frame plane the texture "
                         "is projected onto), got 'xz'")}));
  EXPECT_EQ(errors_of("<texture kind=\"image\" depth_m=\"0.0001\" period_m=\"0.002\" file=\"four_by_two.png\" "
                      "size_m=\"0.01 0.01\"/>"),
            (Lines{at(3, "attribute 'period_m' on <texture> applies to kind grating or noise only, not to kind image")}));
  const std::string missing = (test::kSourceDir / "tests/data/textures/no_such.png").lexically_normal().string();
  EXPECT_EQ(errors_of("<texture kind=\"image\" depth_m=\"0.0001\" file=\"no_such.png\" size_m=\"0.01 0.01\"/>"),
            (Lines{at(3, "texture image 'no_such.png' not found (resolved to '" + missing + "')")}));
}

TEST_F(TextureReader, MissingAttributesAndChildrenAreRefused) {
  EXPECT_EQ(errors_of("<texture kind=\"grating\" period_m=\"0.002\"/>"),
            (Lines{at(3, "missing required attribute 'depth_m' on <texture>")}));
  EXPECT_EQ(errors_of("<texture kind=\"image\" depth_m=\"0.0001\" file=\"four_by_two.png\"/>"),
            (Lines{at(3, "missing required attribute 'size_m' on <texture>")}));
  EXPECT_EQ(errors_of("<texture kind=\"grating\" depth_m=\"0.0001\" period_m=\"0.002\"><bump/></texture>"),
            (Lines{at(3, "unknown element <bump> in <texture>")}));
  EXPECT_EQ(errors_of("<texture kind=\"grating\" depth_m=\"0.0001\" period_m=\"0.002\"/><texture kind=\"noise\" "
                      "depth_m=\"0.0001\" period_m=\"0.002\"/>"),
            (Lines{at(3, "<material> has more than one <texture> (the first is at line 3)")}));
}

}  // namespace
}  // namespace mhd
