// `mhd try` driven as a user would (engine/viewer/hand_session.h): mouse and key events
// go into the viewer's event queue, and the drawn image and the reported numbers are
// checked. On scenes/cube_wall.xml (cube top face y = 1.2 m over x in [-0.2, 0.2],
// z in [-0.7, -0.3]), seen from above and in front: a drag moves the HIP in the screen
// plane; dragged down into the top face, the force arrow appears, the proxy (red) stays
// on the face while the HIP is hidden under it, and the force is out of the face and
// at most the scene's max force; reset to free space, no arrow pixel is left and the
// proxy is at the HIP. Needs an X display with GLX: ctest runs it under xvfb-run.

#include "scene_compiler/scene_compiler.h"
#include "viewer/display_check.h"
#include "viewer/hand_session.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace mhd::viewer {
namespace {

constexpr double kTop_y_m = 1.2;
constexpr int kWidth = 480;
constexpr int kHeight = 320;

bool is_red(const std::uint8_t* p) { return p[0] > 100 && p[1] < 0.45 * p[0] && p[2] < 0.45 * p[0]; }
bool is_yellow(const std::uint8_t* p) { return p[0] > 150 && p[1] > 120 && p[2] < 0.5 * p[1]; }

/// Pixels within radius_px of `centre` (or, with `outside`, farther) that pass `test`.
template <class Test>
int count(const RgbaImage& image, const Eigen::Vector2d& centre, double radius_px, bool outside, Test test) {
  int n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const bool near = (Eigen::Vector2d(x, y) - centre).norm() <= radius_px;
      if (near != outside && test(image.pixel(x, y))) ++n;
    }
  }
  return n;
}

class TryByHand : public ::testing::Test {
 protected:
  void SetUp() override {
    if (const std::string e = check_display(); !e.empty()) GTEST_SKIP() << e << " (ctest runs this under xvfb-run)";
    const std::filesystem::path file = std::filesystem::path(MHD_SOURCE_DIR) / "scenes/cube_wall.xml";
    const Result<ViewerScene, std::vector<std::string>> loaded = load_viewer_scene(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error_text();
    scene_ = *loaded;
    CompileOptions compile;
    compile.use_cache = false;
    Result<std::unique_ptr<CompiledScene>> compiled = compile_scene(scene_.scene, compile);
    ASSERT_TRUE(compiled.ok());
    compiled_ = std::move(compiled).value();

    HandSessionOptions o;
    o.view.offscreen = true;
    o.view.width = kWidth;
    o.view.height = kHeight;
    o.view.fov_deg = 60.0;
    o.view.max_frame_rate_Hz = 0.0;
    o.view.force_scale_m_per_N = 0.02;
    o.view.default_head_m = Eigen::Vector3d(0.0, 1.6, 0.3);
    o.view.look_at_m = Eigen::Vector3d(0.0, 1.2, -0.5);
    o.p_W_start_m = Eigen::Vector3d(0.0, 1.25, -0.5);  // 5 cm over the top face's centre
    Result<std::unique_ptr<HandSession>, std::string> opened = HandSession::open(scene_, *compiled_, o);
    ASSERT_TRUE(opened.ok()) << opened.error_text();
    session_ = std::move(opened).value();
    session_->frame();
  }

  /// Frames enough for the injected events to act and the damping to die away.
  RgbaImage settle_and_capture() {
    for (int i = 0; i < 5; ++i) session_->frame();
    return session_->frame_and_capture();
  }

  Eigen::Vector2d pixel(const Eigen::Vector3d& p_W) {
    Eigen::Vector2d px(-1.0, -1.0);
    EXPECT_TRUE(project_to_pixel(session_->view(), p_W, px));
    return px;
  }

  double hip_metres_per_pixel() {
    const HandCamera& c = session_->camera();
    return metres_per_pixel(c, -(c.X_W_camera.inverse() * session_->sample().p_W_hip_m).z());
  }

  ViewerScene scene_;
  std::unique_ptr<CompiledScene> compiled_;
  std::unique_ptr<HandSession> session_;
};

TEST_F(TryByHand, ADragMovesTheHipInTheScreenPlaneAndRPutsItBack) {
  const double mpp = hip_metres_per_pixel();
  session_->inject(InputEvent::press(240.0, 160.0));
  session_->inject(InputEvent::drag(270.0, 160.0));
  session_->inject(InputEvent::release(270.0, 160.0));
  (void)settle_and_capture();
  const HandSample& s = session_->sample();
  EXPECT_NEAR(s.p_W_hip_m.x(), 30.0 * mpp, 1e-6);  // the camera's right is world +x
  EXPECT_NEAR(s.p_W_hip_m.y(), 1.25, 1e-9);
  EXPECT_FALSE(s.in_contact);
  session_->inject(InputEvent::key_press('r'));
  (void)settle_and_capture();
  EXPECT_LT((session_->sample().p_W_hip_m - Eigen::Vector3d(0.0, 1.25, -0.5)).norm(), 1e-12);
}

TEST_F(TryByHand, PushedIntoTheCubeTheArrowShowsAndTheProxyStaysOnTheSurfaceThenBackOutNothing) {
  // Down by 18.8 px: about 53 mm down the screen's up axis, which tilts 27 deg from +y,
  // so the HIP ends about 3 mm under the 50 mm-away top face.
  session_->inject(InputEvent::press(240.0, 160.0));
  session_->inject(InputEvent::drag(240.0, 160.0 - 18.8));
  session_->inject(InputEvent::release(240.0, 160.0 - 18.8));
  const RgbaImage in = settle_and_capture();
  const HandSample contact = session_->sample();
  ASSERT_TRUE(contact.in_contact) << session_->overlay_text();
  EXPECT_LT(contact.p_W_hip_m.y(), kTop_y_m);
  EXPECT_GE(contact.p_W_proxy_m.y(), kTop_y_m);  // on the surface side
  EXPECT_LT(contact.p_W_proxy_m.y(), kTop_y_m + 1e-5);
  const double force_N = contact.force_W_N.norm();
  EXPECT_GT(force_N, 0.5);
  EXPECT_LE(force_N, compiled_->proxy.max_force_N + 1e-9);
  EXPECT_GT(contact.force_W_N.y(), 0.95 * force_N);  // out of the top face
  EXPECT_NE(session_->overlay_text().find("contact yes (cube)"), std::string::npos) << session_->overlay_text();

  const Eigen::Vector2d proxy_px = pixel(contact.p_W_proxy_m);
  const Eigen::Vector2d hip_px = pixel(contact.p_W_hip_m);
  const double marker_px = 0.012 / hip_metres_per_pixel();
  // The arrow's red beyond the proxy marker; the proxy marker red (in contact) on the face;
  // the HIP's yellow hidden under the face.
  EXPECT_GT(count(in, proxy_px, marker_px + 3.0, true, is_red), 20);
  EXPECT_GT(count(in, proxy_px, 3.0, false, is_red), 5);
  EXPECT_EQ(count(in, hip_px, 3.0, false, is_yellow), 0);
  // The overlay's text (white) in the top-left corner.
  EXPECT_GT(count(in, Eigen::Vector2d(0.0, 0.0), 60.0, false,
                  [](const std::uint8_t* p) { return p[0] > 150 && p[1] > 150 && p[2] > 150; }),
            40);

  // Back out to free space.
  session_->inject(InputEvent::key_press(kKeyHome));
  const RgbaImage out = settle_and_capture();
  const HandSample& free = session_->sample();
  EXPECT_FALSE(free.in_contact);
  EXPECT_EQ(free.force_W_N, Eigen::Vector3d::Zero());
  EXPECT_LT((free.p_W_proxy_m - free.p_W_hip_m).norm(), 1e-9);  // the proxy at the HIP
  EXPECT_LT((free.p_W_hip_m - Eigen::Vector3d(0.0, 1.25, -0.5)).norm(), 1e-12);
  EXPECT_EQ(count(out, Eigen::Vector2d(0.0, 0.0), 0.0, true, is_red), 0);  // no arrow anywhere
  EXPECT_GT(count(out, pixel(free.p_W_hip_m), 3.0, false, is_yellow), 5);
  EXPECT_NE(session_->overlay_text().find("force 0.00 N"), std::string::npos) << session_->overlay_text();
  EXPECT_NE(session_->overlay_text().find("contact no"), std::string::npos);
}

}  // namespace
}  // namespace mhd::viewer
