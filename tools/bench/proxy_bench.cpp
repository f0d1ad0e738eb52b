// mhd-proxy-bench: the ANCHORS.md protocol on each benchmark scene. 200 random strokes
// at 0.5 m/s and 1 kHz; per-update times (median / p99 / p99.9 / max, one core) over the
// ticks in contact and over all ticks (free-space transit included), the ticks that ran
// out of the proxy's work budget, the most sweeps in one tick, and the exact pop-through
// count. Prints a Markdown table.

#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"
#include "verification/stroke_run.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <cstdio>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  std::vector<std::string> scenes = {"scenes/benchmarks/dolphin_3k.xml", "scenes/benchmarks/bunny.xml",
                                     "scenes/benchmarks/dolphin_100k.xml", "scenes/benchmarks/dolphin_1m.xml",
                                     "scenes/benchmarks/uv_sphere_1m.xml"};
  int strokes = 200;
  std::uint64_t seed = 1;
  double speed = 0.5;
  double rate = 1000.0;
  CLI::App app{"Proxy update benchmark over the ANCHORS.md stroke protocol", "mhd-proxy-bench"};
  app.add_option("scenes", scenes, "Scene files (default: scenes/benchmarks/*)");
  app.add_option("--strokes", strokes, "Strokes per scene");
  app.add_option("--seed", seed, "Stroke seed");
  app.add_option("--speed-mps", speed, "Stroke speed, m/s");
  app.add_option("--rate-hz", rate, "Update rate, Hz");
  CLI11_PARSE(app, argc, argv);

  fmt::print("| scene | triangles | contact updates | median µs | p99 µs | p99.9 µs | max µs | all updates "
             "| all median µs | all p99 µs | all p99.9 µs | all max µs | budget exhausted | max sweeps "
             "| max planes | pop-throughs | ticks inside |\n");
  fmt::print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  int status = 0;
  for (const auto& file : scenes) {
    const auto read = mhd::read_scene_file(file);
    if (!read.ok()) {
      for (const auto& d : read.diagnostics) fmt::print(stderr, "{}\n", d.to_string());
      status = 1;
      continue;
    }
    const auto compiled = mhd::compile_scene(*read.scene);
    if (!compiled.ok()) {
      for (const auto& d : compiled.diagnostics) fmt::print(stderr, "{}\n", d.to_string());
      status = 1;
      continue;
    }
    const auto& scene = *compiled.scene;
    const mhd::verify::SurfaceCrossingOracle oracle(scene.world);
    mhd::verify::AnchorStrokeParams params;
    params.speed_m_per_s = speed;
    params.rate_Hz = rate;
    const auto set = mhd::verify::make_anchor_strokes(oracle, seed, strokes, params);
    const auto r = mhd::verify::run_strokes(scene, oracle, set, rate);
    const auto& c = r.contact_updates;
    const auto& a = r.all_updates;
    fmt::print("| {} | {} | {} | {:.2f} | {:.2f} | {:.2f} | {:.1f} | {} | {:.2f} | {:.2f} | {:.2f} | {:.1f} | {} | {} "
               "| {} | {} | {} |\n",
               file, scene.triangle_count, c.count, c.median_us, c.p99_us, c.p999_us, c.max_us, a.count, a.median_us,
               a.p99_us, a.p999_us, a.max_us, r.budget_exhausted_ticks, r.max_sweeps, r.max_plane_count,
               r.pop_throughs, r.ticks_inside);
    std::fflush(stdout);
    if (r.pop_throughs != 0 || r.ticks_inside != 0) status = 1;
  }
  return status;
}
