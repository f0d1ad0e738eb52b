// mhd-moving-bench: the proxy's per-tick cost with moving objects (docs/benchmarks.md,
// "Moving objects"). For each object with a <motion>, a hand comes from the user's place in
// free space, waits in the object's way (at a random point near where the object passes,
// drawn from the seed) wandering slowly for a few seconds while the object pushes, carries
// and leaves it, and goes on to the next. Times MovingWorld::advance + step_proxy per tick
// (median / p99 / p99.9 / max, one core) over all ticks and over contact ticks, then
// replays the same path through verify::drive_moving_proxy for the exact counts
// (crossings, ticks inside, follow failures, squeezes). Prints a Markdown table.
// Pushable objects (<dynamics>) are visited too: waiting round where the body started, the
// hand pushes it about; the timed tick then includes its physics and the reaction.

#include "proxy/moving_world.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"
#include "verification/moving_drive.h"
#include "verification/stroke_run.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace {

using V = Eigen::Vector3d;

// Straight moves at speed_mps sampled at rate_Hz, appended to path.
void go(std::vector<V>& path, const V& to, double speed_mps, double rate_Hz) {
  const V from = path.back();
  const int n = std::max(1, static_cast<int>(std::ceil((to - from).norm() / (speed_mps / rate_Hz))));
  for (int i = 1; i <= n; ++i) path.push_back(from + (to - from) * (static_cast<double>(i) / n));
}

// The hand path: from `start`, to a waiting place near each moving object's track, a slow
// random wander there for wait_s, and on. Waiting places are drawn round the object's
// origin at a random time of its motion, within reach_m.
std::vector<V> hand_path(const mhd::CompiledScene& scene, const V& start, int visits, double wait_s, double reach_m,
                         std::uint64_t seed, double rate_Hz) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_real_distribution<double> when(0.0, 8.0);
  std::vector<int> moving;
  for (std::size_t i = 0; i < scene.motions.size(); ++i) {
    if (scene.motions[i] || scene.dynamics[i]) moving.push_back(static_cast<int>(i));
  }
  std::vector<V> path{start};
  if (moving.empty()) return path;
  for (int k = 0; k < visits; ++k) {
    const auto object = static_cast<std::size_t>(moving[static_cast<std::size_t>(k) % moving.size()]);
    const auto& motion = scene.motions[object];
    const double t_s = when(rng);
    const V origin = motion ? V(motion->X_WO_at(t_s).translation()) : V(scene.world.pose(static_cast<int>(object)).translation());
    const V place = origin + reach_m * V(u(rng), u(rng), u(rng));
    go(path, place, 0.3, rate_Hz);
    const int wander = static_cast<int>(wait_s * 4.0);  // a new heading every 0.25 s
    for (int w = 0; w < wander; ++w) go(path, place + 0.02 * V(u(rng), u(rng), u(rng)), 0.05, rate_Hz);
    go(path, start, 0.3, rate_Hz);
  }
  return path;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> scenes{"scenes/moving_objects.xml"};
  int visits = 30;
  double wait_s = 3.0;
  double reach_m = 0.09;
  std::uint64_t seed = 1;
  double rate = 1000.0;
  CLI::App app{"Proxy update benchmark with moving objects (docs/benchmarks.md, \"Moving objects\")",
               "mhd-moving-bench"};
  app.add_option("scenes", scenes,
                 "Scene files with moving or pushable objects (default: scenes/moving_objects.xml; "
                 "scenes/pushable_box.xml pushes a box)");
  app.add_option("--visits", visits, "Waits in a moving object's way, over the objects in turn");
  app.add_option("--wait-s", wait_s, "Seconds of each wait");
  app.add_option("--reach-m", reach_m, "How far from the object's origin a waiting hand may be");
  app.add_option("--seed", seed, "Seed of the waiting places and wanders");
  app.add_option("--rate-hz", rate, "Update rate, Hz");
  CLI11_PARSE(app, argc, argv);

  fmt::print("| scene | ticks | contact ticks | contact median µs | p99 µs | p99.9 µs | max µs | all median µs "
             "| all p99 µs | all p99.9 µs | all max µs | pushes | squeezes | crossings | ticks inside "
             "| follow failures |\n");
  fmt::print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  int status = 0;
  for (const auto& file : scenes) {
    const auto read = mhd::read_scene_file(file);
    if (!read.ok()) {
      fmt::print(stderr, "{}\n", read.error_text());
      status = 1;
      continue;
    }
    const auto compiled = mhd::compile_scene(*read);
    if (!compiled.ok()) {
      fmt::print(stderr, "{}\n", compiled.error_text());
      status = 1;
      continue;
    }
    const mhd::CompiledScene& scene = *compiled.value();
    const std::vector<V> path = hand_path(scene, V(0.0, 1.0, 0.0), visits, wait_s, reach_m, seed, rate);

    // Timed pass: what the haptic tick does, nothing else.
    mhd::MovingWorld moving(scene.world, scene.motions, scene.dynamics);
    moving.place(0.0);
    mhd::ProxyState state;
    mhd::reset_proxy(state, path.front());
    std::vector<double> all_us, contact_us;
    all_us.reserve(path.size());
    using Clock = std::chrono::steady_clock;
    for (std::size_t k = 1; k < path.size(); ++k) {
      const auto t0 = Clock::now();
      (void)moving.advance(static_cast<double>(k) / rate, state, scene.proxy.skin_m);
      const mhd::ProxyOutput out =
          mhd::step_proxy(moving.world(), scene.materials, scene.proxy, state, path[k], 1.0 / rate, moving.twists());
      moving.apply_reaction(state, out.force_W);
      const double us = std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
      all_us.push_back(us);
      if (out.in_contact) contact_us.push_back(us);
    }
    const auto a = mhd::verify::summarize_latency(all_us);
    const auto c = mhd::verify::summarize_latency(contact_us);
    // Judged pass: the same path, every tick checked exactly.
    const mhd::verify::MovingDrive d =
        mhd::verify::drive_moving_proxy(scene.world, scene.motions, scene.materials, scene.proxy, path, rate, scene.dynamics);
    fmt::print("| {} | {} | {} | {:.2f} | {:.2f} | {:.2f} | {:.1f} | {:.2f} | {:.2f} | {:.2f} | {:.1f} | {} | {} | {} "
               "| {} | {} |\n",
               file, a.count, c.count, c.median_us, c.p99_us, c.p999_us, c.max_us, a.median_us, a.p99_us, a.p999_us,
               a.max_us, d.pushes, d.squeezes, d.crossings, d.inside, d.not_followed + d.free_force);
    std::fflush(stdout);
    if (d.crossings != 0 || d.inside != 0 || d.not_followed + d.free_force != 0) status = 1;
  }
  return status;
}
