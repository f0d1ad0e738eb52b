// The osg_stereo display plugin: the viewer (tools/viewer) in a thread of its own.
// display_write() only converts the frame and publishes it into a lock-free
// latest-value slot, so the haptic side never waits for drawing; the render thread
// draws the newest state at up to 60 Hz. All OSG calls happen in the render thread.
// Parameters (all optional): stereo, ipd_m, fov_deg, width, height, offscreen,
// screenshot, frames, max_frame_rate_Hz, rig_file, grid. docs/viewer.md.

#include "sim_common/plugin_shell.h"
#include "viewer/stereo_viewer.h"

#include <mhd/plugin_abi.h>

#include <atomic>
#include <charconv>
#include <cmath>
#include <future>
#include <map>
#include <memory>
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

[[noreturn]] void bad(const std::string& name, const char* what, const std::string& value) {
  throw std::invalid_argument("parameter '" + name + "' must be " + what + ", got '" + value + "'");
}

double number(const std::string& name, const std::string& value) {
  double v = 0.0;
  const char* end = value.data() + value.size();
  const auto [ptr, ec] = std::from_chars(value.data(), end, v);
  if (ec != std::errc() || ptr != end || !std::isfinite(v)) bad(name, "a number", value);
  return v;
}

int integer(const std::string& name, const std::string& value) {
  int v = 0;
  const char* end = value.data() + value.size();
  const auto [ptr, ec] = std::from_chars(value.data(), end, v);
  if (ec != std::errc() || ptr != end) bad(name, "an integer", value);
  return v;
}

bool boolean(const std::string& name, const std::string& value) {
  if (value == "true") return true;
  if (value == "false") return false;
  bad(name, "true or false", value);
}

Config read_config(const mhd_param* params, std::size_t count) {
  if (params == nullptr && count != 0) throw std::invalid_argument("params is NULL");
  Config c;
  viewer::ViewerOptions& o = c.options;
  o.window_title = "MHD osg_stereo";
  for (std::size_t i = 0; i < count; ++i) {
    if (params[i].name == nullptr || params[i].value == nullptr) throw std::invalid_argument("a parameter is NULL");
    const std::string name = params[i].name;
    const std::string value = params[i].value;
    if (name == "stereo") {
      o.stereo = boolean(name, value);
    } else if (name == "ipd_m") {
      o.ipd_m = number(name, value);
    } else if (name == "fov_deg") {
      o.fov_deg = number(name, value);
    } else if (name == "width") {
      o.width = integer(name, value);
    } else if (name == "height") {
      o.height = integer(name, value);
    } else if (name == "offscreen") {
      o.offscreen = boolean(name, value);
    } else if (name == "screenshot") {
      o.screenshot_png = value;
    } else if (name == "frames") {
      o.frames = integer(name, value);
    } else if (name == "max_frame_rate_Hz") {
      o.max_frame_rate_Hz = number(name, value);
    } else if (name == "grid") {
      o.show_grid = boolean(name, value);
    } else if (name == "rig_file") {
      c.rig_file = value;
    } else {
      throw std::invalid_argument(
          "unknown parameter '" + name +
          "' (known: stereo, ipd_m, fov_deg, width, height, offscreen, screenshot, frames, max_frame_rate_Hz, "
          "grid, rig_file)");
    }
  }
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
    MHD_PLUGIN_ABI_VERSION,
    sizeof(mhd_plugin_api),
    MHD_PLUGIN_KIND,
    MHD_PLUGIN_NAME,
    "1.0.0",
    "OpenSceneGraph stereo (side-by-side) or mono view of the scene and the rig, drawn in its own thread",
    open_instance,
    start_instance,
    stop_instance,
    close_instance,
    nullptr,  // device_limits
    nullptr,  // device_read
    nullptr,  // device_write
    nullptr,  // tracker_read
    nullptr,  // base_read
    nullptr,  // base_write
    display_write,
    nullptr,  // simulate_until
    nullptr,  // tracker_wait
    nullptr,  // counters
};

}  // namespace
}  // namespace mhd::osg_stereo

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  return host_abi_version == MHD_PLUGIN_ABI_VERSION ? &mhd::osg_stereo::kApi : nullptr;
}
