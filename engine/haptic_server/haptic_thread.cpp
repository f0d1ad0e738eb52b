// The haptic thread: device read -> HapticTick -> device write at the scene rate, to
// absolute deadlines. No lock, no allocation (haptic_thread_hygiene_tests).
#include "haptic_server/server_impl.h"

#include "haptic_server/haptic_tick.h"
#include "haptic_server/physical_range.h"
#include "haptic_server/safe_stop.h"
#include "realtime/periodic_timer.h"
#include "realtime/thread_name.h"
#include "realtime/thread_page_faults.h"
#include "realtime/thread_priority.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace mhd {
namespace {

// The look-ahead runs only while this fraction of the haptic period has not passed.
constexpr double kLookAheadWithinPeriod = 0.25;

}  // namespace

void HapticServer::Impl::haptic_thread() {
  const HapticTickSettings& tick_settings = settings.tick;  // max_force_N: the device's, set at open
  DeviceInfo info{};
  if (auto reported = device->instance.device_info(); reported.ok()) info = reported.value();
  HapticTick tick(scene, rig, tick_settings);
  realtime::name_current_thread(realtime::kHapticThreadName);
  scheduling = realtime::make_current_thread_realtime(80).detail;
  realtime::PeriodicTimer timer(1.0 / settings.haptic_rate_hz);
  Eigen::Vector3d p_D_tool_m = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  double last_t_s = host.now_s();
  const realtime::PageFaults faults_before_loop = realtime::current_thread_page_faults();

  while (!stop.load(std::memory_order_relaxed)) {
    if (tick_on_tracker_sample) {
      (void)timer.wait_next_or(base_sample_arrived, settings.min_tick_interval_s);
    } else {
      (void)timer.wait_next();
    }
    const double t_s = host.now_s();
    const double dt_s = std::max(0.0, t_s - last_t_s);
    last_t_s = t_s;

    drain_into(tick);
    receive_shared(tick, t_s);
    tick.set_lift_m(lift_m_at(t_s));
    if (!read_device(t_s, info, p_D_tool_m)) break;
    const HapticTickOutput out = tick.tick(t_s, dt_s, p_D_tool_m);
    if (!write_device(t_s, out)) break;
    send_shared(tick);
    tick_histogram.add(host.now_s() - t_s);
    publish(t_s, out);
    if (!options.recording.empty()) record(t_s, dt_s, out);
    count(out, timer.stats());

    // The force is out: the rest of the period is idle, so the proxy looks ahead to the next
    // tick's HIP (ProxyLookAhead), unless this tick ran long enough that the look-ahead,
    // which costs about as much, could make the next one late.
    if (host.now_s() - t_s < kLookAheadWithinPeriod / settings.haptic_rate_hz) (void)tick.look_ahead();
  }

  haptic_page_faults = realtime::current_thread_page_faults() - faults_before_loop;
  // Safe state: zero torque, whatever ended the loop.
  zero_force_sent = send_zero_torque(device->instance, host);
  safety_counters = tick.safety().counters();
  startup_ticks = tick.startup_ticks();
  note_shared_objects(tick, host.now_s());
}

void HapticServer::Impl::drain_into(HapticTick& tick) {
  BaseSensorSample sample;
  while (base_samples.pop(sample)) (void)tick.add_base_sensor_sample(sample.t_s, sample.X_is900_base_sensor);
  BaseCommandEvent command;
  while (commands_to_haptic.pop(command)) tick.add_base_command(command.t_s, command.twist_B);
}

bool HapticServer::Impl::read_device(double t_s, const DeviceInfo& info, Eigen::Vector3d& p_D_tool_m) {
  if (device->instance.simulates()) {
    const InCall in_call(*device, "simulate_until", t_s);
    if (check(device->instance.simulate_until(t_s), *device)) return false;
  }
  DeviceState state{};
  auto read = [&] {
    const InCall in_call(*device, "device_read", t_s);
    return device->instance.device_read(state);
  }();
  if (check(read, *device) || deactivated(read.value(), *device, "device_read")) return false;
  if (read.value() == PluginCallStatus::Ok) {
    p_D_tool_m = Eigen::Vector3d(state.p_D_tool_m[0], state.p_D_tool_m[1], state.p_D_tool_m[2]);
    if (!tool_position_plausible(info, p_D_tool_m)) {
      fail(Diagnostic{device->description.where, plugin_said(*device, tool_position_fault(p_D_tool_m))}.to_string());
      return false;
    }
  }
  return true;
}

bool HapticServer::Impl::write_device(double t_s, const HapticTickOutput& out) {
  // A call that returned after the watchdog ended the run: nothing but zero from here.
  if (stop.load(std::memory_order_relaxed)) return false;
  DeviceCommand cmd{};
  cmd.timestamp_s = t_s;
  for (int j = 0; j < 3; ++j) cmd.force_D_N[j] = out.force_D_N[j];
  auto write = [&] {
    const InCall in_call(*device, "device_write", t_s);
    return device->instance.device_write(cmd);
  }();
  return !check(write, *device) && !deactivated(write.value(), *device, "device_write");
}

void HapticServer::Impl::publish(double t_s, const HapticTickOutput& out) {
  HapticSnapshot snap;
  snap.t_s = t_s;
  snap.valid = out.p_W_hip.allFinite();
  if (snap.valid) {
    snap.p_W_hip = out.p_W_hip;
    snap.proxy_W_m = out.proxy_W_m;
  }
  snap.force_W_N = out.force_W_N;
  snap.in_contact = out.in_contact;
  snap.base = out.base;
  snapshot_for_planner.write(snap);
  snapshot_for_display.write(snap);
  snapshot_for_io.write(snap);
}

void HapticServer::Impl::record(double t_s, double dt_s, const HapticTickOutput& out) {
  RecordingRow row;
  row.t_s = t_s;
  row.dt_s = dt_s;
  for (int i = 0; i < 3; ++i) {
    row.p_D_tool_m[static_cast<std::size_t>(i)] = out.p_D_tool_m[i];
    row.p_W_hip[static_cast<std::size_t>(i)] = out.p_W_hip[i];
    row.proxy_W_m[static_cast<std::size_t>(i)] = out.proxy_W_m[i];
    row.force_W_N[static_cast<std::size_t>(i)] = out.force_W_N[i];
    row.cmd_force_W_N[static_cast<std::size_t>(i)] = out.proxy_force_W_N[i];
    row.force_D_N[static_cast<std::size_t>(i)] = out.force_D_N[i];
  }
  if (rig.kind() == RigKind::Desktop) {
    // No base: its columns stay, empty (nan), so one reader reads both kinds of rig.
    row.base_x_m = row.base_z_m = row.base_heading_rad = std::numeric_limits<double>::quiet_NaN();
  } else {
    row.base_x_m = out.base.x_m;
    row.base_z_m = out.base.z_m;
    row.base_heading_rad = out.base.heading_rad;
  }
  row.lift_m = out.lift_m;
  for (int i = 0; i < 3; ++i) row.p_W_shared_m[static_cast<std::size_t>(i)] = out.p_W_shared_m[i];
  row.tracker_age_s = std::isfinite(out.tracker_age_s) ? out.tracker_age_s : -1.0;
  row.safety_gain = out.safety_gain;
  row.contact = out.in_contact ? 1 : 0;
  row.contact_object = out.contact_object;
  if (!recording_rows.push(row)) recording_dropped.fetch_add(1, std::memory_order_relaxed);
}

void HapticServer::Impl::count(const HapticTickOutput& out, const realtime::TimerStats& timer) {
  status_counters.ticks.fetch_add(1, std::memory_order_relaxed);
  if (out.in_contact) contact_ticks.fetch_add(1, std::memory_order_relaxed);
  if (out.proxy_budget_exhausted) proxy_budget_exhausted_ticks.fetch_add(1, std::memory_order_relaxed);
  status_counters.overruns.store(timer.overruns, std::memory_order_relaxed);
  missed.store(timer.missed_deadlines, std::memory_order_relaxed);
  status_counters.early_ticks.store(timer.early_wakes, std::memory_order_relaxed);
  status_counters.force_N.store(out.force_W_N.norm(), std::memory_order_relaxed);
  status_counters.safety_gain.store(out.safety_gain, std::memory_order_relaxed);
  status_counters.tracker_age_s.store(out.tracker_age_s, std::memory_order_relaxed);
  status_counters.in_contact.store(out.in_contact, std::memory_order_relaxed);
}

}  // namespace mhd
