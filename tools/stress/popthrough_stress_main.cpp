// mhd-popthrough-stress: throws random fast strokes (up to 1.5 m/s at 1 kHz, random
// directions, grazing angles, edges, creases and corners) at every object of every scene
// in scenes/ and of meshes named on the command line, through the engine's god-object
// proxy, and counts proxies found inside or behind a surface (exact CGAL oracle, plus
// the engine's own containment test) and follow failures: ticks where the proxy did not
// go to a HIP it could reach (verification/follow_check.h). A share of the strokes are
// continuous tours with free-space transits round the object. Long-running; never run
// by ctest. With --moving, each stroke chain gives the target object a random motion
// (twist, loop or ping-pong keyframes, up to --max-object-speed-mps and
// --max-object-rate-deg-s) and every tick is judged in each object's frame
// (moving_stress_run.h); with --pushed too, the object is a body the proxy pushes
// (pushed_stress_cli.h). Exit status 1 on any pop-through or follow failure, 2 on bad
// input. See docs/reliability/pop_through.md.

#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"
#include "stress/moving_stress_run.h"
#include "stress/pushed_stress_cli.h"
#include "stress/stress_run.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Scenes above this many triangles skip the engine's containment test under "auto".
constexpr std::size_t kAutoEngineTriangles = 200000;
// ... and below it ask on every n-th contact tick, n = triangles / this.
constexpr std::size_t kAutoEngineTrianglesPerStride = 5000;

struct Options {
  std::vector<std::string> scenes;
  std::vector<std::string> meshes;
  double mesh_scale = 0.001;
  bool no_scenes = false;
  std::vector<std::string> objects;
  std::size_t strokes = 100000;
  std::uint64_t seed = 1;
  double max_speed_mps = 1.5;
  double rate_hz = 1000.0;
  std::size_t chain = 8;
  std::string engine = "auto";
  double follow_tolerance_m = mhd::verify::kFollowTolerance_m;
  std::optional<std::size_t> replay;
  bool no_cache = false;
  bool moving = false;
  double max_object_speed_mps = 0.5;
  double max_object_rate_deg_s = 180.0;
  double object_excursion_m = 0.1;
  mhd::stress::PushedCli pushed;
};

// One input: a scene file, or a mesh file wrapped in a one-object scene.
struct Source {
  std::string file;
  bool is_mesh = false;
};

std::vector<Source> collect_sources(const Options& opt) {
  std::vector<Source> out;
  std::vector<std::string> roots = opt.scenes;
  if (roots.empty() && !opt.no_scenes) roots.emplace_back("scenes");
  for (const std::string& root : roots) {
    if (fs::is_directory(root)) {
      std::vector<std::string> files;
      for (const auto& entry : fs::recursive_directory_iterator(root)) {
        if (entry.is_regular_file() && entry.path().extension() == ".xml") files.push_back(entry.path().string());
      }
      std::sort(files.begin(), files.end());
      for (auto& f : files) out.push_back(Source{std::move(f), false});
    } else {
      out.push_back(Source{root, false});
    }
  }
  for (const std::string& m : opt.meshes) out.push_back(Source{m, true});
  return out;
}

// The scene description of a source; nullopt (with a message) when it has nothing to
// touch or does not load.
std::optional<mhd::SceneDescription> describe(const Source& src, const Options& opt, bool& error) {
  if (src.is_mesh) {
    mhd::SceneDescription d;
    d.file = fs::absolute(src.file);
    d.name = fs::path(src.file).stem().string();
    mhd::ObjectDescription o;
    o.name = d.name;
    o.shape = mhd::MeshSource{fs::absolute(src.file), Eigen::Vector3d::Constant(opt.mesh_scale)};
    d.objects.push_back(o);  // benchmark material: k = 1000 N/m, no friction, no shading
    return d;
  }
  mhd::Result<mhd::SceneDescription> read = mhd::read_scene_file(src.file);
  if (!read.ok()) {
    for (const auto& diag : read.diagnostics()) fmt::print(stderr, "{}\n", diag.to_string());
    fmt::print(stderr, "mhd-popthrough-stress: error: {}: scene does not load\n", src.file);
    error = true;
    return std::nullopt;
  }
  if (read->objects.empty()) {
    fmt::print(stderr, "mhd-popthrough-stress: skipping {}: no objects (an include, not a full scene)\n", src.file);
    return std::nullopt;
  }
  return std::move(read).value();
}

std::string reproducer(const Source& src, const Options& opt, const std::string& object, std::size_t stroke) {
  std::string line = "mhd-popthrough-stress ";
  if (src.is_mesh) {
    line += fmt::format("--no-scenes --mesh {} --mesh-scale {}", src.file, opt.mesh_scale);
  } else {
    line += src.file;
  }
  if (opt.moving) {
    line += fmt::format(" --moving --max-object-speed-mps {} --max-object-rate-deg-s {} --object-excursion-m {}",
                        opt.max_object_speed_mps, opt.max_object_rate_deg_s, opt.object_excursion_m);
    line += mhd::stress::pushed_reproducer_flags(opt.pushed);
  }
  return line + fmt::format(
                    " --object {} --seed {} --chain {} --max-speed-mps {} --rate-hz {} --follow-tolerance-m {} "
                    "--replay-stroke {}",
                    object, opt.seed, opt.chain, opt.max_speed_mps, opt.rate_hz, opt.follow_tolerance_m, stroke);
}

mhd::stress::MovingStressSettings moving_settings(const Options& opt) {
  mhd::stress::MovingStressSettings s;
  s.strokes = opt.strokes;
  s.seed = opt.seed;
  s.chain_length = opt.chain;
  s.stroke.max_speed_m_per_s = opt.max_speed_mps;
  s.stroke.rate_Hz = opt.rate_hz;
  s.motion.max_speed_mps = opt.max_object_speed_mps;
  s.motion.max_rate_radps = opt.max_object_rate_deg_s * std::numbers::pi / 180.0;
  s.motion.max_excursion_m = opt.object_excursion_m;
  mhd::stress::apply_pushed_options(opt.pushed, s);
  return s;
}

// One object under the moving stress: its table row (stdout), its counts by kind (stderr),
// its failures' reproducers. Returns whether it was clean.
bool stress_moving(const Source& src, const Options& opt, const mhd::CompiledScene& scene, int object,
                   std::vector<std::string>& reproducers) {
  const std::string& name = scene.object_names[static_cast<std::size_t>(object)];
  const std::uint64_t key = mhd::stress::name_key(scene.name + "/" + name);
  const auto settings = moving_settings(opt);
  if (opt.replay) {
    const auto r = mhd::stress::replay_moving_stroke(scene, object, key, settings, *opt.replay, stdout);
    const bool failed = !r.failures.empty() && r.failures.back().stroke == *opt.replay;
    fmt::print("{} / {}: stroke {}: {}\n", src.file, name, *opt.replay, failed ? "FAILED" : "clean");
    return r.clean();
  }
  const auto r = mhd::stress::stress_moving_object(scene, object, key, settings);
  fmt::print("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {:.3f} / {:.0f} / {:.2f} | "
             "{:.1f} | {:.1f} |\n",
             src.file, name, r.triangles, r.closed ? "yes" : "no", r.strokes, r.ticks, r.contact_ticks, r.push_ticks,
             r.strokes_with_push, r.squeeze_ticks, r.overlap_ticks, r.ride_ticks, r.crossing_ticks, r.inside_ticks, r.not_followed_ticks,
             r.free_force_ticks, r.max_object_speed_mps, r.max_object_rate_radps * 180.0 / std::numbers::pi,
             r.max_surface_speed_mps, 1e3 * r.max_hip_depth_m, r.seconds);
  std::fflush(stdout);
  if (opt.pushed.pushed) mhd::stress::print_pushed_reached(stderr, src.file, name, r);
  fmt::print(stderr, "  {} / {}: strokes by kind:", src.file, name);
  for (int k = 0; k < mhd::stress::kStrokeKindCount; ++k) {
    fmt::print(stderr, " {} {}", to_string(static_cast<mhd::stress::StrokeKind>(k)),
               r.strokes_by_kind[static_cast<std::size_t>(k)]);
  }
  fmt::print(stderr, "; {} chains:", r.chains);
  for (int k = 0; k < mhd::stress::kMotionKindCount; ++k) {
    fmt::print(stderr, " {} {}", to_string(static_cast<mhd::stress::MotionKind>(k)),
               r.chains_by_motion[static_cast<std::size_t>(k)]);
  }
  fmt::print(stderr, ", strokes");
  for (int k = 0; k < mhd::stress::kStrokeAnchorCount; ++k) {
    fmt::print(stderr, " {} {}", to_string(static_cast<mhd::stress::StrokeAnchor>(k)),
               r.chains_by_anchor[static_cast<std::size_t>(k)]);
  }
  fmt::print(stderr, "; {} proxy resets; most pushed stroke {} ({} push ticks): {}\n", r.resets, r.busiest_stroke,
             r.busiest_stroke_pushes, reproducer(src, opt, name, r.busiest_stroke));
  for (const auto& f : r.failures) {
    reproducers.push_back(fmt::format("{} / {}: stroke {} ({}, {} motion) tick {}: {}{}{}{}\n  reproduce: {}", src.file,
                                      name, f.stroke, to_string(f.kind), to_string(f.motion), f.tick,
                                      f.verdict.crossed ? "crossed " : "", f.verdict.inside ? "inside " : "",
                                      f.verdict.not_followed ? "not-followed " : "",
                                      f.verdict.free_force ? "free-space-force " : "",
                                      reproducer(src, opt, name, f.stroke)));
  }
  if (r.failing_strokes > r.failures.size()) {
    reproducers.push_back(
        fmt::format("{} / {}: ... and {} more failing strokes", src.file, name, r.failing_strokes - r.failures.size()));
  }
  return r.clean();
}

int run(const Options& opt) {
  using Clock = std::chrono::steady_clock;
  const auto t_start = Clock::now();
  mhd::stress::StressSettings settings;
  settings.strokes = opt.strokes;
  settings.seed = opt.seed;
  settings.chain_length = opt.chain;
  settings.stroke.max_speed_m_per_s = opt.max_speed_mps;
  settings.stroke.rate_Hz = opt.rate_hz;
  settings.follow_tolerance_m = opt.follow_tolerance_m;

  bool input_error = false;
  bool any_failure = false;
  std::size_t objects_run = 0;
  std::size_t objects_failed_to_run = 0;  // of objects_run
  std::vector<std::string> reproducers;
  if (!opt.replay && opt.moving) {
    fmt::print("strokes per object: {}, seed {}, up to {} m/s at {} Hz, chains of {}; moving objects: origin up to {} "
               "m/s, turning up to {} deg/s, keyframes within {} m\n\n",
               opt.strokes, opt.seed, opt.max_speed_mps, opt.rate_hz, opt.chain, opt.max_object_speed_mps,
               opt.max_object_rate_deg_s, opt.object_excursion_m);
    fmt::print("| source | object | triangles | closed | strokes | ticks | contact ticks | push ticks | strokes pushed | "
               "squeeze ticks | overlap ticks | ride ticks | crossings | inside | not followed | free-space force | "
               "object m/s / deg/s / surface m/s | max HIP depth mm | time s |\n");
    fmt::print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    std::fflush(stdout);
  } else if (!opt.replay) {
    fmt::print("strokes per object: {}, seed {}, up to {} m/s at {} Hz, chains of {}, engine containment: {}, "
               "follow tolerance {} mm\n\n",
               opt.strokes, opt.seed, opt.max_speed_mps, opt.rate_hz, opt.chain, opt.engine,
               1e3 * opt.follow_tolerance_m);
    fmt::print("| source | object | triangles | closed | strokes | ticks | contact ticks | inside | crossings | "
               "follow failures | max free-space gap mm | engine inside / asked | worst penetration mm | "
               "max HIP depth mm | step µs median / p99 / p99.9 / max | time s |\n");
    fmt::print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    std::fflush(stdout);
  }
  for (const Source& src : collect_sources(opt)) {
    const std::optional<mhd::SceneDescription> desc = describe(src, opt, input_error);
    if (!desc) continue;
    std::vector<int> selected;
    for (std::size_t i = 0; i < desc->objects.size(); ++i) {
      if (opt.objects.empty() ||
          std::find(opt.objects.begin(), opt.objects.end(), desc->objects[i].name) != opt.objects.end()) {
        selected.push_back(static_cast<int>(i));
      }
    }
    if (selected.empty()) continue;
    mhd::CompileOptions compile_options;
    compile_options.use_cache = !opt.no_cache;
    const mhd::Result<std::unique_ptr<mhd::CompiledScene>> compiled = mhd::compile_scene(*desc, compile_options);
    if (!compiled.ok()) {
      for (const auto& d : compiled.diagnostics()) fmt::print(stderr, "{}\n", d.to_string());
      fmt::print(stderr, "mhd-popthrough-stress: error: {}: does not compile\n", src.file);
      input_error = true;
      continue;
    }
    const mhd::CompiledScene& scene = *compiled.value();
    const mhd::verify::SurfaceCrossingOracle oracle(scene.world);
    // The engine's containment test sweeps a 1000 m ray whose bounding box covers much
    // of a mesh: on large meshes it costs up to milliseconds, so "auto" asks it on every
    // n-th contact tick (n = triangles / 5000) and leaves scenes over 200k triangles to
    // the exact oracle alone.
    settings.engine = opt.engine == "off"     ? mhd::stress::EngineContainment::Off
                      : opt.engine == "every" ? mhd::stress::EngineContainment::Every
                      : opt.engine == "auto" && scene.triangle_count > kAutoEngineTriangles
                          ? mhd::stress::EngineContainment::Off
                          : mhd::stress::EngineContainment::Contact;
    settings.engine_stride =
        opt.engine == "auto" ? std::max(1, static_cast<int>(scene.triangle_count / kAutoEngineTrianglesPerStride)) : 1;
    for (const int object : selected) {
      const std::string& name = scene.object_names[static_cast<std::size_t>(object)];
      const std::uint64_t key = mhd::stress::name_key(scene.name + "/" + name);
      ++objects_run;
      // The strokes are drawn where the engine and the exact oracle both find free space;
      // an object where the generator finds none in its draws ends its run with the
      // reason, not the program.
      try {
        if (opt.moving) {
          if (!stress_moving(src, opt, scene, object, reproducers)) any_failure = true;
          continue;
        }
        if (opt.replay) {
          const auto r = mhd::stress::replay_stroke(scene, oracle, object, key, settings, *opt.replay, stdout);
          const bool failed = !r.failures.empty() && r.failures.back().stroke == *opt.replay;
          const auto& v = failed ? r.failures.back().verdict : mhd::stress::TickVerdict{};
          fmt::print("{} / {}: stroke {}: {}\n", src.file, name, *opt.replay,
                     !failed                ? "clean"
                     : v.popped_through()   ? "POP-THROUGH"
                                            : "FOLLOW FAILURE");
          if (!r.clean()) any_failure = true;
          continue;
        }
        const auto r = mhd::stress::stress_object(scene, oracle, object, key, settings);
        fmt::print(
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {:.3f} | {} / {} | {:.6f} | {:.1f} | "
            "{:.2g} / {:.2g} / {:.2g} / {:.0f} | {:.1f} |\n",
            src.file, name, r.triangles, r.closed ? "yes" : "no", r.strokes, r.ticks, r.contact_ticks, r.inside_ticks,
            r.crossing_ticks, r.follow_failure_ticks, 1e3 * r.max_free_gap_m, r.inside_engine_ticks, r.engine_checks,
            1e3 * r.worst_penetration_m, 1e3 * r.max_hip_depth_m, r.step_median_us, r.step_p99_us, r.step_p999_us,
            r.step_max_us, r.seconds);
        std::fflush(stdout);
        fmt::print(stderr, "  {} / {}: strokes by kind:", src.file, name);
        for (int k = 0; k < mhd::stress::kStrokeKindCount; ++k) {
          fmt::print(stderr, " {} {} ({} failing)", to_string(static_cast<mhd::stress::StrokeKind>(k)),
                     r.strokes_by_kind[static_cast<std::size_t>(k)], r.failing_strokes_by_kind[k]);
        }
        fmt::print(stderr,
                   "; {} proxy resets; features: {} ridges/rims, {} creases, {} corners; up to {} planes; {} start "
                   "redraws; follow failures: {} ticks ({} stuck), longest {} ticks, force {:.3f} N at the largest "
                   "free-space gap; {} ticks whose way brushed a surface closer than the proxy's skin (not failures)\n",
                   r.resets, r.ridges, r.creases, r.corners, r.max_plane_count, r.start_redraws, r.follow_failure_ticks,
                   r.stuck_ticks, r.longest_follow_failure_ticks, r.force_at_max_free_gap_N, r.brushed_ticks);
        if (!r.clean()) {
          any_failure = true;
          for (const auto& f : r.failures) {
            reproducers.push_back(fmt::format(
                "{} / {}: stroke {} ({}) tick {}: {}{}{}{} depth {:.3e} m, proxy {:.3f} mm from the HIP{}\n"
                "  reproduce: {}",
                src.file, name, f.stroke, to_string(f.kind), f.tick, f.verdict.crossed ? "crossed " : "",
                f.verdict.inside ? "inside " : "", f.verdict.inside_engine ? "engine-inside " : "",
                f.verdict.follow_failed ? fmt::format("follow-{} ", to_string(f.verdict.follow_kind)) : std::string(),
                f.verdict.penetration_m, 1e3 * f.verdict.follow_gap_m,
                f.verdict.hip_in_free_view ? " (in free view)" : "", reproducer(src, opt, name, f.stroke)));
          }
          if (r.failing_strokes > r.failures.size()) {
            reproducers.push_back(fmt::format("{} / {}: ... and {} more failing strokes", src.file, name,
                                              r.failing_strokes - r.failures.size()));
          }
        }
      } catch (const std::exception& e) {
        fmt::print(stderr, "mhd-popthrough-stress: error: {} / {}: {}\n", src.file, name, e.what());
        input_error = true;
        ++objects_failed_to_run;
      }
    }
  }
  if (!opt.replay) {
    fmt::print("\n{} objects, {:.1f} s in all. ", objects_run,
               std::chrono::duration<double>(Clock::now() - t_start).count());
    if (objects_failed_to_run > 0) fmt::print("{} of them not stressed (errors above). ", objects_failed_to_run);
    fmt::print("{}\n", any_failure ? "FAILURES FOUND (crossed, inside: a pop-through; engine-inside alone: the engine's "
                                     "containment test called a proxy inside that the exact test found outside; "
                                     "follow-stuck / follow-free-space force: the proxy did not go to a HIP it "
                                     "could reach):"
                                   : "No pop-through, no follow failure.");
    for (const auto& line : reproducers) fmt::print("{}\n", line);
  }
  if (objects_run == 0) {
    fmt::print(stderr, "mhd-popthrough-stress: error: nothing to stress (no scene object matched)\n");
    return 2;
  }
  if (any_failure) return 1;
  return input_error ? 2 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  CLI::App app{"Pop-through stress: random fast strokes through the god-object proxy, checked exactly",
               "mhd-popthrough-stress"};
  app.add_option("scenes", opt.scenes, "Scene files or folders (default: scenes/, recursively)");
  app.add_option("--mesh", opt.meshes, "A mesh file to stress alone (repeatable)")->check(CLI::ExistingFile);
  app.add_option("--mesh-scale", opt.mesh_scale, "Metres per mesh-file unit (default 0.001: mm, as assets/)")
      ->check(CLI::PositiveNumber);
  app.add_flag("--no-scenes", opt.no_scenes, "Only the --mesh files, not scenes/");
  app.add_option("--object", opt.objects, "Only objects with this name (repeatable)");
  app.add_option("--strokes", opt.strokes, "Strokes per object")->check(CLI::Range(1, 100000000));
  app.add_option("--seed", opt.seed, "Random seed");
  app.add_option("--max-speed-mps", opt.max_speed_mps, "Fastest HIP speed, m/s")->check(CLI::Range(1e-3, 20.0));
  app.add_option("--rate-hz", opt.rate_hz, "Haptic rate, Hz")->check(CLI::Range(10.0, 100000.0));
  app.add_option("--chain", opt.chain, "Strokes per proxy reset (1: reset before every stroke)")
      ->check(CLI::Range(1, 1000000));
  app.add_option("--engine-containment", opt.engine,
                 "When to ask the engine's point_inside_surface too: off, contact (ticks in contact), every, "
                 "auto (contact, every n-th tick with n = scene triangles / 5000, off over 200k triangles)")
      ->check(CLI::IsMember({"off", "contact", "every", "auto"}));
  app.add_option("--follow-tolerance-m", opt.follow_tolerance_m,
                 "Gap a proxy that should be at the HIP may keep (and its spring force at the stiffest material)")
      ->check(CLI::PositiveNumber);
  app.add_option("--replay-stroke", opt.replay, "Rerun one stroke (and its chain) and print every tick");
  app.add_flag("--no-cache", opt.no_cache, "Build every BVH instead of using the on-disk cache");
  app.add_flag("--moving", opt.moving,
               "Move the stressed object: each chain a random twist or looping / ping-pong keyframes, the strokes "
               "riding with it, lagging behind it or still; every tick judged in each object's frame");
  app.add_option("--max-object-speed-mps", opt.max_object_speed_mps, "--moving: fastest speed of the object's origin")
      ->check(CLI::Range(0.0, 20.0));
  app.add_option("--max-object-rate-deg-s", opt.max_object_rate_deg_s, "--moving: fastest rotation, deg/s")
      ->check(CLI::Range(0.0, 720.0));
  app.add_option("--object-excursion-m", opt.object_excursion_m,
                 "--moving: how far a keyframed motion's keys move the object's centre")
      ->check(CLI::Range(0.0, 10.0));
  mhd::stress::add_pushed_options(app, opt.pushed);
  CLI11_PARSE(app, argc, argv);
  if (opt.pushed.pushed && !opt.moving) {
    fmt::print(stderr, "mhd-popthrough-stress: error: --pushed needs --moving\n");
    return 2;
  }
  return run(opt);
}
