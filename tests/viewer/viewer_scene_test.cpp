// Loading a scene for viewing (rig frames from the scene or a rig file), scene graphs
// of good and broken scenes, and the clear refusal when there is no display.

#include "scene_xml/scene_reader.h"
#include "viewer/demo_state.h"
#include "viewer/scene_graph.h"
#include "viewer/stereo_viewer.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace mhd::viewer {
namespace {

const std::filesystem::path kSource = MHD_SOURCE_DIR;

std::filesystem::path scratch_dir() {
  // One folder per test process: ctest runs the cases of this file at the same time.
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "mhd_viewer_tests" / std::to_string(::getpid());
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(ViewerScene, SceneWithoutRigFramesLoadsWithANote) {
  const std::filesystem::path file = scratch_dir() / "no_rig.xml";
  std::ofstream(file) << R"(<scene version="1"><object name="ball"><material stiffness_N_per_m="500"/><sphere radius="0.1"/></object></scene>)";
  const Result<ViewerScene, std::vector<std::string>> r = load_viewer_scene(file);
  ASSERT_TRUE(r.ok()) << r.error_text();
  EXPECT_FALSE(r->rig);
  ASSERT_EQ(r->notes.size(), 1u);
  EXPECT_NE(r->notes[0].find("no rig frames"), std::string::npos);
}

TEST(ViewerScene, RigFramesComeFromTheSceneOrARigFile) {
  const Result<ViewerScene, std::vector<std::string>> own = load_viewer_scene(kSource / "scenes/dolphin.xml");  // includes rigs/pomhi.xml
  ASSERT_TRUE(own.ok()) << own.error_text();
  EXPECT_TRUE(own->rig);
  EXPECT_TRUE(own->notes.empty());
  EXPECT_EQ(own->scene.objects.size(), 2u);
  const std::filesystem::path file = scratch_dir() / "no_rig.xml";
  std::ofstream(file) << R"(<scene version="1"><object name="ball"><material stiffness_N_per_m="500"/><sphere radius="0.1"/></object></scene>)";
  const Result<ViewerScene, std::vector<std::string>> given = load_viewer_scene(file, kSource / "scenes/rigs/pomhi.xml");
  ASSERT_TRUE(given.ok()) << given.error_text();
  EXPECT_TRUE(given->rig);
}

TEST(ViewerScene, MissingFileAndRigFileWithoutFramesAreErrors) {
  const Result<ViewerScene, std::vector<std::string>> missing = load_viewer_scene(kSource / "scenes/no_such_scene.xml");
  ASSERT_FALSE(missing.ok());
  ASSERT_FALSE(missing.error().empty());
  EXPECT_NE(missing.error()[0].find("no_such_scene.xml"), std::string::npos);
  const Result<ViewerScene, std::vector<std::string>> no_frames = load_viewer_scene(kSource / "scenes/dolphin.xml", kSource / "scenes/bunny.xml");
  ASSERT_FALSE(no_frames.ok());
  ASSERT_EQ(no_frames.error().size(), 1u);
  EXPECT_NE(no_frames.error()[0].find("the rig file defines no rig frames"), std::string::npos);
}

TEST(SceneGraph, DolphinSceneHasBothObjectsAndBoundsWithoutTheFloor) {
  const Result<SceneDescription> read = read_scene_file(kSource / "scenes/dolphin.xml");
  ASSERT_TRUE(read.ok());
  const Result<SceneGraph, std::vector<std::string>> g = build_scene_graph(*read);
  ASSERT_TRUE(g.ok()) << g.error_text();
  EXPECT_EQ(g->root->getNumChildren(), 2u);
  // The 2 m dolphin around (0, 0.9, -0.7); the 6 m floor is left out of the bounds.
  EXPECT_NEAR(g->objects_bounds_W.center().y(), 0.9, 0.05);
  EXPECT_NEAR(g->objects_bounds_W.center().z(), -0.7, 0.05);
  EXPECT_LT(g->objects_bounds_W.sizes().x(), 2.5);
}

TEST(SceneGraph, AMeshThatCannotBeLoadedIsNamed) {
  const std::filesystem::path dir = scratch_dir();
  std::ofstream(dir / "garbage.ply") << "ply\nthis is not a mesh\n";
  const Result<SceneDescription> read = read_scene_string(
      R"(<scene version="1"><object name="bad"><material stiffness_N_per_m="500"/><mesh file="garbage.ply"/></object>
         <object name="ball"><material stiffness_N_per_m="500"/><sphere radius="0.1"/></object></scene>)",
      dir / "bad.xml");
  ASSERT_TRUE(read.ok()) << read.diagnostics().front().to_string();
  const Result<SceneGraph, std::vector<std::string>> g = build_scene_graph(*read);
  ASSERT_EQ(g.error().size(), 1u);
  EXPECT_EQ(g.error()[0].rfind("object 'bad': mesh file '", 0), 0u) << g.error()[0];
}

TEST(DemoState, DolphinBaseFromItsSimOmni3AndHipInFrontOfTheWorkspaceCentre) {
  const Result<ViewerScene, std::vector<std::string>> loaded = load_viewer_scene(kSource / "scenes/dolphin.xml");
  ASSERT_TRUE(loaded.ok() && loaded->rig);
  const RigState s = demo_rig_state(*loaded);
  const auto base = std::find_if(loaded->scene.plugins.begin(), loaded->scene.plugins.end(),
                                 [](const PluginDescription& p) { return p.name == "sim_omni3"; });
  ASSERT_NE(base, loaded->scene.plugins.end());
  EXPECT_DOUBLE_EQ(s.base.x_m, std::stod(base->params.at("x_m")));
  EXPECT_DOUBLE_EQ(s.base.z_m, std::stod(base->params.at("z_m")));
  EXPECT_NEAR(s.base.heading_rad, std::stod(base->params.at("heading_deg")) * M_PI / 180.0, 1e-12);
  const Rig& rig = *loaded->rig;
  const Eigen::Vector3d centre_W =
      rig.X_W_phantom(rig.X_W_robot_from_base(s.base)) * rig.device().usable_workspace().center_P_m();
  EXPECT_TRUE(s.p_W_hip_m.isApprox(centre_W + Eigen::Vector3d(0.0, 0.08, 0.15), 1e-12));
  EXPECT_EQ(s.p_W_proxy_m, s.p_W_hip_m);
  EXPECT_FALSE(s.in_contact);
  EXPECT_TRUE(s.X_W_head.translation().isApprox(s.p_W_hip_m + Eigen::Vector3d(0.0, 0.5, 0.7), 1e-12));
  const Eigen::Vector3d gaze = s.X_W_head.linear().col(0);
  EXPECT_TRUE(gaze.isApprox((s.p_W_hip_m - s.X_W_head.translation()).normalized(), 1e-12));
}

TEST(DemoState, WithoutRigOrBasePluginTheHipIsAheadOfTheBaseAtOneMetre) {
  ViewerScene scene;
  const RigState s = demo_rig_state(scene);
  EXPECT_TRUE(s.p_W_hip_m.isApprox(Eigen::Vector3d(0.5, 1.08, 0.15), 1e-12));
  // A given base replaces the scene's; forward is (cos h, 0, -sin h).
  const RigState turned = demo_rig_state(scene, BasePose{1.0, 2.0, M_PI / 2.0});
  EXPECT_DOUBLE_EQ(turned.base.x_m, 1.0);
  EXPECT_TRUE(turned.p_W_hip_m.isApprox(Eigen::Vector3d(1.0, 1.08, 1.5 + 0.15), 1e-12));
}

class NoDisplay : public ::testing::Test {
 protected:
  void SetUp() override {
    if (const char* d = std::getenv("DISPLAY")) saved_ = d;
  }
  void TearDown() override {
    if (saved_) {
      setenv("DISPLAY", saved_->c_str(), 1);
    } else {
      unsetenv("DISPLAY");
    }
  }
  std::optional<std::string> saved_;
};

TEST_F(NoDisplay, OpenWithoutDisplaySaysSoAndReturnsNoViewer) {
  const Result<ViewerScene, std::vector<std::string>> scene = load_viewer_scene(kSource / "scenes/dolphin.xml");
  ASSERT_TRUE(scene.ok()) << scene.error_text();
  ViewerOptions options;
  options.offscreen = true;
  unsetenv("DISPLAY");
  Result<std::unique_ptr<StereoViewer>, std::string> r = StereoViewer::open(*scene, options, nullptr);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.error().rfind("no display: DISPLAY is not set", 0), 0u) << r.error();
  setenv("DISPLAY", ":31999", 1);  // nothing listens there
  r = StereoViewer::open(*scene, options, nullptr);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.error(), "no display: cannot open X display ':31999' (is the X server or Xvfb running?)");
}

TEST(StereoViewerOpen, BadOptionsAreRefusedBeforeAnythingElse) {
  const Result<ViewerScene, std::vector<std::string>> scene = load_viewer_scene(kSource / "scenes/dolphin.xml");
  ASSERT_TRUE(scene.ok()) << scene.error_text();
  ViewerOptions options;
  options.ipd_m = -1.0;
  const Result<std::unique_ptr<StereoViewer>, std::string> r = StereoViewer::open(*scene, options, nullptr);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.error(), "ipd_m must be in [0, 0.2], got -1");
}

}  // namespace
}  // namespace mhd::viewer
