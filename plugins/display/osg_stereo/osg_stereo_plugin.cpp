// The osg_stereo display plugin: the viewer (engine/viewer) in a thread of its own.
// display_write() only converts the frame and publishes it into a lock-free
// latest-value slot, so the haptic side never waits for drawing; the render thread
// draws the newest state at up to 60 Hz. All OSG calls happen in the render thread.
// Parameters (all optional): stereo, ipd_m, fov_deg, width, height, offscreen,
// screenshot, frames, max_frame_rate_Hz, rig_file, grid. docs/viewer.md.

#include "plugin_host/abi_conversion.h"
#include "viewer/stereo_viewer.h"

#include <mhd/plugin_sdk.hpp>

#include <array>
#include <atomic>
#include <filesystem>
#include <future>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

namespace mhd::osg_stereo {

class OsgStereoPlugin {
 public:
  static constexpr std::array kParams{
      sdk::boolean("stereo", "true", "side-by-side stereo, left eye in the left half"),
      sdk::number("ipd_m", "m", "0.064", "interpupillary distance", sdk::between(0, 0.2)),
      sdk::number("fov_deg", "deg", "90", "per-eye vertical field of view", sdk::above_up_to(0, 179)),
      sdk::integer("width", "px", "1600", "the window or image, both eyes", sdk::between(1, 16384)),
      sdk::integer("height", "px", "800", "the window or image", sdk::between(1, 16384)),
      sdk::boolean("offscreen", "false", "render into a pbuffer (still needs an X display, e.g. Xvfb)"),
      sdk::text("screenshot", nullptr, "a PNG written after 'frames' frames"),
      sdk::integer("frames", "", "0", "frames to render before the screenshot and exit; 0: until closed",
                   sdk::between(0, 1e9)),
      sdk::number("max_frame_rate_Hz", "Hz", "60", "the render thread's pace; 0: as fast as it draws",
                  sdk::between(0, 1000)),
      sdk::boolean("grid", "true", "a 1 m floor grid"),
      sdk::text("rig_file", nullptr, "a scene whose rig frames are drawn instead of the running scene's"),
  };

  OsgStereoPlugin(const mhd_host& host, const sdk::Params& params) : options_(read_options(params)) {
    if (host.scene_file == nullptr || *host.scene_file == '\0') {
      throw std::invalid_argument("the host gives no scene_file to draw");
    }
    const std::optional<std::string> rig_file = params.optional_text("rig_file");
    Result<viewer::ViewerScene, std::vector<std::string>> loaded = viewer::load_viewer_scene(
        host.scene_file, rig_file ? std::optional<std::filesystem::path>(*rig_file) : std::nullopt);
    if (!loaded.ok()) throw std::runtime_error(loaded.error_text());
    scene_ = std::move(loaded).value();
  }
  OsgStereoPlugin(const OsgStereoPlugin&) = delete;
  OsgStereoPlugin& operator=(const OsgStereoPlugin&) = delete;
  ~OsgStereoPlugin() { join_render(); }

  void start() {
    if (render_thread_.joinable()) join_render();  // a restart after stop
    stop_render_.store(false);
    std::promise<std::string> opened;
    std::future<std::string> outcome = opened.get_future();
    render_thread_ = std::thread([this, p = std::move(opened)]() mutable { render(std::move(p)); });
    const std::string error = outcome.get();
    if (!error.empty()) {
      render_thread_.join();
      throw std::runtime_error(error);
    }
  }

  void stop() {
    const std::string error = join_render();
    if (!error.empty()) throw std::runtime_error(error);
  }

  // The haptic side's call: no lock, no allocation, no waiting.
  void display_write(const mhd_display_frame& frame) {
    const Result<viewer::RigState, std::string> state = viewer::rig_state_from_frame(from_abi(frame));
    if (!state.ok()) throw std::invalid_argument(state.error());
    slot_->publish(*state);
  }

 private:
  static viewer::ViewerOptions read_options(const sdk::Params& params) {
    viewer::ViewerOptions o;
    o.window_title = "MHD osg_stereo";
    o.stereo = params.boolean("stereo");
    o.ipd_m = params.number("ipd_m");
    o.fov_deg = params.number("fov_deg");
    o.width = static_cast<int>(params.integer("width"));
    o.height = static_cast<int>(params.integer("height"));
    o.offscreen = params.boolean("offscreen");
    if (auto screenshot = params.optional_text("screenshot")) o.screenshot_png = *screenshot;
    o.frames = static_cast<int>(params.integer("frames"));
    o.max_frame_rate_Hz = params.number("max_frame_rate_Hz");
    o.show_grid = params.boolean("grid");
    if (std::string e = o.check(); !e.empty()) throw std::invalid_argument(e);
    return o;
  }

  /// The render thread: opens the viewer (reporting the outcome to start()), then draws.
  void render(std::promise<std::string> opened) {
    Result<std::unique_ptr<viewer::StereoViewer>, std::string> r = viewer::StereoViewer::open(scene_, options_, slot_);
    if (!r.ok()) {
      opened.set_value(r.error());
      return;
    }
    opened.set_value({});
    render_error_ = r.value()->run(stop_render_);
  }

  /// Stops and joins the render thread; the error it ended with, if any.
  std::string join_render() {
    stop_render_.store(true);
    if (render_thread_.joinable()) render_thread_.join();
    return std::exchange(render_error_, {});
  }

  viewer::ViewerOptions options_;
  viewer::ViewerScene scene_;
  std::shared_ptr<viewer::LatestStateSlot> slot_ = std::make_shared<viewer::LatestStateSlot>();
  std::atomic<bool> stop_render_{false};
  std::thread render_thread_;
  std::string render_error_;  ///< written by the render thread, read after join
};

}  // namespace mhd::osg_stereo

MHD_PLUGIN_ENTRY(mhd::osg_stereo::OsgStereoPlugin,
                 {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                  .description = "OpenSceneGraph stereo (side-by-side) or mono view of the scene and the rig, drawn "
                                 "in its own thread"})
