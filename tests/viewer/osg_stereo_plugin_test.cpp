// The osg_stereo plugin through the real loader: open with the host's scene file, start
// (the render thread opens an offscreen viewer), display_write frames, stop; the
// screenshot it writes shows the HIP where the last frame put it. Bad parameters and a
// host without a scene file are refused at open with a message.

#include "plugin_host/host_services.h"
#include "plugin_host/open_plugin.h"
#include "plugin_host/plugin_search_path.h"
#include "viewer/display_check.h"
#include "viewer/png_image.h"
#include "viewer/rig_state.h"
#include "viewer/stereo_views.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

namespace mhd {
namespace {

const std::filesystem::path kSourceDir = MHD_SOURCE_DIR;

PluginDescription osg_stereo(std::map<std::string, std::string> params) {
  PluginDescription d;
  d.kind = PluginKind::Display;
  d.name = "osg_stereo";
  d.params = std::move(params);
  return d;
}

class OsgStereoPlugin : public ::testing::Test {
 protected:
  PluginSearchPath search_{{PluginFolder{MHD_PLUGIN_BUILD_DIR, PluginFolderSource::Given}}};
  HostServices host_;
};

TEST_F(OsgStereoPlugin, OpenRefusesUnknownParametersAndAHostWithoutScene) {
  host_.set_scene_file(kSourceDir / "scenes/dolphin.xml");
  auto bad = open_plugin(search_, osg_stereo({{"colour", "red"}}), host_.abi());
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().to_string().find("unknown parameter 'colour'"), std::string::npos) << bad.error().to_string();
  auto bad_ipd = open_plugin(search_, osg_stereo({{"ipd_m", "abc"}}), host_.abi());
  ASSERT_FALSE(bad_ipd.ok());
  EXPECT_NE(bad_ipd.error().to_string().find("parameter 'ipd_m' must be a number in [0, 0.2] (m), got 'abc'"), std::string::npos);
  HostServices no_scene;
  auto none = open_plugin(search_, osg_stereo({}), no_scene.abi());
  ASSERT_FALSE(none.ok());
  EXPECT_NE(none.error().to_string().find("the host gives no scene_file to draw"), std::string::npos);
}

TEST_F(OsgStereoPlugin, DrawsTheFramesItIsGivenInItsOwnThread) {
  if (const std::string e = viewer::check_display(); !e.empty()) GTEST_SKIP() << e;
  const std::filesystem::path out =
      std::filesystem::temp_directory_path() / "mhd_viewer_tests" / std::to_string(::getpid()) / "plugin.png";
  std::filesystem::create_directories(out.parent_path());
  std::filesystem::remove(out);
  host_.set_scene_file(kSourceDir / "scenes/dolphin.xml");
  auto opened = open_plugin(search_,
                            osg_stereo({{"offscreen", "true"}, {"width", "640"}, {"height", "320"}, {"frames", "20"},
                                        {"screenshot", out.string()}, {"grid", "false"}, {"max_frame_rate_Hz", "200"}}),
                            host_.abi());
  ASSERT_TRUE(opened.ok()) << opened.error().to_string();
  PluginInstance& display = opened.value();
  ASSERT_TRUE(display.start().ok());
  viewer::RigState s;
  s.X_W_head = viewer::head_looking_at({0.0, 1.6, 0.3}, {0.0, 1.6, -1.0});
  s.p_W_hip_m = Eigen::Vector3d(0.0, 1.6, -0.2);
  s.p_W_proxy_m = Eigen::Vector3d(0.1, 1.7, -0.2);
  s.base = BasePose{0.0, -2.0, 0.0};  // behind the HIP: the arm does not hide it
  const DisplayFrame frame = viewer::display_frame_from_rig_state(s);
  // Frames at about 1 kHz while it draws its 20 frames (at most 200 Hz, so at least
  // 100 ms) and writes the screenshot; every write returns at once. How long the drawing
  // takes depends on the machine (software GL, sanitizers, load): wait for the file.
  int written = 0;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!std::filesystem::exists(out) && std::chrono::steady_clock::now() < give_up) {
    auto status = display.display_write(frame);
    ASSERT_TRUE(status.ok()) << status.error().to_string();
    ++written;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_GT(written, 50);
  ASSERT_TRUE(display.stop().ok());
  ASSERT_TRUE(display.close().ok());
  viewer::RgbaImage image;
  ASSERT_EQ(viewer::read_png(out, image), "");
  ASSERT_EQ(image.width, 640);
  viewer::ViewGeometry g;
  g.width = 640;
  g.height = 320;
  g.fov_y_deg = 90.0;
  for (const viewer::EyeView& v : viewer::eye_views(s.X_W_head, g)) {
    Eigen::Vector2d hip;
    ASSERT_TRUE(viewer::project_to_pixel(v, s.p_W_hip_m, hip));
    const std::uint8_t* p = image.pixel(static_cast<int>(hip.x()), static_cast<int>(hip.y()));
    EXPECT_GT(p[0], 120) << "the HIP sphere (yellow) at the written position";
    EXPECT_GT(p[1], 100);
    EXPECT_LT(p[2], 80);
  }
}

}  // namespace
}  // namespace mhd
