// `mhd strokes SCENE`: loads a scene and drives the scripted stroke set (the benchmark protocol of docs/benchmarks.md,
// protocol) through the god-object proxy at the haptic rate, without plugins or threads,
// then prints contacts, forces, update timings, an exact pop-through count (CGAL) and
// an exact follow-failure count (the proxy did not go to a HIP it could reach).
// The rendering check behind the figures in docs/benchmarks.md; `mhd run` is the server.

#include "strokes_command.h"

#include "command_scene.h"

#include "command_exit.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"
#include "verification/stroke_run.h"

#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

namespace {

struct StrokesOptions {
  std::string scene;
  int strokes = 200;
  std::uint64_t seed = 1;
  double speed_m_per_s = 0.5;
  double rate_Hz = 1000.0;
  bool no_cache = false;
  std::string touch;  ///< object whose surface anchors the strokes; empty: all objects
};

// Strokes anchored on one object: sampled on that object alone, kept only where the
// start is also clear of every other object (the proxy starts in free space).
mhd::verify::StrokeSet strokes_on_object(const mhd::CompiledScene& scene, int object,
                                         const mhd::verify::SurfaceCrossingOracle& whole_scene, std::uint64_t seed,
                                         int count, const mhd::verify::AnchorStrokeParams& params) {
  const mhd::verify::SurfaceCrossingOracle just_object(scene.world.shape(object).mesh(), scene.world.pose(object));
  mhd::verify::StrokeSet out;
  for (int round = 0; round < 8 && static_cast<int>(out.strokes.size()) < count; ++round) {
    auto candidates = mhd::verify::make_anchor_strokes(just_object, seed + static_cast<std::uint64_t>(round), count, params);
    for (auto& stroke : candidates.strokes) {
      const Eigen::Vector3d& start = stroke.p_W_hip.front();
      if (static_cast<int>(out.strokes.size()) == count) break;
      if (whole_scene.distance_to_surface(start) < params.min_start_clearance_m ||
          whole_scene.point_inside_closed_mesh(start)) {
        ++out.rejected;
        continue;
      }
      out.strokes.push_back(std::move(stroke));
    }
  }
  return out;
}

int run(const StrokesOptions& opt) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const std::optional<mhd::SceneDescription> read = mhd::cli::read_command_scene(opt.scene);
  if (!read) return 1;

  const std::unique_ptr<mhd::CompiledScene> compiled = mhd::cli::compile_command_scene(*read, !opt.no_cache);
  if (!compiled) return 1;
  const double load_s = std::chrono::duration<double>(Clock::now() - t0).count();
  const mhd::CompiledScene& scene = *compiled;
  fmt::print("scene {}: {} objects, {} triangles, touchable after {:.3f} s\n", opt.scene,
             scene.world.object_count(), scene.triangle_count, load_s);

  const mhd::verify::SurfaceCrossingOracle oracle(scene.world);
  mhd::verify::AnchorStrokeParams params;
  params.speed_m_per_s = opt.speed_m_per_s;
  params.rate_Hz = opt.rate_Hz;
  int touch_object = -1;
  if (!opt.touch.empty()) {
    for (std::size_t i = 0; i < scene.object_names.size(); ++i) {
      if (scene.object_names[i] == opt.touch) touch_object = static_cast<int>(i);
    }
    if (touch_object < 0) {
      fmt::print(stderr, "mhd strokes: error: scene {} has no object '{}'\n", opt.scene, opt.touch);
      return 1;
    }
  }
  const auto strokes = touch_object < 0
                           ? mhd::verify::make_anchor_strokes(oracle, opt.seed, opt.strokes, params)
                           : strokes_on_object(scene, touch_object, oracle, opt.seed, opt.strokes, params);
  const auto r = mhd::verify::run_strokes(scene, oracle, strokes, opt.rate_Hz);

  fmt::print("strokes: {} at {} m/s, {} Hz on {} (approach 20 mm -> 5 mm deep, slide 50 mm, retract)\n", r.strokes,
             opt.speed_m_per_s, opt.rate_Hz, opt.touch.empty() ? std::string("every object") : opt.touch);
  fmt::print("ticks: {}, in contact {} ({:.1f} %), up to {} constraint planes at once\n", r.ticks, r.contact_ticks,
             r.ticks > 0 ? 100.0 * static_cast<double>(r.contact_ticks) / static_cast<double>(r.ticks) : 0.0,
             r.max_plane_count);
  fmt::print("force: mean in contact {:.2f} N, max {:.2f} N (limit {:.2f} N), clamped on {} ticks\n",
             r.mean_contact_force_N, r.max_force_N, scene.proxy.max_force_N, r.clamped_ticks);
  for (std::size_t i = 0; i < r.contact_ticks_by_object.size(); ++i) {
    const std::size_t n = r.contact_ticks_by_object[i];
    if (n == 0) continue;
    fmt::print("  {}: {} contact ticks, mean force {:.2f} N (k = {:.0f} N/m, mu_s = {:.2f})\n", scene.object_names[i], n,
               r.force_sum_by_object_N[i] / static_cast<double>(n), scene.materials[i].stiffness_N_per_m,
               scene.materials[i].static_friction);
  }
  fmt::print("proxy update in contact: median {:.2f} us, p99 {:.2f} us, p99.9 {:.2f} us, max {:.1f} us\n",
             r.contact_updates.median_us, r.contact_updates.p99_us, r.contact_updates.p999_us,
             r.contact_updates.max_us);
  fmt::print("look-ahead between ticks (off the force's path): median {:.2f} us, p99 {:.2f} us, p99.9 {:.2f} us, "
             "max {:.1f} us\n",
             r.look_ahead_updates.median_us, r.look_ahead_updates.p99_us, r.look_ahead_updates.p999_us,
             r.look_ahead_updates.max_us);
  fmt::print("pop-throughs: {} proxy moves touched the surface, {} ticks ended inside (exact check); "
             "follow failures: {} ticks (largest free-space gap {:.3f} mm)\n",
             r.pop_throughs, r.ticks_inside, r.follow_failures, 1e3 * r.max_free_gap_m);
  fmt::print("held behind a surface: {} ticks (proxy over {:.0f} mm from the hand, a face's front towards the hand "
             "between them)\n",
             r.held_ticks, 1e3 * mhd::verify::kHeldGap_m);
  // A tick out of work stops its proxy short (docs/proxy.md, "The work budget"): what a
  // follow failure with no force is most likely to be.
  fmt::print("out of work: {} ticks (the tick's budget of sweeps and triangle tests ran out)\n",
             r.budget_exhausted_ticks);
  // Both halves of the proxy's contract (docs/proxy.md) decide the status.
  return r.pop_throughs == 0 && r.ticks_inside == 0 && r.follow_failures == 0 ? 0 : 1;
}

}  // namespace

void add_strokes_command(CLI::App& app) {
  auto opt = std::make_shared<StrokesOptions>();
  CLI::App* cmd = app.add_subcommand(
      "strokes", "Drive the scripted stroke set through the haptic proxy and count pop-throughs exactly");
  cmd->add_option("scene", opt->scene, "Scene XML file")->required()->check(CLI::ExistingFile);
  cmd->add_option("--strokes", opt->strokes, "Number of strokes")->check(CLI::Range(1, 1000000));
  cmd->add_option("--seed", opt->seed, "Random seed of the stroke set");
  cmd->add_option("--speed-mps", opt->speed_m_per_s, "HIP speed, m/s")->check(CLI::Range(1e-4, 10.0));
  cmd->add_option("--rate-hz", opt->rate_Hz, "Haptic update rate, Hz")->check(CLI::Range(10.0, 100000.0));
  cmd->add_option("--touch", opt->touch, "Anchor the strokes on this object only (default: every object)");
  cmd->add_flag("--no-cache", opt->no_cache, "Build every BVH instead of using the on-disk cache");
  cmd->callback([opt] { mhd::cli::exit_with(run(*opt)); });
}
