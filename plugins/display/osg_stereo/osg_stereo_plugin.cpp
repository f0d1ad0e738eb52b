// The osg_stereo display plugin: the viewer (tools/viewer) in a thread of its own.
// display_write() only converts the frame and publishes it into a lock-free
// latest-value slot, so the haptic side never waits for drawing; the render thread
// draws the newest state at up to 60 Hz. All OSG calls happen in the render thread.
// Parameters (all optional): stereo, ipd_m, fov_deg, width, height, offscreen,
// screenshot, frames, max_frame_rate_Hz, rig_file, grid. docs/viewer.md.

#include "sim_common/plugin_params.h"
#include "sim_common/plugin_shell.h"
#include "viewer/stereo_viewer.h"

#include <mhd/plugin_abi.h>
#include <mhd/plugin_params.hpp>

#include <array>
#include <atomic>
#include <cstdint>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

namespace mhd::osg_stereo {
namespace {

using plugin_support::guarded;
using plugin_support::guarded_open;
using plugin_support::set_error;

struct Config {
  viewer::ViewerOptions options;
  std::optional<std::string> rig_file;
};

constexpr std::array kParams{
    sdk::boolean("stereo", "true", "side-by-side stereo, left eye in the left half"),
    sdk::number("ipd_m", "m", "0.064", "interpupillary distance", sdk::non_negative()),
    sdk::number("fov_deg", "deg", "90", "per-eye vertical field of view", sdk::above_up_to(0, 179)),
    sdk::integer("width", "px", "1600", "the window or image, both eyes", sdk::between(1, 16384)),
    sdk::integer("height", "px", "800", "the window or image", sdk::between(1, 16384)),
    sdk::boolean("offscreen", "false", "render into a pbuffer (still needs an X display, e.g. Xvfb)"),
    sdk::text("screenshot", nullptr, "a PNG written after 'frames' frames"),
    sdk::integer("frames", "", "0", "frames to render before the screenshot and exit; 0: until closed",
                 sdk::between(0, 1e9)),
    sdk::number("max_frame_rate_Hz", "Hz", "60", "the render thread's pace; 0: as fast as it draws",
                sdk::non_negative()),
    sdk::boolean("grid", "true", "a 1 m floor grid"),
    sdk::text("rig_file", nullptr, "a scene whose rig frames are drawn instead of the running scene's"),
};

Config read_config(const mhd_param* params, std::size_t count) {
  plugin_support::ParamReader reader(kParams, params, count);
  Config c;
  viewer::ViewerOptions& o = c.options;
  o.window_title = "MHD osg_stereo";
  const auto flag = [&](const char* name, bool fallback) {
    const std::optional<std::string> v = reader.optional_text(name);
    return v ? *v == "true" : fallback;  // the declaration has checked true|false
  };
  o.stereo = flag("stereo", o.stereo);
  o.ipd_m = reader.non_negative("ipd_m", o.ipd_m);
  o.fov_deg = reader.positive("fov_deg", o.fov_deg);
  o.width = static_cast<int>(reader.unsigned_integer("width", static_cast<std::uint64_t>(o.width), 16384));
  o.height = static_cast<int>(reader.unsigned_integer("height", static_cast<std::uint64_t>(o.height), 16384));
  o.offscreen = flag("offscreen", o.offscreen);
  if (auto screenshot = reader.optional_text("screenshot")) o.screenshot_png = *screenshot;
  o.frames = static_cast<int>(reader.unsigned_integer("frames", static_cast<std::uint64_t>(o.frames), 1000000000));
  o.max_frame_rate_Hz = reader.non_negative("max_frame_rate_Hz", o.max_frame_rate_Hz);
  o.show_grid = flag("grid", o.show_grid);
  c.rig_file = reader.optional_text("rig_file");
  reader.reject_unknown();
  if (std::string e = o.check(); !e.empty()) throw std::invalid_argument(e);
  return c;
}

struct Instance {
  viewer::ViewerOptions options;
  viewer::ViewerScene scene;
  std::shared_ptr<viewer::LatestStateSlot> slot = std::make_shared<viewer::LatestStateSlot>();
  std::atomic<bool> running{false};
  std::atomic<bool> stop_render{false};
  std::thread render_thread;
  std::string render_error;  ///< written by the render thread, read after join
};

/// The render thread: opens the viewer (reporting the outcome to start()), then draws.
void render(Instance& s, std::promise<std::string> opened) {
  viewer::StereoViewer::OpenResult r = viewer::StereoViewer::open(s.scene, s.options, s.slot);
  if (!r.viewer) {
    opened.set_value(r.error);
    return;
  }
  opened.set_value({});
  s.render_error = r.viewer->run(s.stop_render);
}

/// Stops and joins the render thread; the error it ended with, if any.
std::string join_render(Instance& s) {
  s.running.store(false);
  s.stop_render.store(true);
  if (s.render_thread.joinable()) s.render_thread.join();
  return std::exchange(s.render_error, {});
}

mhd_plugin_instance* open_instance(const mhd_host* host, const mhd_param* params, size_t count, mhd_error* err) {
  return guarded_open(err, [&] {
    plugin_support::check_host(host);
    if (host->scene_file == nullptr || *host->scene_file == '\0') {
      throw std::invalid_argument("the host gives no scene_file to draw");
    }
    Config config = read_config(params, count);
    viewer::ViewerSceneResult loaded = viewer::load_viewer_scene(
        host->scene_file, config.rig_file ? std::optional<std::filesystem::path>(*config.rig_file) : std::nullopt);
    if (!loaded.scene) throw std::runtime_error(loaded.errors.empty() ? "cannot load the scene" : loaded.errors.front());
    auto instance = std::make_unique<Instance>();
    instance->options = config.options;
    instance->scene = std::move(*loaded.scene);
    return reinterpret_cast<mhd_plugin_instance*>(instance.release());
  });
}

Instance& instance_of(mhd_plugin_instance* self) {
  if (self == nullptr) throw std::invalid_argument("instance is NULL");
  return *reinterpret_cast<Instance*>(self);
}

mhd_status start_instance(mhd_plugin_instance* self, mhd_error* err) {
  return guarded(err, [&] {
    Instance& s = instance_of(self);
    if (s.render_thread.joinable()) join_render(s);  // a restart after stop
    s.stop_render.store(false);
    std::promise<std::string> opened;
    std::future<std::string> outcome = opened.get_future();
    s.render_thread = std::thread(render, std::ref(s), std::move(opened));
    const std::string error = outcome.get();
    if (!error.empty()) {
      s.render_thread.join();
      throw std::runtime_error(error);
    }
    s.running.store(true);
    return MHD_OK;
  });
}

mhd_status stop_instance(mhd_plugin_instance* self, mhd_error* err) {
  return guarded(err, [&] {
    const std::string error = join_render(instance_of(self));
    if (!error.empty()) throw std::runtime_error(error);
    return MHD_OK;
  });
}

void close_instance(mhd_plugin_instance* self) noexcept {
  if (self == nullptr) return;
  std::unique_ptr<Instance> s(reinterpret_cast<Instance*>(self));
  join_render(*s);
}

// The haptic side's call: no lock, no allocation, no waiting.
mhd_status display_write(mhd_plugin_instance* self, const mhd_display_frame* frame, mhd_error* err) {
  if (self == nullptr || frame == nullptr) {
    set_error(err, "display_write: NULL instance or frame");
    return MHD_ERROR;
  }
  Instance& s = *reinterpret_cast<Instance*>(self);
  if (!s.running.load(std::memory_order_relaxed)) {
    set_error(err, MHD_PLUGIN_NAME " is not started");
    return MHD_ERROR;
  }
  return guarded(err, [&] {
    viewer::RigStateResult state = viewer::rig_state_from_frame(*frame);
    if (!state.state) throw std::invalid_argument(state.error);
    s.slot->publish(*state.state);
    return MHD_OK;
  });
}

constexpr mhd_plugin_api kApi = {
    .abi_version = MHD_PLUGIN_ABI_VERSION,
    .struct_size = sizeof(mhd_plugin_api),
    .kind = MHD_PLUGIN_KIND,
    .name = MHD_PLUGIN_NAME,
    .version = "1.0.0",
    .description = "OpenSceneGraph stereo (side-by-side) or mono view of the scene and the rig, drawn in its own thread",
    .open = open_instance,
    .start = start_instance,
    .stop = stop_instance,
    .close = close_instance,
    .params = kParams.data(),
    .param_count = kParams.size(),
    .device_info = nullptr,
    .device_read = nullptr,
    .device_write = nullptr,
    .tracker_read = nullptr,
    .base_read = nullptr,
    .base_write = nullptr,
    .display_write = display_write,
    .simulate_until = nullptr,
    .tracker_wait = nullptr,
    .counters = nullptr,
};

}  // namespace
}  // namespace mhd::osg_stereo

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  return host_abi_version == MHD_PLUGIN_ABI_VERSION ? &mhd::osg_stereo::kApi : nullptr;
}
