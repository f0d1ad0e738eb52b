// `mhd run SCENE [--duration S] [--record FILE]`: loads and compiles the scene, opens the
// plugins it names and runs the haptic server (engine/haptic_server) until the duration
// is over, Ctrl-C, or a fault. A status line shows the loop's rate, overruns, contact and
// force; the summary at the end gives the tick timings and every safety count.
// Exit status (docs/haptic_server.md, "How a run ends"): 0 for a clean run or one stopped
// by SIGINT/SIGTERM, 1 when the scene or a plugin cannot be opened, 3 when a fault ended
// the run (the message names the plugin and its scene line), 4 when the last gasp ended
// it (a plugin crashed, aborted, threw or called exit(); run_signals.h), 128 + the signal
// for a run stopped safely by SIGHUP or SIGQUIT.

#include "run_command.h"

#include "command_scene.h"

#include "command_exit.h"
#include "load_progress.h"
#include "output_path_check.h"
#include "run_signals.h"
#include "haptic_server/haptic_server.h"
#include "mesh_io/mesh_memory_lock.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"

#include <fmt/core.h>

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <exception>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace {

inline constexpr int kRunFault = 3;

struct RunOptions {
  std::string scene;
  double duration_s = 0.0;
  std::string record;
  std::vector<std::string> plugin_path;
  bool no_cache = false;
  bool quiet = false;
  bool lock_meshes = false;
};

/// " (plugin: stale 3, non_finite 1)" when the tracker plugin dropped samples itself.
std::string plugin_drops(const mhd::ServerStatus& s) {
  const std::string text = mhd::dropped_counts_text(s.tracker_plugin_counters);
  return text.empty() ? std::string() : " (plugin: " + text + ")";
}

void print_status(const mhd::ServerStatus& s, bool tty) {
  // A desktop rig has no tracker and no base: its line ends with the force.
  const std::string line = s.rig_kind == mhd::RigKind::Desktop
      ? fmt::format("t {:6.1f} s | {:6.0f} Hz | overruns {} | {} {:4.2f} N (gain {:.2f}) | desktop",
                    s.elapsed_s, s.haptic_rate_hz, s.overruns, s.in_contact ? "CONTACT" : "free   ", s.force_N,
                    s.safety_gain)
      : fmt::format(
      "t {:6.1f} s | {:6.0f} Hz | overruns {} | {} {:4.2f} N (gain {:.2f}) | tracker {} ms, {} samples, {} dropped{} | "
      "base ({:+.2f}, {:+.2f}) m {:+4.0f} deg",
      s.elapsed_s, s.haptic_rate_hz, s.overruns, s.in_contact ? "CONTACT" : "free   ", s.force_N, s.safety_gain,
      std::isfinite(s.tracker_age_s) ? fmt::format("{:.0f}", s.tracker_age_s * 1e3) : std::string("-"),
      s.tracker_samples, s.tracker_rejected, plugin_drops(s), s.base.x_m, s.base.z_m,
      s.base.heading_rad * 180.0 / 3.141592653589793);
  try {
    if (tty) {
      fmt::print(stderr, "\r{}\x1b[K", line);
    } else {
      fmt::print(stderr, "{}\n", line);
    }
    std::fflush(stderr);
  } catch (const std::exception&) {
    // A closed terminal or pipe never ends a run: the line is lost, nothing else.
  }
}

/// The name of a stop signal, for the summary.
const char* signal_name(int signal) {
  switch (signal) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    case SIGQUIT: return "SIGQUIT";
    default: return "a signal";
  }
}

void print_summary(const RunOptions& opt, const mhd::CompiledScene& scene, const mhd::ServerReport& r);

int run(const RunOptions& opt) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  mhd::cli::install_run_signal_handlers();
  const std::optional<mhd::SceneDescription> read = mhd::cli::read_command_scene(opt.scene);
  if (!read) return 1;
  if (!opt.record.empty()) {
    // The recording and its .meta beside it.
    for (const std::string& out : {opt.record, opt.record + ".meta"}) {
      if (const auto problem = mhd::cli::output_path_problem(out, mhd::cli::scene_inputs(*read))) {
        fmt::print(stderr, "mhd run: error: --record {}\n", *problem);
        return 1;
      }
    }
  }

  const std::unique_ptr<mhd::CompiledScene> compiled = mhd::cli::compile_command_scene(*read, !opt.no_cache);
  if (!compiled) return 1;
  const mhd::CompiledScene& scene = *compiled;
  // Before any plugin opens: a lock that fails ends the run with nothing started. Held
  // until the run is over (it goes before the scene it locks).
  mhd::LockedPages locked;
  if (opt.lock_meshes) {
    const mhd::MeshProgress progress = mhd::cli::stderr_load_progress();
    mhd::PageLock lock = mhd::lock_pages(mhd::mesh_memory_blocks(scene.world),
                                         [&](double f) { progress("locking the meshes in RAM", f); });
    if (lock.error) {
      fmt::print(stderr, "mhd run: error: --lock-meshes: {}\n", *lock.error);
      return 1;
    }
    locked = std::move(lock.pages);
  }

  mhd::ServerOptions options;
  options.duration_s = opt.duration_s;
  options.recording = opt.record;
  for (const auto& p : opt.plugin_path) options.plugin_path.emplace_back(p);
  const bool tty = isatty(STDERR_FILENO) != 0;
  if (!opt.quiet) {
    options.on_status = [tty](const mhd::ServerStatus& s) { print_status(s, tty); };
    options.status_interval_s = tty ? 0.2 : 1.0;
  }

  mhd::Result<mhd::OpenedServer> build = mhd::HapticServer::open(*read, scene, std::move(options));
  for (const auto& d : build.diagnostics()) fmt::print(stderr, "{}\n", d.to_string());
  if (!build.ok()) return 1;
  for (const auto& w : build->warnings) {
    fmt::print(stderr, "{}{}: warning: {}\n", w.where.file, w.where.line > 0 ? fmt::format(":{}", w.where.line) : "",
               w.message);
  }
  const double load_s = std::chrono::duration<double>(Clock::now() - t0).count();
  try {
    fmt::print("scene {}: {} objects, {} triangles, plugins open after {:.3f} s; haptic loop at {:.0f} Hz{}\n",
               opt.scene, scene.world.object_count(), scene.triangle_count, load_s,
               build->server->settings().haptic_rate_hz,
               opt.duration_s > 0.0 ? fmt::format(" for {} s", opt.duration_s) : std::string(" until Ctrl-C"));
    if (opt.lock_meshes) {
      fmt::print("meshes locked in RAM: {:.1f} MiB\n", static_cast<double>(locked.bytes()) / (1U << 20));
    }
    std::fflush(stdout);
  } catch (const std::exception&) {
    // stdout closed (`mhd run ... | head -1`): the run goes on.
  }

  if (!opt.record.empty()) {
    // For `mhd replay`: which scene this recording ran. And where its t_s = 0 falls in
    // Unix time: each process's host clock starts where its server opened, so recordings
    // of several processes (or of hosts on one synchronised clock) line up only on this.
    const auto unix_now = std::chrono::system_clock::now();
    const double host_s = build->server->host_now_s();
    const std::int64_t zero_unix_ns =
        std::chrono::duration_cast<std::chrono::nanoseconds>(unix_now.time_since_epoch()).count() -
        std::llround(host_s * 1e9);
    std::ofstream meta(opt.record + ".meta");
    meta << "scene=" << std::filesystem::absolute(opt.scene).lexically_normal().string() << "\n"
         << "host_clock_zero_unix_ns=" << zero_unix_ns << "\n";
  }
  mhd::cli::guard_server(build->server.get());
  const mhd::ServerReport r = [&] {
    try {
      return build->server->run();
    } catch (...) {
      std::terminate();  // the last gasp, naming the exception (run_signals.h)
    }
  }();
  mhd::cli::guard_server(nullptr);
  try {
    if (!opt.quiet && tty) fmt::print(stderr, "\n");
    print_summary(opt, scene, r);
  } catch (const std::exception&) {
    // stdout or stderr closed: the run itself ended safely; its status still says how.
  }
  if (r.error) {
    try {
      fmt::print(stderr, "mhd run: error: {}\n", *r.error);
    } catch (const std::exception&) {
    }
    return kRunFault;
  }
  const int signal = mhd::cli::stop_signal();
  return signal == SIGHUP || signal == SIGQUIT ? 128 + signal : 0;
}

// Each shared object where this rig left it, and what the rig sent and heard.
void print_shared_objects(const mhd::ServerReport& r) {
  for (const mhd::SharedObjectEnd& o : r.shared_objects) {
    const Eigen::Vector3d moved = o.p_W_end_m - o.p_W_start_m;
    fmt::print("shared object '{}' (id {}): authority rig {}{}; from ({:.3f}, {:.3f}, {:.3f}) to ({:.3f}, {:.3f}, "
               "{:.3f}) m, moved {:.3f} m",
               o.name, o.id, o.authority_rig, o.held_here ? " (this rig)" : "", o.p_W_start_m.x(), o.p_W_start_m.y(),
               o.p_W_start_m.z(), o.p_W_end_m.x(), o.p_W_end_m.y(), o.p_W_end_m.z(), moved.norm());
    if (o.held_here) {
      fmt::print("\n");
    } else {
      fmt::print("; last state {:.3f} s old\n", o.state_age_s);
    }
  }
  if (r.shared_objects.empty()) return;
  const mhd::SharingCounters& c = r.sharing;
  fmt::print("sharing: sent {} states, {} pushes; received {} states obeyed, {} ignored, {} pushes kept, {} ignored, "
             "{} for unknown objects; {} dropped between the haptic thread and the link\n",
             c.states_sent, c.pushes_sent, c.states_obeyed, c.states_ignored, c.pushes_kept, c.pushes_ignored,
             c.unknown_object, r.link_dropped);
}

void print_summary(const RunOptions& opt, const mhd::CompiledScene& scene, const mhd::ServerReport& r) {
  const mhd::ServerStatus& s = r.status;
  fmt::print("ran {:.2f} s: {} ticks ({:.1f} Hz), {} overruns, {} deadlines missed\n", s.elapsed_s, s.ticks,
             s.haptic_rate_hz, s.overruns, r.missed_deadlines);
  fmt::print("  overrun: a tick that ended after the next one was due, which then started late; deadline missed: "
             "a whole period skipped after an overrun, the loop keeping its time grid\n");
  fmt::print("haptic thread: {}; page faults while ticking: {} minor, {} major\n", r.haptic_scheduling,
             r.haptic_minor_page_faults, r.haptic_major_page_faults);
  fmt::print("tick (device read to device write): median {:.1f} us, p99 {:.1f} us, p99.9 {:.1f} us, max {:.1f} us\n",
             r.tick_median_us, r.tick_p99_us, r.tick_p999_us, r.tick_max_us);
  const bool desktop = s.rig_kind == mhd::RigKind::Desktop;
  if (desktop) {
    // No tracker: nothing starts up late or goes stale; the device's own faults remain.
    fmt::print("contact ticks {}; safety: {} fault, {} HIP jumps, {} clamped ticks\n", r.contact_ticks, r.fault_ticks,
               r.hip_jumps, r.clamped_ticks);
    fmt::print("  fault: non-finite tool position, HIP or force, force cut; HIP jump: force step faded in; "
               "clamped: force cut to the device's limit\n");
  } else {
    fmt::print("contact ticks {}; safety: {} start-up, {} stale, {} fault, {} HIP jumps, {} clamped ticks\n",
               r.contact_ticks, r.startup_ticks, r.stale_ticks, r.fault_ticks, r.hip_jumps, r.clamped_ticks);
    // Each count in words: a reader should not have to know the safety stage to read them.
    fmt::print("  start-up: before the first tracker sample, no force (normal); stale: tracking too old, force "
               "faded out; fault: non-finite tool position, HIP or force, force cut; HIP jump: force step faded in; "
               "clamped: force cut to the device's limit\n");
  }
  fmt::print("proxy work budget ({} sweeps, {} triangle tests per tick): exhausted on {} ticks\n",
             scene.proxy.max_sweeps_per_tick, scene.proxy.max_triangle_tests_per_tick,
             r.proxy_budget_exhausted_ticks);
  if (desktop) {
    fmt::print("rig: desktop (device fixed in the world; no tracker, base or planner)\n");
  } else {
    fmt::print("tracker: {} samples, {} dropped{}; {} ticks started by a new sample; base: {} commands ({} stops), "
               "ends at ({:.3f}, {:.3f}) m\n",
               s.tracker_samples, s.tracker_rejected, plugin_drops(s), s.early_ticks, r.base_commands, r.base_stops,
               s.base.x_m, s.base.z_m);
    const mhd::BaseStopCounts& why = r.base_stops_by_cause;
    fmt::print("base stops by cause: {} head stale, {} base stale, {} not finite; {} keep-out deflections\n",
               why.head_stale, why.base_stale, why.not_finite, why.keep_out_deflections);
  }
  if (!opt.record.empty()) {
    fmt::print("recording {}: {} rows, {} dropped\n", opt.record, r.recording_rows, r.recording_dropped);
  }
  print_shared_objects(r);
  if (desktop) {
    fmt::print("safe state: {}\n", r.zero_force_sent ? "zero force sent" : "ZERO FORCE NOT CONFIRMED");
  } else {
    fmt::print("safe state: {}, {}\n", r.zero_force_sent ? "zero force sent" : "ZERO FORCE NOT CONFIRMED",
               r.base_stop_sent ? "base stopped" : "BASE STOP NOT CONFIRMED");
  }
  if (const int signal = mhd::cli::stop_signal(); signal != 0 && r.ended_by == mhd::RunEnd::StopRequested) {
    fmt::print("stopped by {}\n", signal_name(signal));
  }
  std::fflush(stdout);
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto opt = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("run", "Run the haptic server on the scene's plugins (simulated or real hardware)");
  cmd->add_option("scene", opt->scene, "Scene XML file (with <rig>, <plugins> and optionally <simulated_user>)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--duration", opt->duration_s, "Seconds to run (default: until Ctrl-C)")->check(CLI::Range(0.0, 1e9));
  cmd->add_option("--record", opt->record, "Write a CSV recording of every haptic tick to this file");
  cmd->add_option("--plugin-path", opt->plugin_path, "Look for plugins in this folder first (repeatable)");
  cmd->add_flag("--no-cache", opt->no_cache, "Build every BVH instead of using the on-disk cache");
  cmd->add_flag("-q,--quiet", opt->quiet, "No status line");
  cmd->add_flag("--lock-meshes", opt->lock_meshes,
                "Lock the meshes' arrays and trees in RAM before the run starts, so that no haptic tick waits on a "
                "page fault (needs RLIMIT_MEMLOCK raised or CAP_IPC_LOCK)");
  cmd->callback([opt] { mhd::cli::exit_with(run(*opt)); });
}
