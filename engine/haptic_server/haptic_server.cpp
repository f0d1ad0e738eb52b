// HapticServer: opening a scene's plugins, run() (start, the threads, the watchdog and
// status, stop and close, the report) and the last gasp. The threads' bodies are in
// <name>_thread.cpp, their shared state in server_impl.h.
#include "haptic_server/haptic_server.h"

#include "haptic_server/force_limit.h"
#include "haptic_server/plugin_watchdog.h"
#include "haptic_server/run_check.h"
#include "haptic_server/safe_stop.h"
#include "haptic_server/scene_planner.h"
#include "haptic_server/server_impl.h"
#include "plugin_host/open_plugin.h"
#include "plugin_host/plugin_kind.h"
#include "plugin_host/plugin_search_path.h"
#include "realtime/alternate_signal_stack.h"
#include "scene/rig_kind_check.h"
#include "simulation_config/simulated_user_params.h"

#include <array>
#include <chrono>
#include <ctime>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace mhd {
namespace {

/// Set on the server's own threads (haptic, io, planner, display).
thread_local bool t_server_thread = false;

}  // namespace

// ---- opening -------------------------------------------------------------------------

HapticServer::HapticServer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
HapticServer::~HapticServer() {
  // A thread still inside a plugin call uses the Impl and the plugin's code: keep both.
  if (impl_ && impl_->abandoned) (void)impl_.release();
}

const ServerSettings& HapticServer::settings() const noexcept { return impl_->settings; }

double HapticServer::host_now_s() const noexcept { return impl_->host.now_s(); }

namespace {

/// The scene's plugins by role, in the order they are opened (and started, but for the
/// device, which starts last): device, tracker, base, displays, link.
struct PluginRoles {
  const PluginDescription* device = nullptr;
  const PluginDescription* tracker = nullptr;
  const PluginDescription* base = nullptr;
  std::vector<const PluginDescription*> displays;
  const PluginDescription* link = nullptr;

  explicit PluginRoles(const SceneDescription& scene) {
    for (const PluginDescription& p : scene.plugins) {
      if (p.kind == PluginKind::Device) {
        device = &p;
      } else if (p.kind == PluginKind::Tracker) {
        tracker = &p;
      } else if (p.kind == PluginKind::Base) {
        base = &p;
      } else if (p.kind == PluginKind::Link) {
        link = &p;
      } else {
        displays.push_back(&p);
      }
    }
  }
  [[nodiscard]] std::vector<const PluginDescription*> open_order() const {
    std::vector<const PluginDescription*> order = {device};
    if (tracker != nullptr) order.push_back(tracker);
    if (base != nullptr) order.push_back(base);
    order.insert(order.end(), displays.begin(), displays.end());
    if (link != nullptr) order.push_back(link);
    return order;
  }
};

/// The scene's own base planner, into `settings` and `options`: none on a desktop rig or
/// when the caller brings one. True when the scene plans.
Result<bool> plan_from_scene(const SceneDescription& scene, const Rig& rig, ServerSettings& settings,
                             ServerOptions& options) {
  if (scene.rig_kind.kind == RigKind::Desktop || options.plan_base) return false;
  Result<ScenePlanner> made = scene_planner(scene, rig);
  if (!made.ok()) return made.error();
  if (!made->plan) return false;
  settings.planner_usable_B = made->usable_B;
  options.plan_base = std::move(made->plan);
  // The guard's keep-out is the planner's user cylinder unless <server> says otherwise.
  if (!(scene.server && scene.server->params.count("keep_out_m") != 0)) {
    settings.base_guard.keep_out_m = made->collision_radius_m;
  }
  return true;
}

}  // namespace

Result<OpenedServer> HapticServer::open(const SceneDescription& scene, const CompiledScene& compiled,
                                        ServerOptions options) {
  // What `mhd validate` checks too: the verdict is the same function's.
  Diagnostics errors = check_scene_for_run(scene, static_cast<bool>(options.plan_base));
  if (!errors.empty()) return errors;
  Result<ServerSettings> settings = server_settings_from(scene);
  Result<Rig, std::vector<RigError>> rig = Rig::from_scene(scene);
  if (!settings.ok() || !rig.ok()) throw std::logic_error("check_scene_for_run passed a scene it cannot run");

  const PluginRoles roles(scene);
  const Result<bool> scene_plans = plan_from_scene(scene, *rig, *settings, options);
  if (!scene_plans.ok()) return scene_plans.error();
  auto impl = std::make_unique<Impl>(compiled, *settings, std::move(options), std::move(*rig));
  impl->host.set_scene_file(scene.file);
  errors = impl->open_plugins(roles.open_order());
  if (!errors.empty()) return errors;  // the opened ones close with impl

  OpenedServer out;
  impl->device = &impl->plugins[0];
  errors = impl->fit_to_device(scene, *roles.device, scene_plans.value(), out.warnings);
  if (!errors.empty()) return errors;
  std::size_t next = 1;
  if (roles.tracker != nullptr) impl->tracker = &impl->plugins[next++];
  if (roles.base != nullptr) impl->base = &impl->plugins[next++];
  for (std::size_t i = 0; i < roles.displays.size(); ++i) impl->displays.push_back(&impl->plugins[next++]);
  if (roles.link != nullptr) impl->link = &impl->plugins[next++];
  out.server = std::unique_ptr<HapticServer>(new HapticServer(std::move(impl)));
  return out;
}

Diagnostics HapticServer::Impl::open_plugins(const std::vector<const PluginDescription*>& order) {
  const PluginSearchPath search = PluginSearchPath::standard(options.plugin_path);
  Diagnostics errors;
  plugins.reserve(order.size());  // pointers into it stay valid
  for (const PluginDescription* d : order) {
    auto opened = open_plugin(search, *d, host.abi());
    if (!opened.ok()) {
      errors.push_back({d->where, opened.error().to_string()});
      continue;
    }
    plugins.push_back({*d, std::move(opened).value()});
  }
  return errors;
}

Diagnostics HapticServer::Impl::fit_to_device(const SceneDescription& description, const PluginDescription& described,
                                              bool scene_plans, Diagnostics& warnings) {
  auto info = device->instance.device_info();
  if (!info.ok()) return {};
  // One source for the force limit: the device's, lowered by the scene's when smaller.
  ForceLimit limit = force_limit_for(description.haptics.max_force_N, info.value().max_force_N, described.name);
  settings.tick.safety.max_force_N = limit.max_force_N;
  if (limit.warning) warnings.push_back({described.where, std::move(*limit.warning)});
  if (!scene_plans) return {};
  // The scene's planner keeps the HIP in this device's own workspace, not the rig
  // model's (which describes a PHANToM): checked with the rig's, made again here.
  const std::optional<WorkspaceBox> usable_P = usable_device_workspace(info.value(), rig.device().usable_margin_m);
  if (!usable_P) {
    return {{described.where, "device '" + described.name + "' reports no workspace box larger than the "
                                                              "rig's usable margin: the base planner has nowhere to keep the hand"}};
  }
  Result<ScenePlanner> made = scene_planner(description, rig, usable_P);
  if (!made.ok()) return made.error();
  settings.planner_usable_B = made->usable_B;
  options.plan_base = std::move(made->plan);
  return {};
}

// ---- running -------------------------------------------------------------------------

ServerReport HapticServer::run() {
  Impl& m = *impl_;
  ServerReport report;
  const std::vector<OpenedPlugin*> start_order = m.start_plugins();
  if (!m.options.recording.empty()) m.open_recording();

  const bool desktop = m.rig.kind() == RigKind::Desktop;
  m.tick_on_tracker_sample = m.tracker != nullptr && m.settings.tick_on_tracker_sample && m.tracker->instance.waits();
  if (desktop) m.stop_base();  // no base: nothing to stop, and that is confirmed now
  const double t0_s = m.host.now_s();
  if (!m.stop.load()) m.run_threads(report, t0_s, stop_requested_);
  if (!m.abandoned) m.read_final_tracker_counts();

  // A dying thread is sending its last gasp through the plugins: leave them open; the
  // process ends from that thread.
  if (int armed = Impl::kGaspArmed; !m.gasp_state.compare_exchange_strong(armed, Impl::kGaspIdle)) {
    for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
  }
  if (!m.abandoned) m.stop_and_close(start_order);
  m.fill_report(report, m.host.now_s() - t0_s);
  return report;
}

void HapticServer::Impl::run_threads(ServerReport& report, double t0_s, const std::atomic<bool>& stop_requested) {
  const bool desktop = rig.kind() == RigKind::Desktop;
  std::vector<std::thread> threads;
  // A desktop rig has no tracker, base or planner: the haptic thread (and the displays).
  if (!desktop) spawn(threads, &Impl::io_thread, "io");
  spawn(threads, &Impl::haptic_thread, "haptic");
  if (!desktop) spawn(threads, &Impl::planner_thread, "planner");
  if (!displays.empty()) spawn(threads, &Impl::display_thread, "display");
  if (link != nullptr) spawn(threads, &Impl::link_thread, "link");
  std::thread recorder;
  if (recording) recorder = std::thread([this] { recorder_thread(); });

  // A plugin call that does not come back within plugin_call_timeout_s ends the run.
  // The other threads then reach their safe state; the base gets its stop from here
  // when its own (io) thread is the one stuck, inside the tracker.
  PluginWatchdog watchdog(settings.plugin_call_timeout_s);
  std::vector<OpenedPlugin*> watched;
  for (OpenedPlugin* p : {device, tracker, base, link}) {
    if (p == nullptr) continue;
    (void)watchdog.watch(*p->watch);
    watched.push_back(p);
  }
  supervise(report, t0_s, stop_requested, watchdog, watched);
  join_threads(threads, watchdog, watched);
  recorder_stop.store(true, std::memory_order_release);
  if (recorder.joinable()) recorder.join();
  // A vanished thread never sent its safe state: this thread does, now that none of
  // the server's threads calls the plugins any more.
  if (!abandoned && haptic_thread_vanished.load()) {
    const InCall in_call(*device, "device_write", host.now_s());
    zero_force_sent = send_zero_torque(device->instance, host);
  }
  if (!abandoned && io_thread_vanished.load()) stop_base();
}

void HapticServer::Impl::supervise(ServerReport& report, double t0_s, const std::atomic<bool>& stop_requested,
                                   PluginWatchdog& watchdog, const std::vector<OpenedPlugin*>& watched) {
  double last_status_t_s = t0_s;
  std::uint64_t last_status_ticks = 0;
  while (!stop.load()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const double now_s = host.now_s();
    watch_calls(watchdog, watched, now_s);
    if (stop_requested.load(std::memory_order_relaxed)) {
      report.ended_by = RunEnd::StopRequested;
      stop.store(true);
    } else if (options.duration_s > 0.0 && now_s - t0_s >= options.duration_s) {
      report.ended_by = RunEnd::Duration;
      stop.store(true);
    }
    if (options.on_status && now_s - last_status_t_s >= options.status_interval_s) {
      ServerStatus s = status_counters.snapshot(now_s - t0_s, last_status_ticks, now_s - last_status_t_s);
      s.rig_kind = rig.kind();
      options.on_status(s);
      last_status_t_s = now_s;
      last_status_ticks = s.ticks;
    }
  }
}

std::vector<OpenedPlugin*> HapticServer::Impl::start_plugins() {
  // Device last, so force starts only once the rest is running.
  std::vector<OpenedPlugin*> start_order;
  for (auto& p : plugins) {
    if (&p != device) start_order.push_back(&p);
  }
  start_order.push_back(device);
  gasp_state.store(kGaspArmed);
  for (OpenedPlugin* p : start_order) {
    const InCall in_call(*p, "start", host.now_s());
    auto r = p->instance.start();
    if (!r.ok()) {
      fail(plugin_failure(p->description, r.error()));
      break;
    }
  }
  return start_order;
}

void HapticServer::Impl::open_recording() {
  try {
    recording.emplace(options.recording, settings.record_flush_s, scene.sharing.has_value());
  } catch (const std::exception& e) {
    fail(e.what());
  }
}

void HapticServer::Impl::spawn(std::vector<std::thread>& threads, void (Impl::*body)(), const char* name) {
  running_threads.fetch_add(1);
  threads.emplace_back([this, body, name] {
    t_server_thread = true;
    // The last gasp must run even when this thread's own stack overflowed.
    const realtime::AlternateSignalStack signal_stack;
    // Runs on a return and on the unwinding of pthread_exit alike.
    struct ThreadEnd {
      Impl& m;
      void (Impl::*body)();
      const char* name;
      bool returned = false;
      ~ThreadEnd() {
        if (!returned) m.thread_vanished(body, name);
        m.running_threads.fetch_sub(1);
      }
    } end{*this, body, name};
    (this->*body)();
    end.returned = true;
  });
}

void HapticServer::Impl::watch_calls(PluginWatchdog& watchdog, const std::vector<OpenedPlugin*>& watched,
                                     double now_s) {
  const std::optional<StuckCall> stuck = watchdog.check(now_s);
  if (!stuck) return;
  const OpenedPlugin& plugin = *watched[stuck->index];
  fail(Diagnostic{plugin.description.where, stuck_call_message(plugin.description.name, *stuck)}.to_string());
  if (&plugin == tracker) stop_base();
}

void HapticServer::Impl::join_threads(std::vector<std::thread>& threads, PluginWatchdog& watchdog,
                                      const std::vector<OpenedPlugin*>& watched) {
  // Wait for the threads, watching calls still; one that never leaves a plugin call is
  // left behind (and the plugins with it: nothing may unload code a thread is in).
  const double give_up_s = host.now_s() + settings.plugin_call_timeout_s + 2.0;
  while (running_threads.load() > 0 && host.now_s() < give_up_s) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    watch_calls(watchdog, watched, host.now_s());
  }
  if (running_threads.load() > 0) {
    abandoned = true;
    for (auto& t : threads) t.detach();
  } else {
    for (auto& t : threads) t.join();
  }
}

void HapticServer::Impl::read_final_tracker_counts() {
  // Its thread has ended, so this thread may call it.
  if (tracker == nullptr || !tracker->instance.counts() || tracker->instance.state() == PluginState::Loaded) return;
  std::array<CounterReading, PluginCounterFrame::kMax> buffer{};
  if (auto n = tracker->instance.counters(buffer); n.ok()) {
    PluginCounterFrame frame;
    for (std::size_t i = 0; i < n.value(); ++i) {
      frame.names[i] = buffer[i].name;
      frame.values[i] = buffer[i].value;
    }
    frame.count = n.value();
    status_counters.tracker_plugin_counters.write(frame);
  }
}

void HapticServer::Impl::stop_and_close(const std::vector<OpenedPlugin*>& start_order) {
  // Device first: no force while the rest shuts down.
  for (auto p = start_order.rbegin(); p != start_order.rend(); ++p) {
    OpenedPlugin& plugin = **p;
    if (plugin.instance.state() == PluginState::Running) {
      const InCall in_call(plugin, "stop", host.now_s());
      if (auto r = plugin.instance.stop(); !r.ok()) fail(plugin_failure(plugin.description, r.error()));
    }
    const InCall in_call(plugin, "close", host.now_s());
    (void)plugin.instance.close();
  }
}

void HapticServer::Impl::fill_report(ServerReport& report, double elapsed_s) {
  report.status = status_counters.snapshot(elapsed_s, 0, elapsed_s);
  report.status.rig_kind = rig.kind();
  report.missed_deadlines = missed.load();
  report.tick_median_us = tick_histogram.quantile_us(0.5);
  report.tick_p99_us = tick_histogram.quantile_us(0.99);
  report.tick_p999_us = tick_histogram.quantile_us(0.999);
  report.tick_max_us = tick_histogram.max_us();
  report.contact_ticks = contact_ticks.load();
  report.proxy_budget_exhausted_ticks = proxy_budget_exhausted_ticks.load();
  report.startup_ticks = startup_ticks;
  report.stale_ticks = safety_counters.stale_ticks;
  report.fault_ticks = safety_counters.fault_ticks;
  report.hip_jumps = safety_counters.jumps;
  report.clamped_ticks = safety_counters.clamped_ticks;
  report.base_commands = base_commands.load();
  report.base_stops = base_stops.load();
  report.base_stops_by_cause = base_stop_counts.latest();
  report.recording_rows = recording_rows_written;
  report.recording_dropped = recording_dropped.load();
  for (int s = 0; s < shared_final_count; ++s) {
    const SharedObjectFinal& f = shared_final[static_cast<std::size_t>(s)];
    const auto object = static_cast<std::size_t>(f.object);
    report.shared_objects.push_back({scene.object_names[object], f.id, f.authority_rig, f.held_here,
                                     scene.world.pose(f.object).translation(), f.p_W_end_m, f.state_age_s});
  }
  report.sharing = sharing_counters;
  report.link_dropped = link_dropped.load();
  report.zero_force_sent = zero_force_sent;
  report.haptic_scheduling = scheduling;
  report.haptic_minor_page_faults = haptic_page_faults.minor;
  report.haptic_major_page_faults = haptic_page_faults.major;
  report.base_stop_sent = base_stop_sent.load();
  {
    const std::lock_guard lock(error_mutex);
    report.error = error;
  }
  if (report.error) report.ended_by = RunEnd::Fault;  // a fault wins over a stop at the same moment
}

void HapticServer::Impl::thread_vanished(void (Impl::*body)(), const char* thread_name) {
  if (body == &Impl::haptic_thread) haptic_thread_vanished.store(true);
  if (body == &Impl::io_thread) io_thread_vanished.store(true);
  const auto [plugin, call] = last_plugin_call_on_this_thread();
  std::string message = std::string("the ") + thread_name + " thread ended without returning";
  if (plugin != nullptr) {
    message = Diagnostic{plugin->description.where, "plugin '" + plugin->description.name + "': " + message +
                                                        ", last in " + call + " (pthread_exit?)"}
                  .to_string();
  }
  fail(std::move(message));
}

// ---- last gasp -------------------------------------------------------------------------

std::pair<const char*, const char*> HapticServer::call_in_progress() noexcept {
  const auto [plugin, call] = plugin_call_on_this_thread();
  if (plugin == nullptr) return {nullptr, nullptr};
  return {plugin->culprit.c_str(), call};
}

HapticServer::LastGasp HapticServer::last_gasp() noexcept {
  Impl& m = *impl_;
  LastGasp out;
  if (int armed = Impl::kGaspArmed; !m.gasp_state.compare_exchange_strong(armed, Impl::kGaspSending)) return out;
  m.stop.store(true);
  // The server's threads see the stop and send their own zeros; waiting for them means
  // none of their commands lands after ours. The dying thread, if one of them, never ends.
  const int dying = t_server_thread ? 1 : 0;
  for (int waited_ms = 0; waited_ms < 50 && m.running_threads.load() > dying; ++waited_ms) {
    const timespec one_ms{0, 1000000};
    nanosleep(&one_ms, nullptr);
  }
  // The plugin that died mid-call may hang or crash again: the other one goes first.
  const SafeStopOrder order =
      plugin_call_on_this_thread().first == m.device ? SafeStopOrder::BaseFirst : SafeStopOrder::DeviceFirst;
  const SafeStopSent sent =
      send_safe_stop(m.device->instance, m.base == nullptr ? nullptr : &m.base->instance, order, m.host);
  out.zero_torque_sent = sent.zero_torque;
  out.base_stop_sent = sent.base_stop;
  out.desktop = m.rig.kind() == RigKind::Desktop;
  out.sent = true;
  m.gasp_state.store(Impl::kGaspDone);
  return out;
}

}  // namespace mhd
