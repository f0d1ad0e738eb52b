// mhd-proxy-tick-probe: what each tick of a HIP path costs, and why. Replays a path
// (`mhd-proxy-bench --write-path`, or any `mhd proxy-replay` HIP CSV) through step_proxy and
// writes one row per tick: its time as it came (first_us: the caches hold what the earlier
// ticks left there), the least time of the same tick run again from a copy of the state
// (again_us: everything it needs is in the cache), and what it did (sweeps, those answered
// at once, triangle tests, candidate-list gathers, planes). A tick slow the first time and
// fast again waited on memory; one slow both times did work. --evict-every N streams
// 64 MiB through the cache before every Nth tick that follows a contact tick (column
// `evicted`), for ticks that start with nothing cached. --look-ahead steps the look-ahead
// after each tick, as the haptic server does (proxy/proxy_look_ahead.h), so that first_us
// is what a tick costs there. Diagnostic only: not run by ctest, no targets.

#include "proxy/god_object.h"
#include "proxy/proxy_look_ahead.h"
#include "recording/hip_path_csv.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

namespace {

constexpr std::size_t kEvictBytes = std::size_t{64} << 20;
constexpr std::size_t kCacheLineBytes = 64;

}  // namespace

int main(int argc, char** argv) {
  std::string scene_file;
  std::string hip_csv;
  std::string out_csv;
  int repeats = 3;
  int evict_every = 0;
  bool look_ahead = false;
  CLI::App app{"Per-tick cost of the proxy on a HIP path: first run against repeated run, with the tick's work",
               "mhd-proxy-tick-probe"};
  app.add_option("scene", scene_file, "Scene XML file")->required();
  app.add_option("--hip-csv", hip_csv, "HIP path (t_s,x_m,y_m,z_m), e.g. from mhd-proxy-bench --write-path")
      ->required();
  app.add_option("--out", out_csv, "Per-tick CSV to write")->required();
  app.add_option("--repeats", repeats, "Runs of each tick from a copy of its state, for again_us (0: none)");
  app.add_option("--evict-every", evict_every, "Evict the caches before every Nth tick after a contact tick (0: never)");
  app.add_flag("--look-ahead", look_ahead, "Look ahead after each tick, as the haptic server does");
  CLI11_PARSE(app, argc, argv);

  const auto read = mhd::read_scene_file(scene_file);
  for (const auto& d : read.diagnostics()) fmt::print(stderr, "{}\n", d.to_string());
  if (!read.ok()) return 1;
  const auto compiled = mhd::compile_scene(*read);
  for (const auto& d : compiled.diagnostics()) fmt::print(stderr, "{}\n", d.to_string());
  if (!compiled.ok()) return 1;
  const auto& scene = *compiled.value();

  mhd::HipPathCsvReader reader{std::filesystem::path(hip_csv)};
  std::vector<Eigen::Vector3d> hips_W;
  std::vector<double> times_s;
  while (const auto sample = reader.next()) {
    hips_W.push_back(sample->p_W_hip_m);
    times_s.push_back(sample->t_s);
  }
  if (reader.error()) {
    fmt::print(stderr, "mhd-proxy-tick-probe: {}\n", reader.error()->to_string());
    return 1;
  }
  if (hips_W.empty()) return 1;
  std::FILE* out = std::fopen(out_csv.c_str(), "w");
  if (out == nullptr) {
    fmt::print(stderr, "mhd-proxy-tick-probe: cannot write {}\n", out_csv);
    return 1;
  }

  std::vector<unsigned char> junk(evict_every > 0 ? kEvictBytes : 0, 1);
  unsigned sink = 0;
  fmt::print(out, "tick,first_us,again_us,contact,planes,sweeps,sweeps_at_once,triangle_tests,gathers,candidates,"
                  "after_contact,hip_step_mm,proxy_to_hip_mm,proxy_step_mm,evicted\n");
  mhd::ProxyState state;
  mhd::reset_proxy(state, hips_W.front());
  mhd::ProxyLookAhead ahead;
  using Clock = std::chrono::steady_clock;
  bool after_contact = false;
  long contact_followers = 0;
  for (std::size_t i = 0; i < hips_W.size(); ++i) {
    const double dt_s = i > 0 ? times_s[i] - times_s[i - 1] : (hips_W.size() > 1 ? times_s[1] - times_s[0] : 1e-3);
    const bool evicted = evict_every > 0 && after_contact && (contact_followers++ % evict_every) == 0;
    if (evicted) {
      for (std::size_t k = 0; k < junk.size(); k += kCacheLineBytes) sink += junk[k]++;
    }
    const mhd::ProxyState before = state;
    const int gathers_before = state.near.gathers();
    const auto t0 = Clock::now();
    const mhd::ProxyOutput o = mhd::step_proxy(scene.world, scene.materials, scene.proxy, state, hips_W[i], dt_s);
    const double first_us = std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
    double again_us = 0.0;
    for (int r = 0; r < repeats; ++r) {
      mhd::ProxyState copy = before;
      const auto t1 = Clock::now();
      (void)mhd::step_proxy(scene.world, scene.materials, scene.proxy, copy, hips_W[i], dt_s);
      const double us = std::chrono::duration<double, std::micro>(Clock::now() - t1).count();
      again_us = r == 0 ? us : std::min(again_us, us);
    }
    const Eigen::Vector3d& p_W_hip_previous = hips_W[i > 0 ? i - 1 : 0];
    fmt::print(out, "{},{:.3f},{:.3f},{},{},{},{},{},{},{},{},{:.4f},{:.4f},{:.4f},{}\n", i, first_us, again_us,
               o.in_contact ? 1 : 0, o.plane_count, o.sweeps, o.sweeps_at_once, o.triangle_tests,
               state.near.gathers() - gathers_before, state.near.size(), after_contact ? 1 : 0,
               (hips_W[i] - p_W_hip_previous).norm() * 1e3, (o.proxy_W - hips_W[i]).norm() * 1e3,
               (o.proxy_W - before.proxy_W).norm() * 1e3, evicted ? 1 : 0);
    after_contact = o.in_contact;
    if (look_ahead) (void)ahead.run(scene.world, scene.materials, scene.proxy, state, dt_s);
  }
  std::fclose(out);
  // The evicting reads must not be optimised away.
  return sink == 1U ? 2 : 0;
}
