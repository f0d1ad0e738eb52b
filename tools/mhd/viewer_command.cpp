#include "viewer_command.h"

#include "command_exit.h"
#include "viewer/demo_state.h"
#include "viewer/stereo_viewer.h"
#ifdef MHD_HAVE_VIEWER_DDS
#include "viewer_dds/dds_state_source.h"
#endif

#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

struct ViewerCommandOptions {
  std::string scene;
  std::string rig;
  mhd::viewer::ViewerOptions view;
  bool mono = false;
  bool no_grid = false;
  bool observer = false;
  bool demo_state = false;
  std::vector<double> demo_base;
  std::vector<double> head_m;
  std::vector<double> look_at_m;
  // Network mode: the rig state of rig `rig_id` over DDS.
  std::uint32_t rig_id = 0;
  std::vector<std::uint32_t> other_rig_ids;  ///< drawn too; the view stays with rig_id's head
  std::uint32_t domain_id = 0;
  double stale_after_s = 1.0;
  CLI::Option* rig_id_option = nullptr;
  CLI::Option* domain_id_option = nullptr;
};

std::optional<Eigen::Vector3d> vector3(const std::vector<double>& v) {
  if (v.size() != 3) return std::nullopt;
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

#ifdef MHD_HAVE_VIEWER_DDS
/// Rig `rig_id`'s state over DDS; exits with the reason when it cannot subscribe.
std::shared_ptr<mhd::viewer::StateSource> dds_source(const ViewerCommandOptions& o, std::uint32_t rig_id) {
  mhd::viewer::DdsStateSourceOptions dds;
  dds.rig_id = rig_id;
  if (o.domain_id_option->count() > 0) dds.domain_id = o.domain_id;
  dds.stale_after_s = o.stale_after_s;
  const std::string domain =
      dds.domain_id ? "domain " + std::to_string(*dds.domain_id) : std::string("the default domain");
  try {
    auto source = std::make_shared<mhd::viewer::DdsStateSource>(dds);
    spdlog::info("drawing the rig state of rig {} from DDS ({})", rig_id, domain);
    return source;
  } catch (const std::exception& e) {
    fmt::print(stderr, "mhd viewer: error: cannot subscribe to the rig state of rig {} on {}: {}\n", rig_id, domain,
               e.what());
    mhd::cli::exit_with(1);
  }
  return nullptr;
}
#endif

void run_viewer(ViewerCommandOptions& o) {
  namespace v = mhd::viewer;
  const mhd::Result<v::ViewerScene, std::vector<std::string>> loaded =
      v::load_viewer_scene(o.scene, o.rig.empty() ? std::nullopt : std::optional<std::filesystem::path>(o.rig));
  if (!loaded.ok()) {
    for (const std::string& e : loaded.error()) fmt::print(stderr, "mhd viewer: {}\n", e);
    mhd::cli::exit_with(1);
  }
  for (const std::string& n : loaded->notes) spdlog::info("{}: {}", o.scene, n);

  v::ViewerOptions& view = o.view;
  view.stereo = !o.mono;
  view.show_grid = !o.no_grid;
  view.view_point = o.observer ? v::ViewPoint::Observer : v::ViewPoint::Head;
  view.default_head_m = vector3(o.head_m);
  view.look_at_m = vector3(o.look_at_m);
  if (!view.screenshot_png.empty()) {
    view.offscreen = true;
    if (view.frames == 0) view.frames = 10;
  }
  // The state source: the haptic server's rig state over DDS (network mode), a still
  // demo state, or none (scene only).
  std::shared_ptr<v::StateSource> source;
  if (o.rig_id_option->count() > 0) {
#ifdef MHD_HAVE_VIEWER_DDS
    source = dds_source(o, o.rig_id);
#else
    fmt::print(stderr, "mhd viewer: error: --rig-id needs DDS, and this mhd was built without Cyclone DDS\n");
    mhd::cli::exit_with(1);
#endif
  } else if (o.demo_state) {
    std::optional<mhd::BasePose> base;
    if (o.demo_base.size() == 3) base = mhd::BasePose{o.demo_base[0], o.demo_base[1], o.demo_base[2] * M_PI / 180.0};
    source = std::make_shared<v::FixedStateSource>(v::demo_rig_state(*loaded, base));
  }

  mhd::Result<std::unique_ptr<v::StereoViewer>, std::string> opened = v::StereoViewer::open(*loaded, view, source);
  if (!opened.ok()) {
    fmt::print(stderr, "mhd viewer: error: {}\n", opened.error());
    mhd::cli::exit_with(1);
  }
  const std::unique_ptr<v::StereoViewer> viewer = std::move(opened).value();
#ifdef MHD_HAVE_VIEWER_DDS
  for (const std::uint32_t other : o.other_rig_ids) viewer->add_rig(dds_source(o, other));
#endif
  const std::atomic<bool> stop{false};
  if (const std::string e = viewer->run(stop); !e.empty()) {
    fmt::print(stderr, "mhd viewer: error: {}\n", e);
    mhd::cli::exit_with(1);
  }
  if (!view.screenshot_png.empty()) {
    fmt::print("{}: {} frames, {}x{} {} image written to {}\n", o.scene, viewer->frames_drawn(), view.width,
               view.height, view.stereo ? "stereo" : "mono", view.screenshot_png);
  }
}

}  // namespace

void add_viewer_command(CLI::App& app) {
  auto options = std::make_shared<ViewerCommandOptions>();
  CLI::App* cmd = app.add_subcommand("viewer", "Draw a scene and the rig in stereo (side by side) or mono");
  cmd->add_option("scene", options->scene, "Scene XML file")->required()->check(CLI::ExistingFile);
  cmd->add_option("--screenshot", options->view.screenshot_png,
                  "Render offscreen and write the last frame to this PNG (needs an X display, e.g. xvfb-run -a)");
  cmd->add_option("--frames", options->view.frames, "Frames to draw before the screenshot / exit (0: until closed)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--mono", options->mono, "One view over the whole window instead of two eyes");
  cmd->add_option("--ipd-m", options->view.ipd_m, "Interpupillary distance, metres")->capture_default_str();
  cmd->add_option("--fov-deg", options->view.fov_deg, "Vertical field of view per eye, degrees")->capture_default_str();
  cmd->add_option("--width", options->view.width, "Window or image width, pixels (both eyes)")->capture_default_str();
  cmd->add_option("--height", options->view.height, "Window or image height, pixels")->capture_default_str();
  cmd->add_option("--rig", options->rig, "Take the rig frames from this file (e.g. scenes/rigs/pomhi.xml)")
      ->check(CLI::ExistingFile);
  cmd->add_flag("--no-grid", options->no_grid, "Leave out the floor grid");
  cmd->add_flag("--observer", options->observer, "View from a fixed observer pose that shows the user's head");
  cmd->add_flag("--demo-state", options->demo_state,
                "Draw a still rig state (base from the scene's sim_omni3, HIP at the workspace centre)");
  cmd->add_option("--demo-base", options->demo_base, "With --demo-state: the base at x_m z_m heading_deg")
      ->expected(3);
  options->rig_id_option =
      cmd->add_option("--rig-id", options->rig_id,
                      "Network mode: draw this rig's state, read over DDS (topic mhd_rig_state, e.g. from the "
                      "haptic server's dds_state display plugin)")
          ->excludes("--demo-state");
  cmd->add_option("--other-rig-id", options->other_rig_ids,
                  "With --rig-id: also draw these rigs' states (hand, base, user), read over DDS; the view stays "
                  "with --rig-id's head")
      ->needs(options->rig_id_option);
  options->domain_id_option = cmd->add_option("--domain-id", options->domain_id,
                                              "With --rig-id: the DDS domain (default: $CYCLONEDDS_URI's)")
                                  ->check(CLI::Range(0, 232))
                                  ->needs(options->rig_id_option);
  cmd->add_option("--stale-after-s", options->stale_after_s,
                  "With --rig-id: seconds without a state before the publisher is reported gone")
      ->check(CLI::PositiveNumber)
      ->needs(options->rig_id_option)
      ->capture_default_str();
  cmd->add_option("--head-m", options->head_m, "Eye position while no state arrives: x y z (metres)")->expected(3);
  cmd->add_option("--look-at-m", options->look_at_m, "Point that default head looks at: x y z (metres)")->expected(3);
  cmd->callback([options] { run_viewer(*options); });
}
