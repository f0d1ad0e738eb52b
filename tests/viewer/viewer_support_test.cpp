// Options, material colours, PNG files and OSG geometry from meshes.

#include "geometry/primitive_mesh.h"
#include "viewer/png_image.h"
#include "viewer/scene_colours.h"
#include "viewer/scene_graph.h"
#include "viewer/viewer_options.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

namespace mhd::viewer {
namespace {

std::filesystem::path scratch(const char* name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mhd_viewer_tests";
  std::filesystem::create_directories(dir);
  return dir / name;
}

TEST(ViewerOptions, DefaultsAreUsableAndEachBadValueIsNamed) {
  EXPECT_EQ(ViewerOptions{}.check(), "");
  ViewerOptions o;
  o.ipd_m = 0.5;
  EXPECT_EQ(o.check(), "ipd_m must be in [0, 0.2], got 0.5");
  o = {};
  o.fov_deg = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(o.check(), "fov_deg must be in [10, 170], got nan");
  o = {};
  o.width = 8;
  EXPECT_EQ(o.check(), "image size must be 16..16384 pixels per side, got 8x800");
  o = {};
  o.screenshot_png = "x.png";
  EXPECT_EQ(o.check(), "a screenshot needs frames >= 1");
  o.frames = 3;
  EXPECT_EQ(o.check(), "");
  EXPECT_EQ(o.eye_width(), 800);
  o.stereo = false;
  EXPECT_EQ(o.eye_width(), 1600);
}

TEST(MaterialColour, SharedMaterialsAreFixedOthersStableAndDistinct) {
  const Eigen::Vector4f skin = material_colour("dolphin_skin", "dolphin");
  EXPECT_FLOAT_EQ(skin.x(), 0.42f);
  EXPECT_FLOAT_EQ(skin.w(), 1.0f);
  EXPECT_EQ(material_colour("my_metal", "a"), material_colour("my_metal", "b")) << "the material decides";
  EXPECT_EQ(material_colour("", "table"), material_colour("table", "other")) << "inline: the object's name";
  EXPECT_NE(material_colour("my_metal", ""), material_colour("my_wood", ""));
  for (const char* name : {"a", "b", "zzz", "table"}) {
    const Eigen::Vector4f c = material_colour(name, "");
    EXPECT_GE(c.head<3>().minCoeff(), 0.35f);
    EXPECT_LE(c.head<3>().maxCoeff(), 0.85f);
  }
}

TEST(PngImage, RoundTripsPixelsExactly) {
  RgbaImage image;
  image.width = 5;
  image.height = 3;
  for (int i = 0; i < 15; ++i) {
    for (int c = 0; c < 4; ++c) image.rgba.push_back(static_cast<std::uint8_t>(i * 16 + c * 3));
  }
  const std::filesystem::path file = scratch("roundtrip.png");
  ASSERT_EQ(write_png(file, image), "");
  RgbaImage back;
  ASSERT_EQ(read_png(file, back), "");
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.rgba, image.rgba);
  EXPECT_EQ(back.pixel(4, 2)[0], 14 * 16);
}

TEST(PngImage, ErrorsNameTheFile) {
  RgbaImage image;
  const std::filesystem::path text = scratch("not_a.png");
  std::ofstream(text) << "hello";
  const std::string e = read_png(text, image);
  EXPECT_NE(e.find("cannot read PNG '" + text.string() + "'"), std::string::npos) << e;
  RgbaImage wrong;
  wrong.width = 2;
  wrong.height = 2;
  EXPECT_EQ(write_png(scratch("w.png"), wrong),
            "cannot write PNG '" + scratch("w.png").string() + "': the image is 2x2 with 0 bytes");
  RgbaImage ok{1, 1, {1, 2, 3, 4}};
  EXPECT_NE(write_png("/nonexistent_dir/x.png", ok).find("cannot write PNG '/nonexistent_dir/x.png'"), std::string::npos);
}

TEST(MeshGeometry, DrawableMeshKeepsEveryTriangle) {
  const TriangleMesh box = make_box_mesh({1.0, 2.0, 3.0});
  std::string reason;
  const osg::ref_ptr<osg::Geometry> g = mesh_geometry(box, {1, 0, 0, 1}, reason);
  ASSERT_TRUE(g) << reason;
  ASSERT_EQ(g->getNumPrimitiveSets(), 1u);
  EXPECT_EQ(g->getPrimitiveSet(0)->getNumIndices(), 3 * box.triangle_count());
  EXPECT_EQ(g->getVertexArray()->getNumElements(), box.vertices_m.size());
  EXPECT_EQ(g->getNormalArray()->getNumElements(), box.vertices_m.size());
}

TEST(MeshGeometry, MeshesOsgCannotDrawSayWhy) {
  std::string reason;
  EXPECT_FALSE(mesh_geometry(TriangleMesh{}, {1, 1, 1, 1}, reason));
  EXPECT_EQ(reason, "it has no triangles");
  TriangleMesh m = make_box_mesh({1.0, 1.0, 1.0});
  m.vertices_m[3].x() = 1e300;  // beyond single precision
  EXPECT_FALSE(mesh_geometry(m, {1, 1, 1, 1}, reason));
  EXPECT_EQ(reason, "vertex 3 is not a finite single-precision point");
  m = make_box_mesh({1.0, 1.0, 1.0});
  m.triangles[0][1] = 999;
  m.vertex_normals.clear();
  EXPECT_FALSE(mesh_geometry(m, {1, 1, 1, 1}, reason));
  EXPECT_EQ(reason, "a triangle names vertex 999 of 8");
}

}  // namespace
}  // namespace mhd::viewer
