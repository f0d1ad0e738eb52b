// <scene max_triangles>: read from the root file, checked by the compiler against each
// mesh header before loading and against every shape's triangles, over distinct shapes;
// messages name the object's file:line and the mesh file.
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"

#include "../mesh_io/test_mesh_files.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mhd {
namespace {

using test::TempDir;

std::vector<std::string> compile_errors(const std::filesystem::path& scene_file) {
  const Result<SceneDescription> read = read_scene_file(scene_file);
  std::vector<std::string> lines;
  for (const auto& d : read.diagnostics()) lines.push_back(d.to_string());
  if (!read.ok()) return lines;
  CompileOptions options;
  options.use_cache = false;
  const Result<std::unique_ptr<CompiledScene>> compiled = compile_scene(*read, options);
  for (const auto& d : compiled.diagnostics()) lines.push_back(d.to_string());
  return lines;
}

using Lines = std::vector<std::string>;

TEST(MaxTriangles, DefaultIsFiftyMillion) {
  const Result<SceneDescription> r = read_scene_string("<scene version=\"1\"/>", "x.xml");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->max_triangles, 50'000'000u);
}

TEST(MaxTriangles, HeaderAboveTheLimitIsRefusedBeforeLoading) {
  TempDir dir;
  // The header's 2 faces fit the file's size: only the limit refuses it.
  test::write_binary_ply(dir / "quad.ply", test::unit_square_mesh());
  test::write_text(dir / "scene.xml",
                   "<scene version=\"1\" max_triangles=\"1\">\n"
                   "  <material name=\"m\" stiffness_N_per_m=\"500\"/>\n"
                   "  <object name=\"quad\" material=\"m\">\n"
                   "    <mesh file=\"quad.ply\"/>\n"
                   "  </object>\n"
                   "</scene>\n");
  const std::string scene = (dir / "scene.xml").string();
  EXPECT_EQ(compile_errors(dir / "scene.xml"),
            (Lines{scene + ":3: error: object 'quad': mesh file '" + (dir / "quad.ply").string() +
                   "': the header claims 2 faces, more than max_triangles (1)"}));
}

TEST(MaxTriangles, CountsDistinctShapesAcrossTheScene) {
  TempDir dir;
  test::write_box_obj(dir / "box.obj", Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());  // 12 triangles
  // A box primitive (12) and the mesh (12) fit 30; the second use of the mesh adds none;
  // a 20-triangle sphere (subdivisions 0) does not fit the 6 left.
  test::write_text(dir / "scene.xml",
                   "<scene version=\"1\" max_triangles=\"30\">\n"
                   "  <material name=\"m\" stiffness_N_per_m=\"500\"/>\n"
                   "  <object name=\"brick\" material=\"m\"><box size=\"1 1 1\"/></object>\n"
                   "  <object name=\"a\" material=\"m\"><mesh file=\"box.obj\"/></object>\n"
                   "  <object name=\"b\" material=\"m\"><mesh file=\"box.obj\"/></object>\n"
                   "  <object name=\"ball\" material=\"m\"><sphere radius=\"1\" subdivisions=\"0\"/></object>\n"
                   "</scene>\n");
  const std::string scene = (dir / "scene.xml").string();
  EXPECT_EQ(compile_errors(dir / "scene.xml"),
            (Lines{scene + ":6: error: object 'ball': 20 triangles, more than the 6 left of max_triangles (30) "
                           "after the scene's other 24 triangles"}));
}

TEST(MaxTriangles, MeshAboveTheLimitAfterLoadingIsRefused) {
  TempDir dir;
  test::write_box_obj(dir / "box.obj", Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());  // OBJ: no count
  test::write_text(dir / "scene.xml",
                   "<scene version=\"1\" max_triangles=\"11\">\n"
                   "  <material name=\"m\" stiffness_N_per_m=\"500\"/>\n"
                   "  <object name=\"a\" material=\"m\"><mesh file=\"box.obj\"/></object>\n"
                   "</scene>\n");
  EXPECT_EQ(compile_errors(dir / "scene.xml"),
            (Lines{(dir / "scene.xml").string() + ":3: error: object 'a': mesh file '" + (dir / "box.obj").string() +
                   "': 12 triangles, more than max_triangles (11)"}));
}

TEST(MaxTriangles, OutOfRangeOrMalformedValuesAreRefused) {
  for (const auto& [value, message] : std::vector<std::pair<std::string, std::string>>{
           {"0", "x.xml:1: error: attribute 'max_triangles' on <scene> must be in [1, 1000000000], got 0"},
           {"5e7", "x.xml:1: error: invalid integer '5e7' for attribute 'max_triangles' on <scene>"},
           {"2000000000", "x.xml:1: error: attribute 'max_triangles' on <scene> must be in [1, 1000000000], got "
                          "2000000000"}}) {
    const Result<SceneDescription> r = read_scene_string("<scene version=\"1\" max_triangles=\"" + value + "\"/>", "x.xml");
    ASSERT_EQ(r.diagnostics().size(), 1u) << value;
    EXPECT_EQ(r.diagnostics()[0].to_string(), message);
  }
}

TEST(MaxTriangles, IncludedFilesDoNotChangeTheRootsLimit) {
  TempDir dir;
  test::write_text(dir / "inner.xml", "<scene version=\"1\" max_triangles=\"5\"/>\n");
  test::write_text(dir / "root.xml", "<scene version=\"1\" max_triangles=\"7\">\n  <include file=\"inner.xml\"/>\n</scene>\n");
  const Result<SceneDescription> r = read_scene_file(dir / "root.xml");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->max_triangles, 7u);
}

}  // namespace
}  // namespace mhd
