// The haptic server running the dolphin scene on simulated hardware with osg_stereo as
// its display: the viewer draws in its own thread from the 60 Hz snapshot, and the
// haptic loop keeps every deadline. Needs an X display: ctest runs it under xvfb-run.

#include "haptic_server/haptic_server.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"
#include "viewer/display_check.h"
#include "viewer/png_image.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace mhd {
namespace {

namespace fs = std::filesystem;

struct ServerRun {
  ServerReport report;
  bool ran = false;
};

/// Runs scenes/dolphin.xml for `duration_s`, with osg_stereo added when `screenshot` is set.
ServerRun run_dolphin(double duration_s, const fs::path& screenshot) {
  ServerRun run;
  Result<SceneDescription> read = read_scene_file(fs::path(MHD_SOURCE_DIR) / "scenes/dolphin.xml");
  EXPECT_TRUE(read.ok());
  if (!read.ok()) return run;
  SceneDescription scene = *read;
  if (!screenshot.empty()) {
    PluginDescription display;
    display.kind = PluginKind::Display;
    display.name = "osg_stereo";
    display.params = {{"offscreen", "true"}, {"width", "320"}, {"height", "160"},
                      {"frames", "40"},      {"screenshot", screenshot.string()}};
    scene.plugins.push_back(display);
  }
  Result<std::unique_ptr<CompiledScene>> compiled = compile_scene(scene);
  EXPECT_TRUE(compiled.ok());
  if (!compiled.ok()) return run;
  ServerOptions options;
  options.duration_s = duration_s;
  options.plugin_path = {MHD_PLUGIN_BUILD_DIR};
  Result<OpenedServer> build = HapticServer::open(scene, *compiled.value(), options);
  for (const Diagnostic& d : build.diagnostics()) ADD_FAILURE() << d.to_string();
  if (!build.ok()) return run;
  run.report = build->server->run();
  run.ran = true;
  return run;
}

TEST(ViewerWithServer, HapticLoopKeepsItsDeadlinesWhileTheViewerDraws) {
  if (const std::string e = viewer::check_display(); !e.empty()) GTEST_SKIP() << e;
  // Mesa's software renderer in the drawing thread only, so it does not take both cores
  // of a small machine from the haptic thread (a GPU takes nothing).
  setenv("LP_NUM_THREADS", "0", 1);
  const fs::path png = fs::temp_directory_path() / "mhd_viewer_tests" / "server.png";
  fs::create_directories(png.parent_path());
  fs::remove(png);
  const ServerRun with_viewer = run_dolphin(1.5, png);
  ASSERT_TRUE(with_viewer.ran);
  ASSERT_FALSE(with_viewer.report.error) << *with_viewer.report.error;
  EXPECT_GT(with_viewer.report.status.ticks, 1000u);
  // The viewer drew its 40 frames from the server's snapshots and wrote the picture.
  viewer::RgbaImage image;
  ASSERT_EQ(viewer::read_png(png, image), "");
  EXPECT_EQ(image.width, 320);
  std::printf("haptic tick with the viewer drawing: median %.1f us, p99 %.1f us, max %.1f us, %llu overruns\n",
              with_viewer.report.tick_median_us, with_viewer.report.tick_p99_us, with_viewer.report.tick_max_us,
              static_cast<unsigned long long>(with_viewer.report.status.overruns));
  // Overruns: the viewer's fault only if they clearly exceed those of the same run without
  // it. On a shared 2-core CI machine with software OpenGL a few wake-ups come late either
  // way (0 on an idle machine); the viewer must not add more than a handful. One pair of
  // runs can be unlucky (a clean-clone CI run once saw 13 against 2, alone in ctest), so a
  // viewer that slows the loop must do so in two pairs in a row, the second drawing too.
  auto with = with_viewer.report.status.overruns;
  std::uint64_t without = 0;
  for (int pair = 0; pair < 2 && with > 0; ++pair) {
    if (pair > 0) {
      const ServerRun again = run_dolphin(1.5, png);
      ASSERT_TRUE(again.ran);
      with = again.report.status.overruns;
      if (with == 0) break;
    }
    const ServerRun baseline = run_dolphin(1.5, {});
    ASSERT_TRUE(baseline.ran);
    without = baseline.report.status.overruns;
    std::printf("pair %d: overruns %llu with the viewer, %llu without any display\n", pair + 1,
                static_cast<unsigned long long>(with), static_cast<unsigned long long>(without));
    if (with <= 2 * without + 3) break;
  }
  EXPECT_LE(with, 2 * without + 3) << "the viewer slowed the haptic loop in two pairs of runs";
}

}  // namespace
}  // namespace mhd
