#include "haptic_server/haptic_server.h"

#include "haptic_server/base_command_scheduler.h"
#include "haptic_server/haptic_tick.h"
#include "haptic_server/head_state.h"
#include "haptic_server/physical_range.h"
#include "haptic_server/plugin_watchdog.h"
#include "haptic_server/safe_stop.h"
#include "haptic_server/scene_planner.h"
#include "haptic_server/shared_value.h"
#include "haptic_server/status_counters.h"
#include "haptic_server/tick_histogram.h"
#include "haptic_server/tracker_sample_filter.h"
#include "haptic_server/user_motion_estimate.h"
#include "kinematics/rig.h"
#include "plugin_host/host_services.h"
#include "plugin_host/open_plugin.h"
#include "plugin_host/plugin_kind.h"
#include "plugin_host/plugin_search_path.h"
#include "realtime/periodic_timer.h"
#include "realtime/spsc_ring.h"
#include "realtime/thread_name.h"
#include "realtime/thread_priority.h"
#include "realtime/triple_buffer.h"
#include "realtime/wake_event.h"
#include "recording/csv_recording.h"
#include "safety/base_command_guard.h"
#include "simulation/simulated_user.h"
#include "simulation/simulated_user_params.h"
#include "simulation/simulated_world.h"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <ctime>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>

namespace mhd {
namespace {

struct BaseSensorSample {
  double t_s = 0.0;
  Pose X_is900_base_sensor = Pose::Identity();
};

struct BaseCommandEvent {
  double t_s = 0.0;
  BaseTwist twist_B;
};

/// State the haptic thread publishes each tick (for the planner and the displays).
struct HapticSnapshot {
  double t_s = 0.0;
  bool valid = false;  ///< a HIP is known
  Eigen::Vector3d hip_W_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d proxy_W_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_W_N = Eigen::Vector3d::Zero();
  bool in_contact = false;
  BasePose base;
};

struct OpenedPlugin {
  PluginDescription description;
  PluginInstance instance;
  /// "plugin 'x' (scene.xml:12)", made at open: a crash message names the plugin without allocating.
  std::string culprit = description.where.line > 0
                            ? fmt::format("plugin '{}' ({}:{})", description.name, description.where.file,
                                          description.where.line)
                            : fmt::format("plugin '{}' ({})", description.name, description.where.file);
  std::unique_ptr<CallWatch> watch = std::make_unique<CallWatch>();
  /// Held around every call to this plugin from a server thread, so run()'s thread can
  /// send the base its stop while the io thread is stuck inside another plugin.
  std::unique_ptr<std::mutex> call_mutex = std::make_unique<std::mutex>();
};

/// The plugin call in progress on this thread: the last gasp names it when the thread dies.
thread_local const OpenedPlugin* t_plugin_in_call = nullptr;
thread_local const char* t_call_in_progress = nullptr;
/// Set on the server's own threads (haptic, io, planner, display).
thread_local bool t_server_thread = false;

/// Marks `plugin` as inside `call` for as long as it lives, for the watchdog and, on this
/// thread, for the last gasp. An exception leaving the call keeps the thread's mark, so
/// std::terminate can still name the plugin it came from.
class InCall {
 public:
  InCall(OpenedPlugin& plugin, const char* call, double now_s) noexcept
      : watch_(*plugin.watch), outer_plugin_(t_plugin_in_call), outer_call_(t_call_in_progress),
        exceptions_(std::uncaught_exceptions()) {
    watch_.call.store(call, std::memory_order_relaxed);
    watch_.since_s.store(now_s, std::memory_order_release);
    t_plugin_in_call = &plugin;
    t_call_in_progress = call;
  }
  ~InCall() {
    watch_.since_s.store(0.0, std::memory_order_release);
    if (std::uncaught_exceptions() > exceptions_) return;
    t_plugin_in_call = outer_plugin_;
    t_call_in_progress = outer_call_;
  }
  InCall(const InCall&) = delete;
  InCall& operator=(const InCall&) = delete;

 private:
  CallWatch& watch_;
  const OpenedPlugin* outer_plugin_;
  const char* outer_call_;
  int exceptions_;
};

/// The last gasp's claim on the plugins: run() arms it while plugins may be driven, and
/// exactly one of run() (to stop and close them) and a dying thread (to send the zeros) wins.
enum GaspState : int { kGaspIdle, kGaspArmed, kGaspSending, kGaspDone };

std::string plugin_failure(const PluginDescription& d, const PluginError& e) {
  return Diagnostic{d.where, e.to_string()}.to_string();
}

}  // namespace

struct HapticServer::Impl {
  const CompiledScene& scene;
  ServerSettings settings;
  ServerOptions options;
  Rig rig;
  std::optional<simulation::SimulatedUserConfig> user_config;

  simulation::SimulatedWorld world;
  HostServices host;
  std::vector<OpenedPlugin> plugins;  // device first, then tracker, base, displays
  OpenedPlugin* device = nullptr;
  OpenedPlugin* tracker = nullptr;
  OpenedPlugin* base = nullptr;
  std::vector<OpenedPlugin*> displays;

  // Hand-offs.
  realtime::SpscRing<BaseSensorSample> base_samples{512};
  realtime::SpscRing<BaseCommandEvent> commands_to_haptic{64};
  realtime::SpscRing<RecordingRow> recording_rows{1 << 14};
  realtime::TripleBuffer<HapticSnapshot> snapshot_for_planner;
  realtime::TripleBuffer<HapticSnapshot> snapshot_for_display;
  realtime::TripleBuffer<HapticSnapshot> snapshot_for_io;  ///< the base pose the guard judges
  SharedValue<HeadState> head;
  SharedValue<std::pair<std::uint64_t, BaseTwist>> planned_command;  // sequence, twist
  realtime::WakeEvent base_sample_arrived;  ///< io -> haptic: start the tick now
  bool tick_on_tracker_sample = false;      ///< set by run(): the tracker can wake the io thread

  // Status, written by the haptic, io and planner threads, read by run().
  StatusCounters status_counters;
  // For the report only.
  std::atomic<std::uint64_t> missed{0}, contact_ticks{0}, proxy_budget_exhausted_ticks{0}, recording_dropped{0};
  std::atomic<std::uint64_t> base_commands{0}, base_stops{0};
  SharedValue<BaseStopCounts> base_stop_counts;  ///< the guard's, by cause (io thread)
  std::atomic<double> base_sample_newest_t_s{-std::numeric_limits<double>::infinity()};  ///< for the planner

  std::atomic<bool> stop{false};
  std::atomic<int> gasp_state{kGaspIdle};
  std::atomic<bool> recorder_stop{false};  ///< set after the haptic thread has ended
  std::atomic<int> running_threads{0};     ///< server threads not yet ended (not the recorder)
  /// A thread never came back from a plugin call: this Impl (and the plugin's library)
  /// must outlive it, so it is never destroyed.
  bool abandoned = false;
  std::mutex error_mutex;
  std::optional<std::string> error;

  // Filled by the threads before they end.
  TickHistogram tick_histogram;
  ForceSafetyCounters safety_counters;
  std::optional<CsvRecording> recording;  ///< opened by run(), written by the recorder thread
  bool zero_force_sent = false;
  std::atomic<bool> base_stop_sent{false};  ///< by the io thread, or run()'s when the io thread is stuck
  std::string scheduling;  ///< the haptic thread's, as obtained
  std::uint64_t recording_rows_written = 0;

  Impl(const CompiledScene& s, ServerSettings st, ServerOptions o, Rig r)
      : scene(s), settings(std::move(st)), options(std::move(o)), rig(std::move(r)), host(&world.table()) {}

  void fail(std::string message) {
    {
      const std::lock_guard lock(error_mutex);
      if (!error) error = std::move(message);
    }
    stop.store(true);
  }

  /// True when the call failed (the run is ending); `what` says which call.
  template <typename Result>
  bool check(const Result& result, const OpenedPlugin& plugin) {
    if (result.ok()) return false;
    fail(plugin_failure(plugin.description, result.error()));
    return true;
  }

  /// "plugin 'name': what", for a fault found in what a plugin returned.
  static std::string plugin_said(const OpenedPlugin& plugin, const std::string& what) {
    return "plugin '" + plugin.description.name + "': " + what;
  }

  bool deactivated(PluginCallStatus status, const OpenedPlugin& plugin, const char* call) {
    if (status != PluginCallStatus::Deactivate) return false;
    fail(Diagnostic{plugin.description.where,
                    "plugin '" + plugin.description.name + "': " + call + " asked to be stopped (MHD_DEACTIVATE)"}
             .to_string());
    return true;
  }

  /// Sends the base a zero twist (under its call mutex) and notes whether it took it.
  void stop_base();

  void haptic_thread();
  void io_thread();
  void planner_thread();
  void display_thread();
  void recorder_thread();
};

// ---- haptic thread ------------------------------------------------------------------

void HapticServer::Impl::haptic_thread() {
  HapticTickSettings tick_settings = settings.tick;
  if (auto limits = device->instance.device_limits(); limits.ok()) {
    tick_settings.safety.max_force_N = std::min(tick_settings.safety.max_force_N, limits.value().max_force_N);
  }
  HapticTick tick(scene, rig, tick_settings);
  realtime::name_current_thread(realtime::kHapticThreadName);
  scheduling = realtime::make_current_thread_realtime(80).detail;
  realtime::PeriodicTimer timer(1.0 / settings.haptic_rate_hz);
  Eigen::Vector3d q_rad = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  double last_t_s = host.now_s();

  while (!stop.load(std::memory_order_relaxed)) {
    if (tick_on_tracker_sample) {
      (void)timer.wait_next_or(base_sample_arrived, settings.min_tick_interval_s);
    } else {
      (void)timer.wait_next();
    }
    const double t_s = host.now_s();
    const double dt_s = std::max(0.0, t_s - last_t_s);
    last_t_s = t_s;

    BaseSensorSample sample;
    while (base_samples.pop(sample)) (void)tick.add_base_sensor_sample(sample.t_s, sample.X_is900_base_sensor);
    BaseCommandEvent command;
    while (commands_to_haptic.pop(command)) tick.add_base_command(command.t_s, command.twist_B);

    if (device->instance.simulates()) {
      const InCall in_call(*device, "simulate_until", t_s);
      auto r = device->instance.simulate_until(t_s);
      if (check(r, *device)) break;
    }
    mhd_device_state state{};
    auto read = [&] {
      const InCall in_call(*device, "device_read", t_s);
      return device->instance.device_read(state);
    }();
    if (check(read, *device) || deactivated(read.value(), *device, "device_read")) break;
    if (read.value() == PluginCallStatus::Ok) {
      q_rad = Eigen::Vector3d(state.joint_angles_rad[0], state.joint_angles_rad[1], state.joint_angles_rad[2]);
      if (!joint_angles_plausible(rig.device().limits, q_rad)) {
        fail(Diagnostic{device->description.where, plugin_said(*device, joint_angles_fault(q_rad))}.to_string());
        break;
      }
    }

    const HapticTickOutput out = tick.tick(t_s, dt_s, q_rad);

    mhd_device_command cmd{};
    cmd.timestamp_s = t_s;
    for (int j = 0; j < 3; ++j) cmd.joint_torques_Nm[j] = out.torques_Nm[j];
    auto write = [&] {
      const InCall in_call(*device, "device_write", t_s);
      return device->instance.device_write(cmd);
    }();
    if (check(write, *device) || deactivated(write.value(), *device, "device_write")) break;

    tick_histogram.add(host.now_s() - t_s);

    HapticSnapshot snap;
    snap.t_s = t_s;
    snap.valid = out.hip_W_m.allFinite();
    if (snap.valid) {
      snap.hip_W_m = out.hip_W_m;
      snap.proxy_W_m = out.proxy_W_m;
    }
    snap.force_W_N = out.force_W_N;
    snap.in_contact = out.in_contact;
    snap.base = out.base;
    snapshot_for_planner.write(snap);
    snapshot_for_display.write(snap);
    snapshot_for_io.write(snap);

    if (!options.recording.empty()) {
      RecordingRow row;
      row.t_s = t_s;
      row.dt_s = dt_s;
      for (int i = 0; i < 3; ++i) {
        row.q_rad[static_cast<std::size_t>(i)] = out.q_rad[i];
        row.hip_W_m[static_cast<std::size_t>(i)] = out.hip_W_m[i];
        row.proxy_W_m[static_cast<std::size_t>(i)] = out.proxy_W_m[i];
        row.force_W_N[static_cast<std::size_t>(i)] = out.force_W_N[i];
        row.cmd_force_W_N[static_cast<std::size_t>(i)] = out.proxy_force_W_N[i];
        row.torques_Nm[static_cast<std::size_t>(i)] = out.torques_Nm[i];
      }
      row.base_x_m = out.base.x_m;
      row.base_z_m = out.base.z_m;
      row.base_heading_rad = out.base.heading_rad;
      row.tracker_age_s = std::isfinite(out.tracker_age_s) ? out.tracker_age_s : -1.0;
      row.safety_gain = out.safety_gain;
      row.contact = out.in_contact ? 1 : 0;
      row.contact_object = out.contact_object;
      if (!recording_rows.push(row)) recording_dropped.fetch_add(1, std::memory_order_relaxed);
    }

    status_counters.ticks.fetch_add(1, std::memory_order_relaxed);
    if (out.in_contact) contact_ticks.fetch_add(1, std::memory_order_relaxed);
    if (out.proxy_budget_exhausted) proxy_budget_exhausted_ticks.fetch_add(1, std::memory_order_relaxed);
    status_counters.overruns.store(timer.stats().overruns, std::memory_order_relaxed);
    missed.store(timer.stats().missed_deadlines, std::memory_order_relaxed);
    status_counters.early_ticks.store(timer.stats().early_wakes, std::memory_order_relaxed);
    status_counters.force_N.store(out.force_W_N.norm(), std::memory_order_relaxed);
    status_counters.safety_gain.store(out.safety_gain, std::memory_order_relaxed);
    status_counters.tracker_age_s.store(out.tracker_age_s, std::memory_order_relaxed);
    status_counters.in_contact.store(out.in_contact, std::memory_order_relaxed);
  }

  // Safe state: zero torque, whatever ended the loop.
  zero_force_sent = send_zero_torque(device->instance, host);
  safety_counters = tick.safety().counters();
}

// ---- io thread: tracker, base, simulated user -----------------------------------------

void HapticServer::Impl::io_thread() {
  realtime::name_current_thread("mhd-io");
  std::optional<simulation::SimulatedUser> user;
  if (user_config) user.emplace(*user_config);
  BaseCommandGuardSettings guard_settings = settings.base_guard;
  guard_settings.command_hold_s = 1.0 / settings.io_rate_hz;
  BaseCommandGuard guard(guard_settings);
  // Tracker input is on the force's critical path (stale poses fade the force out), so it
  // runs real-time too, below the haptic thread.
  (void)realtime::make_current_thread_realtime(70);
  realtime::PeriodicTimer timer(1.0 / settings.io_rate_hz);
  std::array<mhd_tracker_sample, 64> samples{};
  TrackerSampleFilter filter({.base_sensor_id = settings.base_sensor_id,
                              .head_sensor_id = settings.head_sensor_id,
                              .tracking_range_m = settings.tracking_range_m});
  double newest_base_sample_t_s = -std::numeric_limits<double>::infinity();
  std::uint64_t command_sequence_seen = 0;
  BaseTwist planned;
  BaseCommandScheduler scheduler(1.0 / settings.base_rate_hz);
  BaseStopCounts counts_published;

  // Everything the tracker has received since the last read: checked, then base-sensor
  // samples to the haptic thread (woken for them) and head samples to the planner.
  // Returns the number of samples taken, or nullopt when the tracker failed.
  auto read_tracker = [&]() -> std::optional<std::size_t> {
    std::size_t taken = 0;
    bool base_sample = false;
    for (;;) {
      std::size_t count = 0;
      auto r = [&] {
        const InCall in_call(*tracker, "tracker_read", host.now_s());
        return tracker->instance.tracker_read(samples, count);
      }();
      if (check(r, *tracker) || deactivated(r.value(), *tracker, "tracker_read")) return std::nullopt;
      taken += count;
      const double read_at_s = host.now_s();  // after the read: a sample is never newer than this
      for (std::size_t i = 0; i < count; ++i) {
        const mhd_tracker_sample& s = samples[i];
        const Eigen::Vector3d p_T_m(s.p_T_m[0], s.p_T_m[1], s.p_T_m[2]);
        const TrackerSampleVerdict verdict = filter.check(s, read_at_s);
        if (verdict == TrackerSampleVerdict::ImplausiblePosition) {
          fail(Diagnostic{tracker->description.where,
                          plugin_said(*tracker, tracked_position_fault(s.sensor_id, p_T_m, settings.tracking_range_m))}
                   .to_string());
          return std::nullopt;
        }
        if (verdict != TrackerSampleVerdict::Accepted) {
          status_counters.tracker_rejected.fetch_add(1, std::memory_order_relaxed);
          continue;
        }
        status_counters.tracker_samples.fetch_add(1, std::memory_order_relaxed);
        const Pose X_T_S = pose_from_xyz_quaternion(p_T_m,
                                                    Eigen::Quaterniond(s.q_T_wxyz[0], s.q_T_wxyz[1], s.q_T_wxyz[2], s.q_T_wxyz[3]));
        if (s.sensor_id == settings.base_sensor_id) {
          if (!base_samples.push({s.timestamp_s, X_T_S})) status_counters.tracker_rejected.fetch_add(1, std::memory_order_relaxed);
          newest_base_sample_t_s = std::max(newest_base_sample_t_s, s.timestamp_s);
          base_sample_newest_t_s.store(newest_base_sample_t_s, std::memory_order_relaxed);
          base_sample = true;
        } else {
          const Pose X_W_head = rig.X_W_is900() * X_T_S;
          HeadState h;
          h.known = true;
          h.t_s = s.timestamp_s;
          h.p_W_m = X_W_head.translation();
          h.q_W = Eigen::Quaterniond(X_W_head.rotation());
          head.set(h);
        }
      }
      if (count < samples.size()) break;
    }
    if (base_sample && tick_on_tracker_sample) base_sample_arrived.signal();
    return taken;
  };

  // The plugin's own counts (samples it dropped, and why), for the status line.
  std::array<mhd_counter, 32> counter_buffer{};
  double next_counters_t_s = host.now_s();
  constexpr double kCountersInterval_s = 0.25;
  auto read_counters = [&](double t_s) -> bool {
    if (!tracker->instance.counts() || t_s < next_counters_t_s) return true;
    next_counters_t_s = t_s + kCountersInterval_s;
    auto n = [&] {
      const InCall in_call(*tracker, "counters", t_s);
      return tracker->instance.counters(counter_buffer);
    }();
    if (check(n, *tracker)) return false;
    std::vector<PluginCounter> out;
    out.reserve(n.value());
    for (std::size_t i = 0; i < n.value(); ++i) out.push_back({counter_buffer[i].name, counter_buffer[i].value});
    status_counters.tracker_plugin_counters.set(out);
    return true;
  };

  // Between deadlines, a tracker that can wait wakes this thread the moment a sample
  // arrives; the last moments before a deadline are slept precisely by the timer.
  constexpr double kWakeMargin_s = 100e-6;
  while (!stop.load(std::memory_order_relaxed)) {
    bool tracker_failed = false;
    if (tick_on_tracker_sample) {
      for (;;) {
        const double remaining_s = timer.next_deadline_s() - realtime::PeriodicTimer::monotonic_now_s() - kWakeMargin_s;
        if (remaining_s <= 0.0 || stop.load(std::memory_order_relaxed)) break;
        auto w = [&] {
          const InCall in_call(*tracker, "tracker_wait", host.now_s());
          return tracker->instance.tracker_wait(remaining_s);
        }();
        if (check(w, *tracker) || deactivated(w.value(), *tracker, "tracker_wait")) {
          tracker_failed = true;
          break;
        }
        if (w.value() != PluginCallStatus::Ok) break;  // timed out
        const std::optional<std::size_t> taken = read_tracker();
        if (!taken) {
          tracker_failed = true;
          break;
        }
        // Woken with nothing to read: a plugin that keeps saying so would spin this
        // real-time thread, so sleep to the deadline instead.
        if (*taken == 0) break;
      }
      if (tracker_failed) break;
    }
    (void)timer.wait_next();
    const double t_s = host.now_s();
    if (user) user->update(t_s, world);
    if (base != nullptr && base->instance.simulates()) {
      const std::lock_guard lock(*base->call_mutex);
      const InCall in_call(*base, "simulate_until", t_s);
      if (check(base->instance.simulate_until(t_s), *base)) break;
    }
    if (tracker->instance.simulates()) {
      const InCall in_call(*tracker, "simulate_until", t_s);
      if (check(tracker->instance.simulate_until(t_s), *tracker)) break;
    }
    if (!read_tracker() || !read_counters(t_s)) break;

    if (base == nullptr) continue;
    mhd_base_state base_state{};
    auto br = [&] {
      const std::lock_guard lock(*base->call_mutex);
      const InCall in_call(*base, "base_read", t_s);
      return base->instance.base_read(base_state);
    }();
    if (check(br, *base) || deactivated(br.value(), *base, "base_read")) break;

    // Command: the planner's newest, through the guard; stale base or head data stops the
    // base at once, otherwise commands go out at the base rate (and feed the base's watchdog).
    const auto [sequence, twist] = planned_command.get();
    const bool new_plan = sequence != command_sequence_seen;
    if (new_plan) {
      command_sequence_seen = sequence;
      planned = twist;
    }
    const HeadState h = head.get();
    BaseGuardInput judged;
    judged.t_s = t_s;
    judged.X_WB = snapshot_for_io.latest().base;
    judged.base_age_s = t_s - newest_base_sample_t_s;
    if (h.known) {
      judged.p_W_head_xz_m = Eigen::Vector2d(h.p_W_m.x(), h.p_W_m.z());
      judged.head_age_s = t_s - h.t_s;
    }
    const BaseGuardResult guarded = guard.apply(planned, judged);
    if (guard.counts().stops() != counts_published.stops() ||
        guard.counts().keep_out_deflections != counts_published.keep_out_deflections) {
      counts_published = guard.counts();
      base_stop_counts.set(counts_published);
    }
    if (scheduler.should_send(t_s, new_plan, guarded.twist_B)) {
      mhd_base_command cmd{};
      cmd.timestamp_s = t_s;
      cmd.vx_mps = guarded.twist_B.vx_mps;
      cmd.vz_mps = guarded.twist_B.vz_mps;
      cmd.omega_radps = guarded.twist_B.omega_radps;
      auto bw = [&] {
        const std::lock_guard lock(*base->call_mutex);
        const InCall in_call(*base, "base_write", t_s);
        return base->instance.base_write(cmd);
      }();
      if (check(bw, *base) || deactivated(bw.value(), *base, "base_write")) break;
      scheduler.sent(t_s, guarded.twist_B);
      base_commands.fetch_add(1, std::memory_order_relaxed);
      if (guarded.action == BaseGuardAction::Stopped) base_stops.fetch_add(1, std::memory_order_relaxed);
      if (!commands_to_haptic.push({t_s, guarded.twist_B})) {
        // The haptic thread drains this every tick; a full ring means it is stuck, and the
        // predictor simply runs without this command.
      }
    }
  }

  // Safe state: the base stops, whatever ended the loop.
  stop_base();
}

void HapticServer::Impl::stop_base() {
  if (base == nullptr) {
    base_stop_sent.store(true);
    return;
  }
  // Bounded: the io thread may itself be stuck inside the base. (A try_lock loop rather
  // than a timed mutex: TSan does not see pthread_mutex_clocklock and reports races.)
  std::unique_lock lock(*base->call_mutex, std::defer_lock);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::milliseconds(200);
  while (!lock.try_lock()) {
    if (std::chrono::steady_clock::now() >= give_up) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  if (base->instance.state() == PluginState::Running) {
    const InCall in_call(*base, "base_write", host.now_s());
    base_stop_sent.store(send_base_stop(&base->instance, host));
  }
}

// ---- planner thread ----------------------------------------------------------------

void HapticServer::Impl::planner_thread() {
  realtime::name_current_thread("mhd-planner");
  realtime::PeriodicTimer timer(1.0 / settings.base_rate_hz);
  std::uint64_t sequence = 0;
  UserMotionEstimate user_motion;
  while (!stop.load(std::memory_order_relaxed)) {
    (void)timer.wait_next();
    const HapticSnapshot snap = snapshot_for_planner.latest();
    status_counters.base.set(snap.base);
    const HeadState h = head.get();
    user_motion.update(h);
    if (!options.plan_base) continue;  // no planner: the base holds still (zero twist)
    BasePlanInput in;
    in.t_s = host.now_s();
    in.base = snap.base;
    in.hip_valid = snap.valid;
    in.hip_W_m = snap.hip_W_m;
    in.user_known = h.known;
    in.user_xz_W_m = Eigen::Vector2d(h.p_W_m.x(), h.p_W_m.z());
    in.user_heading_rad = user_motion.heading_rad();
    in.user_velocity_W_mps = user_motion.velocity_W_mps();
    in.max_input_age_s = settings.base_guard.tracker_timeout_s;
    in.hip_age_s = in.t_s - snap.t_s;
    in.base_age_s = in.t_s - base_sample_newest_t_s.load(std::memory_order_relaxed);
    if (h.known) in.head_age_s = in.t_s - h.t_s;
    const BaseTwist twist = options.plan_base(in);
    planned_command.set({++sequence, twist});
  }
}

// ---- display thread ------------------------------------------------------------------

void HapticServer::Impl::display_thread() {
  realtime::name_current_thread("mhd-display");
  realtime::PeriodicTimer timer(1.0 / settings.display_rate_hz);
  while (!stop.load(std::memory_order_relaxed)) {
    (void)timer.wait_next();
    const HapticSnapshot snap = snapshot_for_display.latest();
    const HeadState h = head.get();
    mhd_display_frame frame{};
    frame.timestamp_s = snap.t_s;
    for (int i = 0; i < 3; ++i) {
      frame.p_W_hip_m[i] = snap.hip_W_m[i];
      frame.p_W_proxy_m[i] = snap.proxy_W_m[i];
      frame.force_W_N[i] = snap.force_W_N[i];
      frame.p_W_head_m[i] = h.p_W_m[i];
    }
    frame.in_contact = snap.in_contact ? 1 : 0;
    frame.base_x_m = snap.base.x_m;
    frame.base_z_m = snap.base.z_m;
    frame.base_heading_rad = snap.base.heading_rad;
    frame.q_W_head_wxyz[0] = h.q_W.w();
    frame.q_W_head_wxyz[1] = h.q_W.x();
    frame.q_W_head_wxyz[2] = h.q_W.y();
    frame.q_W_head_wxyz[3] = h.q_W.z();
    for (OpenedPlugin* d : displays) {
      const InCall in_call(*d, "display_write", host.now_s());
      auto r = d->instance.display_write(frame);
      if (check(r, *d) || deactivated(r.value(), *d, "display_write")) return;
    }
  }
}

// ---- recorder thread ---------------------------------------------------------------

void HapticServer::Impl::recorder_thread() {
  realtime::name_current_thread("mhd-recorder");
  RecordingRow row;
  auto drain = [&] {
    while (recording_rows.pop(row)) {
      const HeadState h = head.get();
      if (h.known) {
        row.user_x_m = h.p_W_m.x();
        row.user_z_m = h.p_W_m.z();
        row.user_heading_rad = planar_heading_rad(h.q_W);
      } else {
        row.user_x_m = row.user_z_m = row.user_heading_rad = std::numeric_limits<double>::quiet_NaN();
      }
      recording->write(row);
    }
  };
  try {
    while (!recorder_stop.load(std::memory_order_acquire)) {
      drain();
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    drain();  // what the haptic thread queued before it stopped
    recording->flush();
  } catch (const std::exception& e) {
    fail(e.what());
  }
  recording_rows_written = recording->rows();
}

// ---- opening -------------------------------------------------------------------------

HapticServer::HapticServer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
HapticServer::~HapticServer() {
  // A thread still inside a plugin call uses the Impl and the plugin's code: keep both.
  if (impl_ && impl_->abandoned) (void)impl_.release();
}

const ServerSettings& HapticServer::settings() const noexcept { return impl_->settings; }

HapticServerBuild HapticServer::open(const SceneDescription& scene, const CompiledScene& compiled,
                                     ServerOptions options) {
  HapticServerBuild out;
  const SourceLocation scene_where{scene.file.string(), 0};

  ServerSettingsResult settings = server_settings_from(scene);
  out.diagnostics.insert(out.diagnostics.end(), settings.diagnostics.begin(), settings.diagnostics.end());

  RigBuildResult rig = Rig::from_scene(scene);
  for (const RigError& e : rig.errors) out.diagnostics.push_back({e.where.file.empty() ? scene_where : e.where, e.message});

  std::optional<simulation::SimulatedUserConfig> user_config;
  if (scene.simulated_user) {
    auto u = simulation::simulated_user_config_from(*scene.simulated_user);
    out.diagnostics.insert(out.diagnostics.end(), u.diagnostics.begin(), u.diagnostics.end());
    user_config = std::move(u.config);
  }

  // One device, one tracker, at most one base.
  const PluginDescription* device = nullptr;
  const PluginDescription* tracker = nullptr;
  const PluginDescription* base = nullptr;
  std::vector<const PluginDescription*> displays;
  for (const PluginDescription& p : scene.plugins) {
    const PluginDescription** slot = p.kind == PluginKind::Device    ? &device
                                     : p.kind == PluginKind::Tracker ? &tracker
                                     : p.kind == PluginKind::Base    ? &base
                                                                     : nullptr;
    if (slot == nullptr) {
      displays.push_back(&p);
    } else if (*slot != nullptr) {
      out.diagnostics.push_back({p.where, "a second " + std::string(to_string(p.kind)) + " plugin '" + p.name +
                                              "' (the server drives one; the first is at line " +
                                              std::to_string((*slot)->where.line) + ")"});
    } else {
      *slot = &p;
    }
  }
  ScenePlannerResult planner;
  if (rig.rig && !options.plan_base) {
    planner = scene_planner(scene, *rig.rig);
    out.diagnostics.insert(out.diagnostics.end(), planner.diagnostics.begin(), planner.diagnostics.end());
  }
  if (device == nullptr) out.diagnostics.push_back({scene_where, "the scene names no device plugin (<plugin kind=\"device\">)"});
  if (tracker == nullptr) out.diagnostics.push_back({scene_where, "the scene names no tracker plugin (<plugin kind=\"tracker\">)"});
  if (!out.diagnostics.empty()) return out;

  if (planner.plan) {
    options.plan_base = std::move(planner.plan);
    // The guard's keep-out is the planner's user cylinder unless <server> says otherwise.
    if (!(scene.server && scene.server->params.count("keep_out_m") != 0)) {
      settings.settings->base_guard.keep_out_m = planner.collision_radius_m;
    }
  }
  auto impl = std::make_unique<Impl>(compiled, *settings.settings, std::move(options), std::move(*rig.rig));
  impl->user_config = std::move(user_config);
  impl->host.set_scene_file(scene.file);
  const PluginSearchPath search = PluginSearchPath::standard(impl->options.plugin_path);

  std::vector<const PluginDescription*> order = {device, tracker};
  if (base != nullptr) order.push_back(base);
  order.insert(order.end(), displays.begin(), displays.end());
  impl->plugins.reserve(order.size());  // pointers into it stay valid
  for (const PluginDescription* d : order) {
    auto opened = open_plugin(search, *d, impl->host.abi());
    if (!opened.ok()) {
      out.diagnostics.push_back({d->where, opened.error().to_string()});
      continue;
    }
    impl->plugins.push_back({*d, std::move(opened).value()});
  }
  if (!out.diagnostics.empty()) return out;  // the opened ones close with impl

  impl->device = &impl->plugins[0];
  impl->tracker = &impl->plugins[1];
  std::size_t next = 2;
  if (base != nullptr) impl->base = &impl->plugins[next++];
  for (; next < impl->plugins.size(); ++next) impl->displays.push_back(&impl->plugins[next]);
  out.server = std::unique_ptr<HapticServer>(new HapticServer(std::move(impl)));
  return out;
}

// ---- running -------------------------------------------------------------------------

ServerReport HapticServer::run() {
  Impl& m = *impl_;
  ServerReport report;

  // Start: device last, so force starts only once the rest is running.
  std::vector<OpenedPlugin*> start_order;
  for (auto& p : m.plugins) {
    if (&p != m.device) start_order.push_back(&p);
  }
  start_order.push_back(m.device);
  m.gasp_state.store(kGaspArmed);
  for (OpenedPlugin* p : start_order) {
    const InCall in_call(*p, "start", m.host.now_s());
    auto r = p->instance.start();
    if (!r.ok()) {
      m.fail(plugin_failure(p->description, r.error()));
      break;
    }
  }

  if (!m.options.recording.empty()) {
    try {
      m.recording.emplace(m.options.recording, m.settings.record_flush_s);
    } catch (const std::exception& e) {
      m.fail(e.what());
    }
  }

  m.tick_on_tracker_sample = m.settings.tick_on_tracker_sample && m.tracker->instance.waits();
  const double t0_s = m.host.now_s();
  if (!m.stop.load()) {
    std::vector<std::thread> threads;
    auto spawn = [&](void (Impl::*body)()) {
      m.running_threads.fetch_add(1);
      threads.emplace_back([&m, body] {
        t_server_thread = true;
        (m.*body)();
        m.running_threads.fetch_sub(1);
      });
    };
    spawn(&Impl::io_thread);
    spawn(&Impl::haptic_thread);
    spawn(&Impl::planner_thread);
    if (!m.displays.empty()) spawn(&Impl::display_thread);
    std::thread recorder;
    if (m.recording) recorder = std::thread([&] { m.recorder_thread(); });

    double last_status_t_s = t0_s;
    std::uint64_t last_status_ticks = 0;
    // A plugin call that does not come back within plugin_call_timeout_s ends the run.
    // The other threads then reach their safe state; the base gets its stop from here
    // when its own (io) thread is the one stuck, inside the tracker.
    PluginWatchdog watchdog(m.settings.plugin_call_timeout_s);
    std::vector<OpenedPlugin*> watched;
    for (OpenedPlugin* p : {m.device, m.tracker, m.base}) {
      if (p == nullptr) continue;
      (void)watchdog.watch(*p->watch);
      watched.push_back(p);
    }
    auto watch_calls = [&](double now_s) {
      const std::optional<StuckCall> stuck = watchdog.check(now_s);
      if (!stuck) return;
      const OpenedPlugin& plugin = *watched[stuck->index];
      m.fail(Diagnostic{plugin.description.where, stuck_call_message(plugin.description.name, *stuck)}.to_string());
      if (&plugin == m.tracker) m.stop_base();
    };
    while (!m.stop.load()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      const double now_s = m.host.now_s();
      watch_calls(now_s);
      if (stop_requested_.load(std::memory_order_relaxed)) {
        report.ended_by = RunEnd::StopRequested;
        m.stop.store(true);
      } else if (m.options.duration_s > 0.0 && now_s - t0_s >= m.options.duration_s) {
        report.ended_by = RunEnd::Duration;
        m.stop.store(true);
      }
      if (m.options.on_status && now_s - last_status_t_s >= m.options.status_interval_s) {
        const ServerStatus s = m.status_counters.snapshot(now_s - t0_s, last_status_ticks, now_s - last_status_t_s);
        m.options.on_status(s);
        last_status_t_s = now_s;
        last_status_ticks = s.ticks;
      }
    }
    // Wait for the threads, watching calls still; one that never leaves a plugin call is
    // left behind (and the plugins with it: nothing may unload code a thread is in).
    const double give_up_s = m.host.now_s() + m.settings.plugin_call_timeout_s + 2.0;
    while (m.running_threads.load() > 0 && m.host.now_s() < give_up_s) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      watch_calls(m.host.now_s());
    }
    if (m.running_threads.load() > 0) {
      m.abandoned = true;
      for (auto& t : threads) t.detach();
    } else {
      for (auto& t : threads) t.join();
    }
    m.recorder_stop.store(true, std::memory_order_release);
    if (recorder.joinable()) recorder.join();
  }

  // The tracker's final counts (its thread has ended, so this thread may call it).
  if (!m.abandoned && m.tracker->instance.counts() && m.tracker->instance.state() != PluginState::Loaded) {
    std::array<mhd_counter, 32> buffer{};
    if (auto n = m.tracker->instance.counters(buffer); n.ok()) {
      std::vector<PluginCounter> out;
      for (std::size_t i = 0; i < n.value(); ++i) out.push_back({buffer[i].name, buffer[i].value});
      m.status_counters.tracker_plugin_counters.set(out);
    }
  }

  // A dying thread is sending its last gasp through the plugins: leave them open; the
  // process ends from that thread.
  if (int armed = kGaspArmed; !m.gasp_state.compare_exchange_strong(armed, kGaspIdle)) {
    for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
  }

  // Stop and close everything (device first: no force while the rest shuts down).
  std::vector<OpenedPlugin*> stop_order(start_order.rbegin(), start_order.rend());
  if (m.abandoned) stop_order.clear();
  for (OpenedPlugin* p : stop_order) {
    if (p->instance.state() == PluginState::Running) {
      const InCall in_call(*p, "stop", m.host.now_s());
      if (auto r = p->instance.stop(); !r.ok()) m.fail(plugin_failure(p->description, r.error()));
    }
    const InCall in_call(*p, "close", m.host.now_s());
    (void)p->instance.close();
  }

  const double elapsed_s = m.host.now_s() - t0_s;
  report.status = m.status_counters.snapshot(elapsed_s, 0, elapsed_s);
  report.missed_deadlines = m.missed.load();
  report.tick_median_us = m.tick_histogram.quantile_us(0.5);
  report.tick_p99_us = m.tick_histogram.quantile_us(0.99);
  report.tick_p999_us = m.tick_histogram.quantile_us(0.999);
  report.tick_max_us = m.tick_histogram.max_us();
  report.contact_ticks = m.contact_ticks.load();
  report.proxy_budget_exhausted_ticks = m.proxy_budget_exhausted_ticks.load();
  report.stale_ticks = m.safety_counters.stale_ticks;
  report.fault_ticks = m.safety_counters.fault_ticks;
  report.hip_jumps = m.safety_counters.jumps;
  report.clamped_ticks = m.safety_counters.clamped_ticks;
  report.base_commands = m.base_commands.load();
  report.base_stops = m.base_stops.load();
  report.base_stops_by_cause = m.base_stop_counts.get();
  report.recording_rows = m.recording_rows_written;
  report.recording_dropped = m.recording_dropped.load();
  report.zero_force_sent = m.zero_force_sent;
  report.haptic_scheduling = m.scheduling;
  report.base_stop_sent = m.base_stop_sent.load();
  {
    const std::lock_guard lock(m.error_mutex);
    report.error = m.error;
  }
  if (report.error) report.ended_by = RunEnd::Fault;  // a fault wins over a stop at the same moment
  return report;
}

// ---- last gasp -------------------------------------------------------------------------

std::pair<const char*, const char*> HapticServer::call_in_progress() noexcept {
  if (t_plugin_in_call == nullptr) return {nullptr, nullptr};
  return {t_plugin_in_call->culprit.c_str(), t_call_in_progress};
}

HapticServer::LastGasp HapticServer::last_gasp() noexcept {
  Impl& m = *impl_;
  LastGasp out;
  if (int armed = kGaspArmed; !m.gasp_state.compare_exchange_strong(armed, kGaspSending)) return out;
  m.stop.store(true);
  // The server's threads see the stop and send their own zeros; waiting for them means
  // none of their commands lands after ours. The dying thread, if one of them, never ends.
  const int dying = t_server_thread ? 1 : 0;
  for (int waited_ms = 0; waited_ms < 50 && m.running_threads.load() > dying; ++waited_ms) {
    const timespec one_ms{0, 1000000};
    nanosleep(&one_ms, nullptr);
  }
  // The plugin that died mid-call may hang or crash again: the other one goes first.
  const SafeStopSent sent =
      send_safe_stop(m.device->instance, m.base == nullptr ? nullptr : &m.base->instance,
                     t_plugin_in_call == m.device ? SafeStopOrder::BaseFirst : SafeStopOrder::DeviceFirst, m.host);
  out.zero_torque_sent = sent.zero_torque;
  out.base_stop_sent = sent.base_stop;
  out.sent = true;
  m.gasp_state.store(kGaspDone);
  return out;
}

}  // namespace mhd
