#include "try_command.h"

#include "load_progress.h"

#include "command_exit.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"
#include "viewer/hand_session.h"

#include <fmt/core.h>

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

struct TryOptions {
  std::string scene;
  std::string script;
  mhd::viewer::HandSessionOptions session;
  std::vector<double> start_m;
  std::vector<double> head_m;
  std::vector<double> look_at_m;
  bool no_cache = false;
};

std::optional<Eigen::Vector3d> vector3_of(const std::vector<double>& v) {
  if (v.size() != 3) return std::nullopt;
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

int run_try(TryOptions& o) {
  namespace v = mhd::viewer;
  std::vector<v::ScriptedEvent> script;
  if (!o.script.empty()) {
    mhd::Result<std::vector<v::ScriptedEvent>> read = v::read_input_script(o.script);
    if (!read.ok()) {
      fmt::print(stderr, "mhd try: {}\n", read.error_text());
      return 1;
    }
    script = std::move(read).value();
  }
  // The scene's objects and materials only: its plugins and rig frames are never opened.
  const mhd::Result<v::ViewerScene, std::vector<std::string>> loaded = v::load_viewer_scene(o.scene);
  if (!loaded.ok()) {
    for (const std::string& e : loaded.error()) fmt::print(stderr, "mhd try: {}\n", e);
    return 1;
  }
  v::ViewerScene scene{loaded->scene, std::nullopt, {}};
  mhd::CompileOptions compile_options;
  compile_options.use_cache = !o.no_cache;
  compile_options.progress = mhd::cli::stderr_load_progress();
  const mhd::Result<std::unique_ptr<mhd::CompiledScene>> compiled = mhd::compile_scene(scene.scene, compile_options);
  for (const auto& d : compiled.diagnostics()) fmt::print(stderr, "mhd try: {}\n", d.to_string());
  if (!compiled.ok()) return 1;

  v::HandSessionOptions& options = o.session;
  v::ViewerOptions& view = options.view;
  view.window_title = "MHD: try it by hand - " + o.scene;
  view.default_head_m = vector3_of(o.head_m);
  view.look_at_m = vector3_of(o.look_at_m);
  options.p_W_start_m = vector3_of(o.start_m);
  if (!view.screenshot_png.empty()) {
    view.offscreen = true;
    if (view.frames == 0) view.frames = 10;
    // A scripted screenshot depends on frame numbers only, not on how fast they come.
    view.max_frame_rate_Hz = 0.0;
  }
  mhd::Result<std::unique_ptr<v::HandSession>, std::string> opened =
      v::HandSession::open(scene, *compiled.value(), options);
  if (!opened.ok()) {
    fmt::print(stderr, "mhd try: error: {}\n", opened.error());
    return 1;
  }
  const std::unique_ptr<v::HandSession> session = std::move(opened).value();
  const std::atomic<bool> stop{false};
  if (const std::string e = session->run(script, stop); !e.empty()) {
    fmt::print(stderr, "mhd try: error: {}\n", e);
    return 1;
  }
  const v::HandSample& s = session->sample();
  fmt::print("{}: {} frames, {} ticks; HIP ({:.4f}, {:.4f}, {:.4f}) m, proxy ({:.4f}, {:.4f}, {:.4f}) m, "
             "force {:.3f} N, penetration {:.2f} mm, contact {}\n",
             o.scene, session->frames_drawn(), s.ticks, s.p_W_hip_m.x(), s.p_W_hip_m.y(), s.p_W_hip_m.z(),
             s.p_W_proxy_m.x(), s.p_W_proxy_m.y(), s.p_W_proxy_m.z(), s.force_W_N.norm(), 1e3 * s.penetration_m,
             s.in_contact ? "yes" : "no");
  if (!view.screenshot_png.empty()) {
    fmt::print("{}x{} mono image written to {}\n", view.width, view.height, view.screenshot_png);
  }
  return 0;
}

}  // namespace

void add_try_command(CLI::App& app) {
  auto o = std::make_shared<TryOptions>();
  o->session.view.fov_deg = 60.0;
  o->session.view.width = 1280;
  o->session.view.height = 800;
  o->session.view.force_scale_m_per_N = 0.02;
  CLI::App* cmd = app.add_subcommand(
      "try", "Try a scene by hand: the mouse and keys move the hand point, the engine's proxy shows the force");
  cmd->footer(
      "In the window: drag with the left button to move the hand point (HIP) in the plane parallel to the screen; "
      "the wheel (up: away from you), W/S or PageUp/PageDown move it in depth; R or Home puts it back; Esc quits. "
      "The proxy is stepped at 1 kHz of simulated time, a frame period of ticks per drawn frame. "
      "The scene's plugins are never opened. See docs/viewer.md, \"Try it by hand\".");
  cmd->add_option("scene", o->scene, "Scene XML file")->required()->check(CLI::ExistingFile);
  cmd->add_option("--script", o->script,
                  "Timed input events, one a line: FRAME press|drag|release X Y, FRAME scroll N, FRAME key K")
      ->check(CLI::ExistingFile);
  cmd->add_option("--screenshot", o->session.view.screenshot_png,
                  "Render offscreen and write the last frame to this PNG (needs an X display, e.g. xvfb-run -a)");
  cmd->add_option("--frames", o->session.view.frames, "Frames to draw before the screenshot / exit (0: until closed)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--start-m", o->start_m, "Where the HIP starts: x y z (metres, world); default: 10 cm in front of "
                                           "the first surface at the view's centre")
      ->expected(3);
  cmd->add_option("--force-scale-m-per-N", o->session.view.force_scale_m_per_N, "Force arrow length per newton")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--depth-step-m", o->session.depth_step_m, "HIP move per wheel notch or W/S key, metres")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--fov-deg", o->session.view.fov_deg, "Vertical field of view, degrees")->capture_default_str();
  cmd->add_option("--width", o->session.view.width, "Window or image width, pixels")->capture_default_str();
  cmd->add_option("--height", o->session.view.height, "Window or image height, pixels")->capture_default_str();
  cmd->add_option("--head-m", o->head_m, "Camera position: x y z (metres; default: back from the objects)")
      ->expected(3);
  cmd->add_option("--look-at-m", o->look_at_m, "Point the camera looks at: x y z (metres)")->expected(3);
  cmd->add_flag("--no-cache", o->no_cache, "Build every BVH instead of using the on-disk cache");
  cmd->callback([o] { mhd::cli::exit_with(run_try(*o)); });
}
