// Rendering through OSG into images that the tests read: both halves of a stereo image
// show the dolphin; a near sphere has crossed parallax (left eye sees it further right)
// of focal * ipd / depth pixels, larger than a far one's; the rig is drawn where the
// state puts it; mono fills the whole width; run() writes the screenshot.
// Needs an X display with GLX: ctest runs this binary under xvfb-run.

#include "scene_xml/scene_reader.h"
#include "viewer/display_check.h"
#include "viewer/png_image.h"
#include "viewer/stereo_viewer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace mhd::viewer {
namespace {

const std::filesystem::path kSource = MHD_SOURCE_DIR;

class Render : public ::testing::Test {
 protected:
  void SetUp() override {
    if (const std::string e = check_display(); !e.empty()) GTEST_SKIP() << e << " (ctest runs this under xvfb-run)";
  }

  static ViewerOptions small_options() {
    ViewerOptions o;
    o.offscreen = true;
    o.width = 640;
    o.height = 320;
    o.fov_deg = 90.0;
    o.max_frame_rate_Hz = 0.0;
    return o;
  }

  static RgbaImage render(const ViewerScene& scene, const ViewerOptions& options,
                          std::shared_ptr<StateSource> source = nullptr, std::vector<EyeView>* views = nullptr) {
    Result<std::unique_ptr<StereoViewer>, std::string> r = StereoViewer::open(scene, options, std::move(source));
    EXPECT_TRUE(r.ok()) << r.error_text();
    if (!r.ok()) return {};
    r.value()->frame();
    RgbaImage image = r.value()->frame_and_capture();
    if (views) *views = r.value()->views();
    return image;
  }
};

ViewerScene scene_from(std::string_view xml) {
  Result<SceneDescription> read = read_scene_string(xml, kSource / "scenes/test_scene.xml");
  EXPECT_TRUE(read.ok()) << (read.diagnostics().empty() ? "" : read.diagnostics().front().to_string());
  return ViewerScene{read.ok() ? *read : SceneDescription{}, std::nullopt, {}};
}

/// Pixels of `a` that differ from `b` (any channel by more than 24), per half.
struct Difference {
  int left = 0, right = 0;
  double left_x = 0, right_x = 0;  ///< mean x of the differing pixels, within their half
};
Difference difference(const RgbaImage& a, const RgbaImage& b) {
  Difference d;
  const int half = a.width / 2;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const std::uint8_t* p = a.pixel(x, y);
      const std::uint8_t* q = b.pixel(x, y);
      if (std::abs(p[0] - q[0]) <= 24 && std::abs(p[1] - q[1]) <= 24 && std::abs(p[2] - q[2]) <= 24) continue;
      if (x < half) {
        ++d.left;
        d.left_x += x;
      } else {
        ++d.right;
        d.right_x += x - half;
      }
    }
  }
  if (d.left > 0) d.left_x /= d.left;
  if (d.right > 0) d.right_x /= d.right;
  return d;
}

TEST_F(Render, BothHalvesShowTheDolphin) {
  const Result<ViewerScene, std::vector<std::string>> loaded = load_viewer_scene(kSource / "scenes/dolphin.xml");
  ASSERT_TRUE(loaded.ok()) << loaded.error_text();
  ViewerScene without = *loaded;
  std::erase_if(without.scene.objects, [](const ObjectDescription& o) { return o.name == "dolphin"; });
  ASSERT_EQ(without.scene.objects.size(), 1u);
  ViewerOptions o = small_options();
  // The same head for both images (the default one depends on the objects' bounds).
  o.default_head_m = Eigen::Vector3d(0.0, 1.7, 1.0);
  o.look_at_m = Eigen::Vector3d(0.0, 0.8, -0.7);
  const RgbaImage with_dolphin = render(*loaded, o);
  const RgbaImage floor_only = render(without, o);
  ASSERT_EQ(with_dolphin.width, 640);
  const Difference d = difference(with_dolphin, floor_only);
  const int half_pixels = 320 * 320;
  EXPECT_GT(d.left, half_pixels / 50) << "the dolphin covers a good part of the left eye's view";
  EXPECT_GT(d.right, half_pixels / 50);
  EXPECT_NEAR(d.left, d.right, 0.2 * d.left) << "the eyes see about the same amount of it";
}

/// Crossed parallax of a sphere at `depth_m` in front of the eyes, measured in the image
/// (difference against an empty scene) and predicted by the eye projections.
void check_parallax(const ViewerOptions& o, double depth_m, double radius_m, double& measured_px, double& expected_px) {
  const std::string sphere = "<object name=\"ball\" material=\"rubber\"><sphere radius=\"" + std::to_string(radius_m) +
                             "\"/><pose position=\"0 1.6 " + std::to_string(-depth_m) + "\"/></object>";
  const std::string head = "<include file=\"common/materials.xml\"/>";
  const ViewerScene ball = scene_from("<scene version=\"1\">" + head + sphere + "</scene>");
  const ViewerScene empty = scene_from("<scene version=\"1\">" + head +
                                       "<object name=\"far\" material=\"smooth\"><sphere radius=\"0.01\"/><pose position=\"0 -50 0\"/></object>"
                                       "</scene>");
  Result<std::unique_ptr<StereoViewer>, std::string> r = StereoViewer::open(ball, o, nullptr);
  ASSERT_TRUE(r.ok()) << r.error_text();
  const RgbaImage with_ball = r.value()->frame_and_capture();
  const std::vector<EyeView> views = r.value()->views();
  r.value().reset();
  Result<std::unique_ptr<StereoViewer>, std::string> e = StereoViewer::open(empty, o, nullptr);
  ASSERT_TRUE(e.ok()) << e.error_text();
  const RgbaImage background = e.value()->frame_and_capture();
  const Difference d = difference(with_ball, background);
  ASSERT_GT(d.left, 50);
  ASSERT_GT(d.right, 50);
  measured_px = d.left_x - d.right_x;
  Eigen::Vector2d left, right;
  ASSERT_TRUE(project_to_pixel(views[0], {0.0, 1.6, -depth_m}, left));
  ASSERT_TRUE(project_to_pixel(views[1], {0.0, 1.6, -depth_m}, right));
  expected_px = (left.x() - views[0].viewport_x) - (right.x() - views[1].viewport_x);
}

TEST_F(Render, NearObjectHasCrossedParallaxMatchingTheIpd) {
  ViewerOptions o = small_options();
  o.show_grid = false;
  o.default_head_m = Eigen::Vector3d(0.0, 1.6, 0.0);
  o.look_at_m = Eigen::Vector3d(0.0, 1.6, -1.0);
  o.ipd_m = 0.064;
  double near_px = 0, near_expected = 0, far_px = 0, far_expected = 0;
  check_parallax(o, 0.4, 0.04, near_px, near_expected);
  check_parallax(o, 3.0, 0.3, far_px, far_expected);
  // focal = 160 px at 90 degrees over 320 rows: 160 * 0.064 / 0.4 = 25.6 px.
  EXPECT_NEAR(near_expected, 25.6, 1e-9);
  EXPECT_GT(near_px, 0.0) << "left eye sees a near object to the right of where the right eye sees it";
  EXPECT_NEAR(near_px, near_expected, 1.5);
  EXPECT_NEAR(far_px, far_expected, 1.5);
  EXPECT_GT(near_px, far_px + 15.0);
  // Zero eye separation: no parallax at all.
  o.ipd_m = 0.0;
  double zero_px = 0, zero_expected = 0;
  check_parallax(o, 0.4, 0.04, zero_px, zero_expected);
  EXPECT_NEAR(zero_px, 0.0, 0.5);
}

TEST_F(Render, RigIsDrawnWhereTheStateSaysAndTheHeadModelDoesNotBlockTheEyes) {
  const ViewerScene scene = scene_from(
      "<scene version=\"1\"><include file=\"common/materials.xml\"/><object name=\"far\" material=\"smooth\"><sphere radius=\"0.01\"/><pose position=\"0 -50 0\"/></object></scene>");
  RigState s;
  s.X_W_head = head_looking_at({0.0, 1.6, 0.0}, {0.0, 1.6, -1.0});
  s.p_W_hip_m = Eigen::Vector3d(0.05, 1.55, -0.5);
  s.p_W_proxy_m = Eigen::Vector3d(-0.1, 1.65, -0.5);
  s.base = BasePose{0.0, -1.5, 0.0};
  s.force_W_N = Eigen::Vector3d(0.0, 2.0, 0.0);  // 0.1 m arrow straight up at 0.05 m/N
  s.in_contact = true;
  ViewerOptions o = small_options();
  o.show_grid = false;
  std::vector<EyeView> views;
  const RgbaImage image = render(scene, o, std::make_shared<FixedStateSource>(s), &views);
  ASSERT_EQ(views.size(), 2u);
  for (const EyeView& v : views) {
    Eigen::Vector2d hip, proxy;
    ASSERT_TRUE(project_to_pixel(v, s.p_W_hip_m, hip));
    ASSERT_TRUE(project_to_pixel(v, s.p_W_proxy_m, proxy));
    const std::uint8_t* h = image.pixel(static_cast<int>(hip.x()), static_cast<int>(hip.y()));
    EXPECT_GT(h[0], 120) << "HIP: yellow";
    EXPECT_GT(h[1], 100);
    EXPECT_LT(h[2], 80);
    const std::uint8_t* p = image.pixel(static_cast<int>(proxy.x()), static_cast<int>(proxy.y()));
    EXPECT_GT(p[0], 150) << "proxy in contact: red";
    EXPECT_LT(p[1], 100);
    Eigen::Vector2d shaft;
    ASSERT_TRUE(project_to_pixel(v, s.p_W_proxy_m + Eigen::Vector3d(0.0, 0.045, 0.0), shaft));
    const std::uint8_t* a = image.pixel(static_cast<int>(std::lround(shaft.x())), static_cast<int>(shaft.y()));
    EXPECT_GT(a[0], 150) << "force arrow: red, above the proxy";
    EXPECT_LT(a[1], 100);
    Eigen::Vector2d beyond;
    ASSERT_TRUE(project_to_pixel(v, s.p_W_proxy_m + Eigen::Vector3d(0.0, 0.13, 0.0), beyond));
    const std::uint8_t* b = image.pixel(static_cast<int>(beyond.x()), static_cast<int>(beyond.y()));
    EXPECT_LT(b[0], 60) << "nothing past the arrow's tip";
  }
  // The corner of the view shows the background, not the inside of the head sphere.
  const std::uint8_t* corner = image.pixel(5, 5);
  EXPECT_LT(corner[0], 40);
  EXPECT_LT(corner[2], 60);
}

// A second rig (add_rig: another haptic process's state) is drawn where its state says,
// beside the first; without it, that place shows the background.
TEST_F(Render, AnotherRigIsDrawnWhereItsStateSays) {
  const ViewerScene scene = scene_from(
      "<scene version=\"1\"><include file=\"common/materials.xml\"/><object name=\"far\" material=\"smooth\"><sphere radius=\"0.01\"/><pose position=\"0 -50 0\"/></object></scene>");
  RigState own;
  own.X_W_head = head_looking_at({0.0, 1.6, 0.0}, {0.0, 1.6, -1.0});
  own.p_W_hip_m = own.p_W_proxy_m = Eigen::Vector3d(-0.2, 1.55, -0.5);
  own.base = BasePose{0.0, -1.5, 0.0};
  RigState other = own;
  other.X_W_head = head_looking_at({0.8, 1.6, -1.5}, {0.0, 1.6, -1.0});
  other.p_W_hip_m = other.p_W_proxy_m = Eigen::Vector3d(0.2, 1.6, -0.6);
  other.base = BasePose{0.8, -2.0, 0.0};
  ViewerOptions o = small_options();
  o.show_grid = false;
  const auto draw = [&](bool with_other, std::vector<EyeView>& views) {
    Result<std::unique_ptr<StereoViewer>, std::string> r =
        StereoViewer::open(scene, o, std::make_shared<FixedStateSource>(own));
    EXPECT_TRUE(r.ok()) << r.error_text();
    if (!r.ok()) return RgbaImage{};
    if (with_other) r.value()->add_rig(std::make_shared<FixedStateSource>(other));
    r.value()->add_rig(nullptr);  // ignored
    r.value()->frame();
    RgbaImage image = r.value()->frame_and_capture();
    views = r.value()->views();
    return image;
  };
  std::vector<EyeView> views, views_alone;
  const RgbaImage both = draw(true, views);
  const RgbaImage alone = draw(false, views_alone);
  ASSERT_EQ(views.size(), 2u);
  for (const EyeView& v : views) {
    Eigen::Vector2d hip, own_hip;
    ASSERT_TRUE(project_to_pixel(v, other.p_W_hip_m, hip));
    ASSERT_TRUE(project_to_pixel(v, own.p_W_hip_m, own_hip));
    const std::uint8_t* h = both.pixel(static_cast<int>(hip.x()), static_cast<int>(hip.y()));
    EXPECT_GT(h[0], 120) << "the other rig's HIP: yellow";
    EXPECT_GT(h[1], 100);
    const std::uint8_t* none = alone.pixel(static_cast<int>(hip.x()), static_cast<int>(hip.y()));
    EXPECT_LT(none[0], 60) << "no other rig: background there";
    const std::uint8_t* mine = both.pixel(static_cast<int>(own_hip.x()), static_cast<int>(own_hip.y()));
    EXPECT_GT(mine[0], 120) << "the first rig's HIP is still drawn";
  }
}

TEST_F(Render, MonoUsesTheWholeWidthAndRunWritesTheScreenshot) {
  const Result<ViewerScene, std::vector<std::string>> loaded = load_viewer_scene(kSource / "scenes/dolphin.xml");
  ASSERT_TRUE(loaded.ok()) << loaded.error_text();
  ViewerOptions o = small_options();
  o.stereo = false;
  o.frames = 3;
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "mhd_viewer_tests" / "mono.png";
  std::filesystem::create_directories(out.parent_path());
  std::filesystem::remove(out);
  o.screenshot_png = out.string();
  Result<std::unique_ptr<StereoViewer>, std::string> r = StereoViewer::open(*loaded, o, nullptr);
  ASSERT_TRUE(r.ok()) << r.error_text();
  ASSERT_EQ(r.value()->views().size(), 0u) << "no frame drawn yet";
  const std::atomic<bool> stop{false};
  EXPECT_EQ(r.value()->run(stop), "");
  EXPECT_EQ(r.value()->frames_drawn(), 3u);
  ASSERT_EQ(r.value()->views().size(), 1u);
  EXPECT_EQ(r.value()->views()[0].width, 640);
  RgbaImage image;
  ASSERT_EQ(read_png(out, image), "");
  EXPECT_EQ(image.width, 640);
  EXPECT_EQ(image.height, 320);
  // The dolphin sits in the middle of the default view: the centre is not background.
  const std::uint8_t* centre = image.pixel(320, 160);
  EXPECT_GT(centre[0] + centre[1] + centre[2], 150);
}

}  // namespace
}  // namespace mhd::viewer
