// The io thread: tracker samples through TrackerSampleFilter to the
// haptic thread (base sensor) and the planner (head); the planner's command through the
// BaseCommandGuard to the base when BaseCommandScheduler says so.
#include "haptic_server/server_impl.h"

#include "haptic_server/base_command_scheduler.h"
#include "haptic_server/physical_range.h"
#include "haptic_server/safe_stop.h"
#include "haptic_server/tracker_sample_filter.h"
#include "realtime/periodic_timer.h"
#include "realtime/thread_name.h"
#include "realtime/thread_priority.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <limits>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace mhd {

void HapticServer::Impl::io_thread() {
  realtime::name_current_thread("mhd-io");
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
          if (!base_samples.push({s.timestamp_s, X_T_S})) {
            status_counters.tracker_rejected.fetch_add(1, std::memory_order_relaxed);
          }
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
    if (br.value() == PluginCallStatus::Ok && !base_position_plausible(base_state, settings.tracking_range_m)) {
      fail(Diagnostic{base->description.where,
                      plugin_said(*base, base_position_fault(base_state, settings.tracking_range_m))}
               .to_string());
      break;
    }

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
    const BaseGuardDecision guarded = guard.apply(planned, judged);
    if (guard.counts().stops() != counts_published.stops() ||
        guard.counts().keep_out_deflections != counts_published.keep_out_deflections) {
      counts_published = guard.counts();
      base_stop_counts.set(counts_published);
    }
    if (stop.load(std::memory_order_relaxed)) break;  // nothing but the stop after the run ended
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

}  // namespace mhd
