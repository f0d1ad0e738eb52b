// The viewer drawing from the DDS state source: a state published on a loopback domain
// is drawn where it says (the HIP, yellow, at the projection of its point in both eyes),
// and still drawn after its publisher has gone. Needs an X display with GLX: ctest runs
// this binary under xvfb-run.

#include "viewer_dds/dds_state_source.h"

#include "dds_common/dds_convert.h"
#include "dds_common/dds_topics.h"
#include "plugin_host/abi_conversion.h"
#include "scene_xml/scene_reader.h"
#include "viewer/display_check.h"
#include "viewer/png_image.h"
#include "viewer/stereo_views.h"
#include "viewer/stereo_viewer.h"
#include "../dds/dds_test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace mhd::viewer {
namespace {

const std::filesystem::path kSource = MHD_SOURCE_DIR;

TEST(DdsRender, TheHipIsDrawnWhereThePublishedStatePutsItAndStaysAfterThePublisherGoes) {
  if (const std::string e = check_display(); !e.empty()) GTEST_SKIP() << e << " (ctest runs this under xvfb-run)";
  const std::uint32_t domain = dds::test::use_loopback_and_unique_domain(11);

  // The state: head at 1.6 m looking along -z, HIP 0.5 m ahead, a little right and low.
  RigState s;
  s.X_W_head = head_looking_at({0.0, 1.6, 0.0}, {0.0, 1.6, -1.0});
  s.p_W_hip_m = Eigen::Vector3d(0.05, 1.55, -0.5);
  s.p_W_proxy_m = s.p_W_hip_m;
  s.base = BasePose{0.0, -1.5, 0.0};
  const mhd_dds_RigState sample = dds::to_dds(to_abi(display_frame_from_rig_state(s)), 2, 0, dds::realtime_ns());

  DdsStateSourceOptions o;
  o.rig_id = 2;
  o.domain_id = domain;
  o.stale_after_s = 600.0;  // opening the viewer takes seconds under llvmpipe; silence is the source test's
  std::vector<std::string> lines;
  auto source = std::make_shared<DdsStateSource>(o, [&](const std::string& line) { lines.push_back(line); });
  {
    const dds::Participant participant(domain);
    dds::Publisher<mhd_dds_RigState> publisher(participant, dds::rig_partition(2));
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (!source->latest() && std::chrono::steady_clock::now() < end) {
      publisher.write(sample);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }  // the publisher is gone before the viewer draws
  ASSERT_TRUE(source->status().has_state) << "no state arrived in 5 s";

  Result<SceneDescription> read = read_scene_string(
      "<scene version=\"1\"><include file=\"common/materials.xml\"/><object name=\"far\" material=\"smooth\">"
      "<sphere radius=\"0.01\"/><pose position=\"0 -50 0\"/></object></scene>",
      kSource / "scenes/test_scene.xml");
  ASSERT_TRUE(read.ok());
  const ViewerScene scene{*read, std::nullopt, {}};
  ViewerOptions view;
  view.offscreen = true;
  view.width = 640;
  view.height = 320;
  view.max_frame_rate_Hz = 0.0;
  view.show_grid = false;
  Result<std::unique_ptr<StereoViewer>, std::string> r = StereoViewer::open(scene, view, source);
  ASSERT_TRUE(r.ok()) << r.error_text();
  r.value()->frame();
  const RgbaImage image = r.value()->frame_and_capture();
  ASSERT_EQ(r.value()->views().size(), 2u);
  for (const EyeView& v : r.value()->views()) {
    Eigen::Vector2d hip;
    ASSERT_TRUE(project_to_pixel(v, s.p_W_hip_m, hip));
    const std::uint8_t* h = image.pixel(static_cast<int>(hip.x()), static_cast<int>(hip.y()));
    EXPECT_GT(h[0], 120) << "HIP: yellow at " << hip.transpose();
    EXPECT_GT(h[1], 100);
    EXPECT_LT(h[2], 80);
    // 60 px to the side (0.1 m at 0.5 m) is background: the HIP is there and nowhere else.
    const std::uint8_t* side = image.pixel(static_cast<int>(hip.x()) + 60, static_cast<int>(hip.y()));
    EXPECT_LT(side[1], 60) << "background beside the HIP";
  }
  EXPECT_TRUE(lines.empty()) << lines.front();
}

// `mhd viewer SCENE --rig-id 6` against a publisher process that publishes for 1 s and
// exits: the viewer says once that the state stopped, keeps drawing the last one, and
// its screenshot, taken after that, shows the HIP where the published state put it.
TEST(DdsRender, TheViewerCommandDrawsAPublishersStateAndKeepsItWhenThePublisherVanishes) {
  if (const std::string e = check_display(); !e.empty()) GTEST_SKIP() << e << " (ctest runs this under xvfb-run)";
  const std::uint32_t domain = dds::test::use_loopback_and_unique_domain(12);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("mhd_viewer_dds_" + std::to_string(domain));
  std::filesystem::create_directories(dir);
  const std::filesystem::path png = dir / "network.png";
  const std::filesystem::path log = dir / "viewer.log";
  std::filesystem::remove(png);

  dds::test::ChildProcess publisher({MHD_VIEWER_DDS_TEST_PUBLISHER, std::to_string(domain), "6", "1.0"},
                                    (dir / "publisher.log").string());
  dds::test::ChildProcess viewer({MHD_VIEWER_DDS_CLI, "viewer", (kSource / "scenes/dolphin.xml").string(), "--rig-id",
                                  "6", "--domain-id", std::to_string(domain), "--stale-after-s", "0.3", "--no-grid",
                                  "--screenshot", png.string(), "--frames", "150", "--width", "640", "--height", "320"},
                                 log.string());
  const std::optional<int> viewer_status = viewer.wait_for(std::chrono::seconds(90));
  const std::optional<int> publisher_status = publisher.wait_for(std::chrono::seconds(30));
  const std::string out = dds::test::read_file(log.string());
  ASSERT_EQ(viewer_status, 0) << out;
  EXPECT_EQ(publisher_status, 0) << dds::test::read_file((dir / "publisher.log").string());
  EXPECT_NE(out.find("mhd viewer: no rig state from rig 6 for "), std::string::npos) << out;  // 0.3 s or more
  EXPECT_NE(out.find("(publisher gone?); keeping the last state"), std::string::npos) << out;
  EXPECT_EQ(out.find("no rig state from rig 6", out.find("no rig state from rig 6") + 1), std::string::npos)
      << "said once: " << out;
  EXPECT_NE(out.find("150 frames, 640x320 stereo image written to"), std::string::npos) << out;

  RgbaImage image;
  ASSERT_EQ(read_png(png, image), "");
  ViewGeometry g;
  g.width = 640;
  g.height = 320;
  const Eigen::Vector3d p_W_hip(0.05, 1.55, -0.5);
  for (const EyeView& v : eye_views(head_looking_at({0.0, 1.6, 0.0}, {0.0, 1.6, -1.0}), g)) {
    Eigen::Vector2d hip;
    ASSERT_TRUE(project_to_pixel(v, p_W_hip, hip));
    const std::uint8_t* h = image.pixel(static_cast<int>(hip.x()), static_cast<int>(hip.y()));
    EXPECT_GT(h[0], 120) << "HIP: yellow at " << hip.transpose();
    EXPECT_GT(h[1], 100);
    EXPECT_LT(h[2], 80);
  }
  if (!::testing::Test::HasFailure()) std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mhd::viewer
