// The scene compiler builds each material's texture: procedural ones from their values,
// height maps from their PNG (read as grey in [0, 1]); what it cannot build it refuses at
// the object's line.

#include "scene_compiler/grey_png.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace mhd {
namespace {

const std::filesystem::path kSource = MHD_SOURCE_DIR;

std::filesystem::path data(const std::string& name) { return kSource / "tests/data/textures" / name; }

SceneDescription plate_with(const HapticTextureSpec& spec, int objects = 1) {
  SceneDescription d;
  d.file = "scene.xml";
  for (int i = 0; i < objects; ++i) {
    ObjectDescription o;
    o.name = "plate" + std::to_string(i);
    o.shape = BoxSource{Eigen::Vector3d(0.1, 0.1, 0.01)};
    o.material_name = "textured";
    o.material.texture_spec = spec;
    o.where = {"scene.xml", 7 + i};
    d.objects.push_back(o);
  }
  return d;
}

CompileOptions no_cache() {
  CompileOptions options;
  options.use_cache = false;
  return options;
}

HapticTextureSpec image_spec(const std::string& file) {
  HapticTextureSpec spec;
  spec.kind = TextureKind::HeightMap;
  spec.depth_m = 1e-3;
  spec.image_file = data(file);
  spec.image_size_m = {0.008, 0.004};
  return spec;
}

TEST(GreyPng, ReadsAGreyscalePngPixelForPixel) {
  GreyImage image;
  ASSERT_EQ(read_grey_png(data("four_by_two.png"), image), "");
  EXPECT_EQ(image.width, 4);
  EXPECT_EQ(image.height, 2);
  const std::vector<double> expected = {0 / 255.0, 64 / 255.0, 128 / 255.0, 1.0, 1.0, 191 / 255.0, 128 / 255.0, 0.0};
  EXPECT_EQ(image.grey, expected);
}

TEST(GreyPng, AColourPngBecomesItsLuminance) {
  GreyImage image;
  ASSERT_EQ(read_grey_png(data("colour_two_by_one.png"), image), "");
  ASSERT_EQ(image.grey.size(), 2U);
  EXPECT_GT(image.grey[0], 0.1);  // red: dark, not black
  EXPECT_LT(image.grey[0], 0.6);
  EXPECT_EQ(image.grey[1], 1.0);  // white
}

TEST(GreyPng, AFileThatIsNoPngIsRefusedAndTheImageKept) {
  GreyImage image;
  image.width = 9;
  const std::string error = read_grey_png(data("not_a_png.png"), image);
  EXPECT_EQ(error.rfind("cannot read PNG '" + data("not_a_png.png").string() + "': ", 0), 0U) << error;
  EXPECT_EQ(image.width, 9);
}

TEST(TextureCompile, AHeightMapSamplesItsImage) {
  const Result<std::unique_ptr<CompiledScene>> r = compile_scene(plate_with(image_spec("four_by_two.png")), no_cache());
  ASSERT_TRUE(r.ok());
  const auto& texture = r.value()->materials[0].texture;
  ASSERT_NE(texture, nullptr);
  // Texel (3, 0) is white: the real surface; texel (0, 0) black: 1 mm down.
  EXPECT_NEAR(texture->sample({7e-3, 1e-3}).height_m, 0.0, 1e-15);
  EXPECT_NEAR(texture->sample({1e-3, 1e-3}).height_m, -1e-3, 1e-15);
}

TEST(TextureCompile, ObjectsOfOneNamedMaterialShareOneTexture) {
  HapticTextureSpec spec;
  spec.kind = TextureKind::Noise;
  spec.depth_m = 1e-4;
  spec.period_m = 1e-3;
  spec.max_period_m = 4e-3;
  const Result<std::unique_ptr<CompiledScene>> r = compile_scene(plate_with(spec, 2), no_cache());
  ASSERT_TRUE(r.ok());
  ASSERT_NE(r.value()->materials[0].texture, nullptr);
  EXPECT_EQ(r.value()->materials[0].texture, r.value()->materials[1].texture);
}

TEST(TextureCompile, AnUnreadableImageIsRefusedAtTheObjectsLine) {
  const Result<std::unique_ptr<CompiledScene>> r = compile_scene(plate_with(image_spec("not_a_png.png")), no_cache());
  ASSERT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics().size(), 1U);
  const std::string prefix = "scene.xml:7: error: object 'plate0': texture: cannot read PNG '" +
                             data("not_a_png.png").string() + "': ";
  EXPECT_EQ(r.diagnostics()[0].to_string().rfind(prefix, 0), 0U) << r.diagnostics()[0].to_string();
}

TEST(TextureCompile, ValuesOutsideTheReadersBoundsAreRefused) {
  HapticTextureSpec spec;
  spec.kind = TextureKind::Grating;
  spec.depth_m = 1e-4;
  spec.period_m = 0.0;
  const Result<std::unique_ptr<CompiledScene>> r = compile_scene(plate_with(spec), no_cache());
  ASSERT_EQ(r.diagnostics().size(), 1U);
  EXPECT_EQ(r.diagnostics()[0].to_string(),
            "scene.xml:7: error: object 'plate0': texture: period must be within [0.0001, 1] m (got 0)");
}

TEST(TextureCompile, TheShippedTexturedPlateSceneGetsItsThreeTextures) {
  std::filesystem::current_path(kSource);
  const Result<SceneDescription> read = read_scene_file("scenes/textured_plate.xml");
  ASSERT_TRUE(read.ok());
  const Result<std::unique_ptr<CompiledScene>> r = compile_scene(*read, no_cache());
  ASSERT_TRUE(r.ok());
  int textured = 0;
  for (std::size_t i = 0; i < r.value()->materials.size(); ++i) {
    const bool has = r.value()->materials[i].texture != nullptr;
    textured += has ? 1 : 0;
    EXPECT_EQ(has, r.value()->object_names[i].find("_plate") != std::string::npos &&
                       r.value()->object_names[i] != "smooth_plate")
        << r.value()->object_names[i];
  }
  EXPECT_EQ(textured, 3);
}

}  // namespace
}  // namespace mhd
