// `mhd proxy-replay SCENE.xml --hip-csv HIP.csv --out TICKS.csv`: replays a HIP path
// (engine/recording/hip_path_csv.h) through the scene's god-object proxy and materials,
// without plugins, safety or threads, and writes one row per tick (docs/proxy_replay.md).
// "What would this hand path feel like on that mesh", and how checks from outside drive
// the proxy. Deterministic: two runs differ only in step_us. Bad input is an error at
// file:line and leaves no output file.

#include "proxy_replay_command.h"

#include "command_scene.h"

#include "command_exit.h"
#include "output_path_check.h"
#include "staged_output_file.h"

#include "proxy/moving_world.h"
#include "proxy/proxy_start.h"
#include "recording/hip_path_csv.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

namespace {

constexpr const char* kTicksHeader =
    "t_s,hip_x_m,hip_y_m,hip_z_m,proxy_x_m,proxy_y_m,proxy_z_m,force_x_N,force_y_N,force_z_N,contact,planes,"
    "step_us,budget_exhausted";
/// dt of the first tick when the path has a single row.
constexpr double kSingleRowDt_s = 1e-3;

struct ProxyReplayOptions {
  std::string scene;
  std::string hip_csv;
  std::string out;
  bool no_cache = false;
};

void print_error(const mhd::Diagnostic& d) {
  if (d.where.line > 0) {
    fmt::print(stderr, "mhd proxy-replay: error: {}:{}: {}\n", d.where.file, d.where.line, d.message);
  } else {
    fmt::print(stderr, "mhd proxy-replay: error: {}: {}\n", d.where.file, d.message);
  }
}

struct ReplayTotals {
  long ticks = 0;
  long contact_ticks = 0;
  long budget_exhausted_ticks = 0;
  double max_force_N = 0.0;
  double max_step_us = 0.0;
};

/// Steps the proxy once and writes the tick's row.
/// Moving objects go to their poses at t_rel_s (from the path's first row) first.
void replay_tick(const mhd::CompiledScene& scene, mhd::MovingWorld& moving, mhd::ProxyState& state,
                 const mhd::HipPathSample& hip, double t_rel_s, double dt_s, std::FILE* out, ReplayTotals& totals) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  (void)moving.advance(t_rel_s, state, scene.proxy.skin_m);
  const mhd::ProxyOutput p = mhd::step_proxy(moving.world(), scene.materials, scene.proxy, state, hip.p_W_hip_m, dt_s,
                                             moving.twists());
  moving.apply_reaction(state, p.force_W);  // pushable objects are pushed back
  const double step_us = std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
  const Eigen::Vector3d& h = hip.p_W_hip_m;
  fmt::print(out, "{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{},{},{:.3f},{}\n",
             hip.t_s, h.x(), h.y(), h.z(), p.proxy_W.x(), p.proxy_W.y(), p.proxy_W.z(), p.force_W.x(), p.force_W.y(),
             p.force_W.z(), p.in_contact ? 1 : 0, p.plane_count, step_us, p.budget_exhausted ? 1 : 0);
  ++totals.ticks;
  if (p.in_contact) ++totals.contact_ticks;
  if (p.budget_exhausted) ++totals.budget_exhausted_ticks;
  totals.max_force_N = std::max(totals.max_force_N, p.force_W.norm());
  totals.max_step_us = std::max(totals.max_step_us, step_us);
}

int proxy_replay(const ProxyReplayOptions& opt) {
  // The path's header and first row first: a bad file fails before the scene compiles.
  mhd::HipPathCsvReader reader{std::filesystem::path(opt.hip_csv)};
  std::optional<mhd::HipPathSample> previous = reader.next();
  if (!previous) {
    print_error(*reader.error());
    return 1;
  }

  const std::optional<mhd::SceneDescription> read = mhd::cli::read_command_scene(opt.scene);
  if (!read) return 1;
  const std::unique_ptr<mhd::CompiledScene> compiled = mhd::cli::compile_command_scene(*read, !opt.no_cache);
  if (!compiled) return 1;
  const mhd::CompiledScene& scene = *compiled;

  mhd::MovingWorld moving(scene.world, scene.motions, scene.dynamics);
  moving.place(0.0);
  const double t_first_s = previous->t_s;
  if (const auto why = mhd::proxy_start_blocked(moving.world(), previous->p_W_hip_m, scene.proxy.skin_m)) {
    const Eigen::Vector3d& p = previous->p_W_hip_m;
    fmt::print(stderr, "mhd proxy-replay: error: {}:{}: the first HIP ({}, {}, {}) m {} in {}; the proxy must start in "
               "free space\n", opt.hip_csv, previous->line, p.x(), p.y(), p.z(), *why, opt.scene);
    return 1;
  }

  std::vector<std::filesystem::path> inputs = mhd::cli::scene_inputs(*read);
  inputs.emplace_back(opt.hip_csv);
  if (const auto problem = mhd::cli::output_path_problem(opt.out, inputs)) {
    fmt::print(stderr, "mhd proxy-replay: error: --out {}\n", *problem);
    return 1;
  }
  mhd::cli::StagedOutputFile out(opt.out);
  if (!out.ok()) {
    fmt::print(stderr, "mhd proxy-replay: error: {}\n", out.error());
    return 1;
  }
  fmt::print(out.stream(), "{}\n", kTicksHeader);

  mhd::ProxyState state;
  mhd::reset_proxy(state, previous->p_W_hip_m);
  ReplayTotals totals;
  // The first tick takes the second row's dt; every later one its own. One row of lookahead.
  std::optional<mhd::HipPathSample> current = reader.next();
  replay_tick(scene, moving, state, *previous, 0.0, current ? current->t_s - previous->t_s : kSingleRowDt_s,
              out.stream(), totals);
  while (current) {
    replay_tick(scene, moving, state, *current, current->t_s - t_first_s, current->t_s - previous->t_s, out.stream(),
                totals);
    previous = current;
    current = reader.next();
  }
  if (reader.error()) {
    print_error(*reader.error());
    return 1;  // `out` removes its temporary file
  }
  if (!out.commit()) {
    fmt::print(stderr, "mhd proxy-replay: error: {}\n", out.error());
    return 1;
  }
  fmt::print("replayed {} ticks of {} on {}: {} in contact, max force {:.3f} N, {} out of work budget, "
             "slowest step {:.1f} us\n",
             totals.ticks, opt.hip_csv, opt.scene, totals.contact_ticks, totals.max_force_N,
             totals.budget_exhausted_ticks, totals.max_step_us);
  fmt::print("wrote {}\n", opt.out);
  return 0;
}

}  // namespace

void add_proxy_replay_command(CLI::App& app) {
  auto opt = std::make_shared<ProxyReplayOptions>();
  CLI::App* cmd = app.add_subcommand(
      "proxy-replay",
      "Replay a HIP path (CSV t_s,x_m,y_m,z_m, world frame) through the scene's proxy; write a row per tick");
  cmd->add_option("scene", opt->scene, "Scene XML file")->required()->check(CLI::ExistingFile);
  cmd->add_option("--hip-csv", opt->hip_csv, "HIP path: header t_s,x_m,y_m,z_m, one row per tick, time increasing")
      ->required();
  cmd->add_option("--out", opt->out,
                  "Ticks CSV to write (t_s, HIP, proxy, force, contact, planes, step_us, budget_exhausted)")
      ->required();
  cmd->add_flag("--no-cache", opt->no_cache, "Build every BVH instead of using the on-disk cache");
  cmd->callback([opt] { mhd::cli::exit_with(proxy_replay(*opt)); });
}
