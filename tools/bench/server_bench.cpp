// mhd-server-bench: the haptic server's per-tick figures (docs/benchmarks.md).
//
//   tick  The whole haptic tick (predicted base pose -> rig chain -> proxy -> safety ->
//         torques) on the 1M-triangle dolphin at 10 kHz: the arm strokes in and out of the
//         dolphin's back along a smooth path (from 10 mm above the surface to --depth-m
//         below it; joint angles from the device's IK), a base pose arrives every 10 ms. Prints median, p99, p99.9 and max per tick; with
//         --realtime it also paces the ticks at 10 kHz on absolute deadlines and counts
//         overruns; with --look-ahead it looks ahead after each tick as the server does
//         and times that apart. --write-path writes the ticks' HIPs for
//         mhd-proxy-tick-probe, --write-times each tick's time, contact, planned depth,
//         distance off its planned point and proxy-to-HIP gap. (Following the surface
//         height, the path also drags the hand sideways through the back's ridge: about a
//         quarter of its ticks hold the proxy over 25 mm behind it; docs/benchmarks.md.)
//   leap  The HIP's leap per 1 kHz tick when a base pose arrives, the base driving at
//         0.2 m/s: IS-900-like samples at 100 Hz (2.5 mm, 0.4 deg noise; 4 ms latency plus
//         0-2 ms jitter), with prediction and with the newest sample held. The leap is the
//         HIP's step minus the true step, |(h_i - h_i-1) - (t_i - t_i-1)|.
//   overruns  The server's overruns beside the platform's own: the haptic server on a
//         scene (as `mhd run`, haptic thread at SCHED_FIFO 80) for --seconds, then a bare
//         loop at the same rate and priority that does nothing but sleep to its absolute
//         deadlines, for as long. A bare loop's overruns are wake-ups over one period late:
//         what the machine and its scheduler cost any real-time loop.

#include "haptic_server/haptic_server.h"
#include "haptic_server/haptic_tick.h"
#include "kinematics/phantom_kinematics.h"
#include "realtime/periodic_timer.h"
#include "realtime/thread_priority.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace mhd;

struct Loaded {
  std::optional<SceneDescription> description;
  std::optional<CompiledScene> scene;
  std::optional<Rig> rig;
};

Loaded load(const std::string& file) {
  Loaded l;
  auto read = read_scene_file(file);
  for (const auto& d : read.diagnostics()) fmt::print(stderr, "{}\n", d.to_string());
  if (!read.ok()) return l;
  auto compiled = compile_scene(*read);
  for (const auto& d : compiled.diagnostics()) fmt::print(stderr, "{}\n", d.to_string());
  if (!compiled.ok()) return l;
  auto rig = Rig::from_scene(*read);
  if (!rig.ok()) {
    fmt::print(stderr, "{}\n", rig.error_text());
    return l;
  }
  l.description = *read;
  l.scene = std::move(*compiled.value());
  l.rig = *rig;
  return l;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(std::min<double>(static_cast<double>(v.size() - 1), q * static_cast<double>(v.size())));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

struct TickBenchOptions {
  double seconds = 10.0;
  bool realtime = false;
  double depth_m = 0.015;
  bool look_ahead = false;
  std::string write_path;   ///< the ticks' HIPs, for mhd-proxy-tick-probe --hip-csv
  std::string write_times;  ///< each tick's time and contact
};

// One tick, for the files --write-path and --write-times write (outside the timed part).
struct TickRow {
  double tick_us = 0.0;
  bool contact = false;
  Eigen::Vector3d p_W_hip = Eigen::Vector3d::Zero();
  Eigen::Vector3d proxy_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d planned_W = Eigen::Vector3d::Zero();  ///< where the strokes meant the HIP to be
  double planned_depth_m = 0.0;                        ///< how far below the surface that is
};

// The HIPs as mhd-proxy-tick-probe and `mhd proxy-replay` read them, and each tick's time,
// contact and geometry beside them (row for row), so the probe's first/again costs can be
// set against them and a HIP off its planned stroke (an IK miss) seen.
bool write_tick_files(const TickBenchOptions& o, const std::vector<TickRow>& rows, double dt_s) {
  if (!o.write_path.empty()) {
    std::ofstream out(o.write_path);
    out << "t_s,x_m,y_m,z_m\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const Eigen::Vector3d& p = rows[i].p_W_hip;
      out << fmt::format("{:.17g},{:.17g},{:.17g},{:.17g}\n", static_cast<double>(i) * dt_s, p.x(), p.y(), p.z());
    }
    if (!out) {
      fmt::print(stderr, "error: cannot write {}\n", o.write_path);
      return false;
    }
  }
  if (!o.write_times.empty()) {
    std::ofstream out(o.write_times);
    out << "tick,tick_us,contact,planned_depth_mm,hip_off_plan_mm,proxy_to_hip_mm\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const TickRow& r = rows[i];
      out << fmt::format("{},{:.3f},{},{:.3f},{:.3f},{:.3f}\n", i, r.tick_us, r.contact ? 1 : 0, r.planned_depth_m * 1e3,
                         (r.p_W_hip - r.planned_W).norm() * 1e3, (r.proxy_W - r.p_W_hip).norm() * 1e3);
    }
    if (!out) {
      fmt::print(stderr, "error: cannot write {}\n", o.write_times);
      return false;
    }
  }
  return true;
}

int run_tick(const std::string& scene_file, const TickBenchOptions& o) {
  const double seconds = o.seconds, depth_m = o.depth_m;
  const bool realtime = o.realtime, look_ahead = o.look_ahead;
  Loaded l = load(scene_file);
  if (!l.scene) return 1;
  const Rig& rig = *l.rig;
  constexpr double kRate = 10000.0, kDt = 1.0 / kRate;
  HapticTick tick(*l.scene, rig, HapticTickSettings{});
  const BasePose base{0.05, -0.926, 0.0};  // the arm's workspace over the dolphin's back
  const Pose X_W_robot = rig.X_W_robot_from_base(base);
  const Pose sensor = rig.X_is900_base_sensor_from_base(base);
  const Eigen::Vector3d centre_W = rig.X_W_phantom(X_W_robot) * rig.device().usable_workspace().center_P_m();

  // The stroke path in the world; joint angles from IK, outside the timed part.
  const auto ticks = static_cast<std::size_t>(seconds * kRate);
  std::vector<Eigen::Vector3d> q(ticks);
  std::vector<Eigen::Vector3d> planned(ticks);  // where the strokes mean the HIP to be
  std::vector<double> planned_depth_m(ticks);   // how far below the surface that is
  Eigen::Vector3d last_q(0, 0.5, 0.2);
  // Strokes as a hand makes them: along the back, from 10 mm above the surface to
  // `depth_m` into it (at 600 N/m the force limit is 14 mm deep), the surface height found
  // by a vertical sweep under each point. `depth_m` is a bench option.
  const auto surface_y = [&](double x, double z) {
    const Eigen::Vector3d top(x, 2.0, z), bottom(x, 0.0, z);
    const auto hit = l.scene->world.sweep(top, bottom, 1e-6);
    return hit ? top.y() + hit->t_stop * (bottom.y() - top.y()) : 0.0;
  };
  for (std::size_t i = 0; i < ticks; ++i) {
    const double t = static_cast<double>(i) * kDt;
    const double x = centre_W.x() + 0.12 * std::sin(2.1 * t);
    const double z = centre_W.z() + 0.05 * std::sin(1.7 * t + 0.5);
    const double height = 0.01 - (0.01 + depth_m) * (0.5 - 0.5 * std::cos(3.3 * t));  // starts above
    const Eigen::Vector3d p(x, surface_y(x, z) + height, z);
    planned[i] = p;
    planned_depth_m[i] = -height;
    const PhantomIkSolution ik = phantom_inverse_kinematics(rig.device(), rig.p_P_from_W(X_W_robot, p));
    if (ik.status == PhantomIkStatus::Ok || ik.status == PhantomIkStatus::OutsideJointLimits) last_q = ik.q_rad;
    q[i] = last_q;
  }

  std::vector<double> us;
  us.reserve(ticks);
  std::vector<double> look_ahead_us;
  look_ahead_us.reserve(look_ahead ? ticks : 0);
  std::vector<TickRow> rows;
  rows.reserve(ticks);
  std::size_t contact = 0, waiting_inside = 0;
  const std::string scheduling = realtime ? realtime::make_current_thread_realtime(80).detail : "";
  realtime::PeriodicTimer timer(kDt);
  double t = 0.0;
  (void)tick.add_base_sensor_sample(t, sensor);
  for (std::size_t i = 0; i < ticks; ++i) {
    if (realtime) (void)timer.wait_next();
    t += kDt;
    const auto start = std::chrono::steady_clock::now();
    if (i % 100 == 0) (void)tick.add_base_sensor_sample(t - 0.004, sensor);
    const HapticTickOutput out = tick.tick(t, kDt, phantom_tool_position(rig.device().geometry, q[i]));
    const auto end = std::chrono::steady_clock::now();
    us.push_back(std::chrono::duration<double, std::micro>(end - start).count());
    if (out.in_contact) ++contact;
    if (out.hip_inside_object) ++waiting_inside;
    rows.push_back({us.back(), out.in_contact, out.p_W_hip, out.proxy_W_m, planned[i], planned_depth_m[i]});
    if (look_ahead) {  // as the haptic thread does once the force is out
      (void)tick.look_ahead();
      look_ahead_us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - end).count());
    }
  }
  fmt::print("tick on {} ({} triangles): {} ticks at 10 kHz{}, {:.1f} % in contact, {} ticks waiting for the "
             "hand to leave the object it started in\n",
             scene_file, l.scene->triangle_count, ticks, realtime ? " (paced)" : " (back to back)",
             100.0 * static_cast<double>(contact) / static_cast<double>(ticks), waiting_inside);
  fmt::print("  per tick: median {:.2f} us, p99 {:.2f} us, p99.9 {:.2f} us, max {:.1f} us\n", quantile(us, 0.5),
             quantile(us, 0.99), quantile(us, 0.999), *std::max_element(us.begin(), us.end()));
  if (look_ahead) {
    fmt::print("  look-ahead after each tick (not in the tick's time): median {:.2f} us, p99 {:.2f} us, p99.9 {:.2f} us, "
               "max {:.1f} us\n",
               quantile(look_ahead_us, 0.5), quantile(look_ahead_us, 0.99), quantile(look_ahead_us, 0.999),
               *std::max_element(look_ahead_us.begin(), look_ahead_us.end()));
  }
  if (realtime) {
    fmt::print("  paced at 10 kHz ({}): {} overruns, {} deadlines missed\n", scheduling, timer.stats().overruns,
               timer.stats().missed_deadlines);
  }
  return write_tick_files(o, rows, kDt) ? 0 : 1;
}

struct LeapFigures {
  double max_at_arrival_mm = 0.0;
  double max_any_mm = 0.0;
  double rms_mm = 0.0;
  double max_error_mm = 0.0;
};

LeapFigures run_leap(const Loaded& l, bool predict, double noise_m, std::uint64_t seed, double seconds) {
  const Rig& rig = *l.rig;
  HapticTickSettings settings;
  settings.predict_base_pose = predict;
  HapticTick tick(*l.scene, rig, settings);
  const BaseTwist twist{0.2, 0.0, 0.0};
  const BasePose start{-1.0, 2.0, 0.3};  // far from the dolphin: the HIP stays free
  const Eigen::Vector3d q(0.0, 0.5, 0.2);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> position_noise(0.0, noise_m);
  std::normal_distribution<double> heading_noise(0.0, noise_m > 0.0 ? 0.4 * std::numbers::pi / 180.0 : 0.0);
  std::uniform_real_distribution<double> jitter(0.0, 0.002);

  struct Pending {
    double arrive_s, measured_s;
    Pose sensor;
  };
  std::vector<Pending> pending;
  const auto truth = [&](double t) { return integrate_twist(start, twist, t); };
  const auto hip_true = [&](double t) { return rig.p_W_hip(rig.X_W_robot_from_base(truth(t)), q); };

  LeapFigures r;
  double sum_sq = 0.0;
  std::size_t scored = 0;
  Eigen::Vector3d previous_hip = Eigen::Vector3d::Zero(), previous_true = Eigen::Vector3d::Zero();
  bool has_previous = false;
  double next_sample_s = 0.0, next_command_s = 0.0;
  const auto ticks = static_cast<int>(seconds * 1000.0);
  for (int i = 1; i <= ticks; ++i) {
    const double t = 0.001 * i;
    while (next_sample_s <= t) {
      BasePose measured = truth(next_sample_s);
      measured.x_m += position_noise(rng);
      measured.z_m += position_noise(rng);
      measured.heading_rad += heading_noise(rng);
      pending.push_back({next_sample_s + 0.004 + jitter(rng), next_sample_s, rig.X_is900_base_sensor_from_base(measured)});
      next_sample_s += 0.01;
    }
    if (next_command_s <= t) {
      tick.add_base_command(t, twist);
      next_command_s += 0.1;
    }
    bool arrived = false;
    for (auto it = pending.begin(); it != pending.end();) {
      if (it->arrive_s <= t) {
        (void)tick.add_base_sensor_sample(it->measured_s, it->sensor);
        arrived = true;
        it = pending.erase(it);
      } else {
        ++it;
      }
    }
    const HapticTickOutput out = tick.tick(t, 0.001, phantom_tool_position(rig.device().geometry, q));
    const Eigen::Vector3d now_true = hip_true(t);
    if (has_previous && t > 1.0 && out.p_W_hip.allFinite()) {  // after a 1 s warm-up
      const double leap_mm = ((out.p_W_hip - previous_hip) - (now_true - previous_true)).norm() * 1e3;
      r.max_any_mm = std::max(r.max_any_mm, leap_mm);
      if (arrived) r.max_at_arrival_mm = std::max(r.max_at_arrival_mm, leap_mm);
      sum_sq += leap_mm * leap_mm;
      ++scored;
      r.max_error_mm = std::max(r.max_error_mm, (out.p_W_hip - now_true).norm() * 1e3);
    }
    previous_hip = out.p_W_hip;
    previous_true = now_true;
    has_previous = out.p_W_hip.allFinite();
  }
  r.rms_mm = scored > 0 ? std::sqrt(sum_sq / static_cast<double>(scored)) : 0.0;
  return r;
}

int run_leaps(const std::string& scene_file, double seconds, int seeds) {
  Loaded l = load(scene_file);
  if (!l.scene) return 1;
  fmt::print("HIP leap per 1 kHz tick, base at 0.2 m/s, 100 Hz samples, {} s x {} seeds\n", seconds, seeds);
  fmt::print("| tracker noise | base pose | max leap at a sample (mm) | max leap any tick (mm) | rms leap (mm) | max HIP error (mm) |\n");
  fmt::print("|---|---|---|---|---|---|\n");
  for (const double noise : {0.0, 0.0025}) {
    for (const bool predict : {true, false}) {
      LeapFigures worst;
      for (int s = 1; s <= seeds; ++s) {
        const LeapFigures r = run_leap(l, predict, noise, static_cast<std::uint64_t>(s), seconds);
        worst.max_at_arrival_mm = std::max(worst.max_at_arrival_mm, r.max_at_arrival_mm);
        worst.max_any_mm = std::max(worst.max_any_mm, r.max_any_mm);
        worst.rms_mm = std::max(worst.rms_mm, r.rms_mm);
        worst.max_error_mm = std::max(worst.max_error_mm, r.max_error_mm);
      }
      fmt::print("| {} | {} | {:.4f} | {:.4f} | {:.4f} | {:.2f} |\n", noise > 0 ? "2.5 mm, 0.4 deg" : "none",
                 predict ? "predicted" : "newest sample held", worst.max_at_arrival_mm, worst.max_any_mm, worst.rms_mm,
                 worst.max_error_mm);
    }
  }
  return 0;
}

}  // namespace

/// A loop at `rate_hz` on SCHED_FIFO `priority` (when allowed) that only sleeps to its
/// absolute deadlines for `seconds`: its timer's counts and each wake-up's lateness.
struct BareLoop {
  std::string scheduling;
  realtime::TimerStats stats;
  std::vector<double> late_us;
};

BareLoop run_bare_loop(double rate_hz, int priority, double seconds) {
  BareLoop loop;
  std::thread thread([&] {  // a thread of its own, as the haptic thread is
    loop.scheduling = realtime::make_current_thread_realtime(priority).detail;
    realtime::PeriodicTimer timer(1.0 / rate_hz);
    const auto ticks = static_cast<std::size_t>(seconds * rate_hz);
    loop.late_us.reserve(ticks);
    for (std::size_t i = 0; i < ticks; ++i) {
      const double deadline_s = timer.wait_next();
      loop.late_us.push_back((realtime::PeriodicTimer::monotonic_now_s() - deadline_s) * 1e6);
    }
    loop.stats = timer.stats();
  });
  thread.join();
  return loop;
}

int run_overruns(const std::string& scene_file, double seconds) {
  auto read = read_scene_file(scene_file);
  for (const auto& d : read.diagnostics()) fmt::print(stderr, "{}\n", d.to_string());
  if (!read.ok()) return 1;
  auto compiled = compile_scene(*read);
  for (const auto& d : compiled.diagnostics()) fmt::print(stderr, "{}\n", d.to_string());
  if (!compiled.ok()) return 1;
  ServerOptions options;
  options.duration_s = seconds;
  auto opened = HapticServer::open(*read, *compiled.value(), options);
  for (const auto& d : opened.diagnostics()) fmt::print(stderr, "{}\n", d.to_string());
  if (!opened.ok()) return 1;
  const double rate_hz = opened->server->settings().haptic_rate_hz;
  const ServerReport server = opened->server->run();
  if (server.error) {
    fmt::print(stderr, "{}\n", *server.error);
    return 1;
  }
  const BareLoop bare = run_bare_loop(rate_hz, 80, seconds);
  const double period_us = 1e6 / rate_hz;
  const auto over_a_period = std::count_if(bare.late_us.begin(), bare.late_us.end(),
                                            [&](double late_us) { return late_us > period_us; });
  fmt::print("over {:g} s at {:g} Hz, each in a thread of its own:\n", seconds, rate_hz);
  fmt::print("  server on {} ({}): {} overruns, {} deadlines missed in {} ticks; tick p99.9 {:.1f} us, max {:.1f} us\n",
             scene_file, server.haptic_scheduling, server.status.overruns, server.missed_deadlines,
             server.status.ticks, server.tick_p999_us, server.tick_max_us);
  fmt::print("  bare loop, no work ({}): {} overruns, {} deadlines missed in {} ticks; woken late by median {:.1f} us, "
             "p99 {:.1f} us, p99.9 {:.1f} us, max {:.1f} us; {} wake-ups over one period ({:g} us) late\n",
             bare.scheduling, bare.stats.overruns, bare.stats.missed_deadlines, bare.stats.ticks,
             quantile(bare.late_us, 0.5), quantile(bare.late_us, 0.99), quantile(bare.late_us, 0.999),
             *std::max_element(bare.late_us.begin(), bare.late_us.end()), over_a_period, period_us);
  return 0;
}

int main(int argc, char** argv) {
  CLI::App app{"Haptic server benchmarks: whole tick at 10 kHz, HIP leap with and without prediction, overruns",
               "mhd-server-bench"};
  app.require_subcommand(1);
  std::string scene = "scenes/benchmarks/server_dolphin_1m.xml";
  double seconds = 10.0;
  int seeds = 5;
  TickBenchOptions tick_options;
  CLI::App* tick = app.add_subcommand("tick", "Whole haptic tick on the 1M dolphin at 10 kHz");
  tick->add_option("--scene", scene, "Scene with a rig (default: the 1M dolphin server scene)");
  tick->add_option("--seconds", tick_options.seconds, "Simulated seconds (10 kHz ticks)");
  tick->add_option("--depth-m", tick_options.depth_m, "Deepest point of the strokes below the surface (default 0.015)");
  tick->add_flag("--realtime", tick_options.realtime, "Pace ticks at 10 kHz on absolute deadlines and count overruns");
  tick->add_flag("--look-ahead", tick_options.look_ahead,
                 "After each tick, look ahead as the server's haptic thread does (HapticTick::look_ahead), timed apart");
  tick->add_option("--write-path", tick_options.write_path,
                   "Write the ticks' HIPs (t_s,x_m,y_m,z_m) for mhd-proxy-tick-probe --hip-csv");
  tick->add_option("--write-times", tick_options.write_times, "Write each tick's time and contact (tick,tick_us,contact)");
  CLI::App* leap = app.add_subcommand("leap", "HIP leap when base poses arrive, with and without prediction");
  leap->add_option("--scene", scene, "Scene with a rig");
  leap->add_option("--seconds", seconds, "Simulated seconds per run");
  leap->add_option("--seeds", seeds, "Runs (noise seeds); the worst is reported");
  CLI::App* overruns = app.add_subcommand(
      "overruns", "The server's overruns beside a bare real-time loop's at the same rate, in one run");
  overruns->add_option("--scene", scene, "Scene to serve (default: the 1M dolphin server scene)");
  overruns->add_option("--seconds", seconds, "Seconds of each: the server, then the bare loop");
  CLI11_PARSE(app, argc, argv);
  if (tick->parsed()) return run_tick(scene, tick_options);
  if (overruns->parsed()) return run_overruns(scene, seconds);
  return run_leaps(scene, seconds, seeds);
}
