// The io thread: tracker samples through TrackerSampleFilter to the
// haptic thread (base sensor) and the planner (head); the planner's command through the
// BaseCommandGuard to the base when BaseCommandScheduler says so. After it starts, it
// takes no lock and allocates nothing: lock-free hand-offs, a claim on the base that never
// waits, fixed buffers (haptic_thread_hygiene_test.cpp watches it).
#include "haptic_server/server_impl.h"

#include "haptic_server/base_command_scheduler.h"
#include "haptic_server/floor_tracker.h"
#include "haptic_server/physical_range.h"
#include "haptic_server/safe_stop.h"
#include "haptic_server/tracker_sample_filter.h"
#include "realtime/periodic_timer.h"
#include "realtime/thread_name.h"
#include "realtime/thread_priority.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <thread>

namespace mhd {

/// What the io thread keeps from one period to the next.
struct HapticServer::Impl::IoThreadState {
  IoThreadState(const ServerSettings& settings, BaseCommandGuardSettings guard_settings)
      : guard(guard_settings),
        filter({.base_sensor_id = settings.base_sensor_id,
                .head_sensor_id = settings.head_sensor_id,
                .other_rigs = settings.other_rigs,
                .tracking_range_m = settings.tracking_range_m}),
        floor(settings.other_rigs),
        scheduler(1.0 / settings.base_rate_hz) {}

  BaseCommandGuard guard;
  TrackerSampleFilter filter;
  FloorTracker floor;
  BaseCommandScheduler scheduler;
  std::array<TrackerSample, 64> samples{};
  double newest_base_sample_t_s = -std::numeric_limits<double>::infinity();
  BaseTwist planned;
  BaseStopCounts counts_published;
  // The plugin's own counts (samples it dropped, and why), for the status line.
  std::array<CounterReading, PluginCounterFrame::kMax> counter_buffer{};
  PluginCounterFrame counters;
  double next_counters_t_s = 0.0;
};

namespace {

constexpr double kCountersInterval_s = 0.25;
// Between deadlines, a tracker that can wait wakes this thread the moment a sample
// arrives; the last moments before a deadline are slept precisely by the timer.
constexpr double kWakeMargin_s = 100e-6;

}  // namespace

void HapticServer::Impl::io_thread() {
  realtime::name_current_thread(realtime::kIoThreadName);
  BaseCommandGuardSettings guard_settings = settings.base_guard;
  guard_settings.command_hold_s = 1.0 / settings.io_rate_hz;
  IoThreadState io(settings, guard_settings);
  io.next_counters_t_s = host.now_s();
  // Tracker input is on the force's critical path (stale poses fade the force out), so it
  // runs real-time too, below the haptic thread.
  (void)realtime::make_current_thread_realtime(70);
  realtime::PeriodicTimer timer(1.0 / settings.io_rate_hz);

  while (!stop.load(std::memory_order_relaxed)) {
    if (tick_on_tracker_sample && !take_samples_until_deadline(io, timer)) break;
    (void)timer.wait_next();
    const double t_s = host.now_s();
    if (!simulate_io_plugins(t_s)) break;
    if (!read_tracker(io) || !read_tracker_counters(io, t_s)) break;
    if (base == nullptr) continue;
    if (!read_base(io, t_s)) break;
    bool new_plan = false;
    const BaseGuardDecision guarded = guard_plan(io, t_s, new_plan);
    if (stop.load(std::memory_order_relaxed)) break;  // nothing but the stop after the run ended
    if (!send_base_command(io, t_s, new_plan, guarded)) break;
  }

  // Safe state: the base stops, whatever ended the loop.
  stop_base();
}

bool HapticServer::Impl::take_samples_until_deadline(IoThreadState& io, const realtime::PeriodicTimer& timer) {
  for (;;) {
    const double remaining_s = timer.next_deadline_s() - realtime::PeriodicTimer::monotonic_now_s() - kWakeMargin_s;
    if (remaining_s <= 0.0 || stop.load(std::memory_order_relaxed)) return true;
    auto w = [&] {
      const InCall in_call(*tracker, "tracker_wait", host.now_s());
      return tracker->instance.tracker_wait(remaining_s);
    }();
    if (check(w, *tracker) || deactivated(w.value(), *tracker, "tracker_wait")) return false;
    if (w.value() != PluginCallStatus::Ok) return true;  // timed out
    const std::optional<std::size_t> taken = read_tracker(io);
    if (!taken) return false;
    // Woken with nothing to read: a plugin that keeps saying so would spin this
    // real-time thread, so sleep to the deadline instead.
    if (*taken == 0) return true;
  }
}

bool HapticServer::Impl::simulate_io_plugins(double t_s) {
  if (base != nullptr && base->instance.simulates()) {
    const ClaimedCall claimed(*base->call_claim);
    if (!claimed.taken()) return false;  // run()'s thread is stopping the base: the run ends
    const InCall in_call(*base, "simulate_until", t_s);
    if (check(base->instance.simulate_until(t_s), *base)) return false;
  }
  if (tracker->instance.simulates()) {
    const InCall in_call(*tracker, "simulate_until", t_s);
    if (check(tracker->instance.simulate_until(t_s), *tracker)) return false;
  }
  return true;
}

std::optional<std::size_t> HapticServer::Impl::read_tracker(IoThreadState& io) {
  // Everything the tracker has received since the last read: checked, then base-sensor
  // samples to the haptic thread (woken for them) and head samples to the planner.
  std::size_t taken = 0;
  bool base_sample = false;
  for (;;) {
    std::size_t count = 0;
    auto r = [&] {
      const InCall in_call(*tracker, "tracker_read", host.now_s());
      return tracker->instance.tracker_read(io.samples, count);
    }();
    if (check(r, *tracker) || deactivated(r.value(), *tracker, "tracker_read")) return std::nullopt;
    taken += count;
    const double read_at_s = host.now_s();  // after the read: a sample is never newer than this
    for (std::size_t i = 0; i < count; ++i) {
      if (!take_sample(io, io.samples[i], read_at_s, base_sample)) return std::nullopt;
    }
    if (count < io.samples.size()) break;
  }
  if (base_sample && tick_on_tracker_sample) base_sample_arrived.signal();
  return taken;
}

bool HapticServer::Impl::take_sample(IoThreadState& io, const TrackerSample& s, double read_at_s,
                                     bool& base_sample) {
  const Eigen::Vector3d p_T_m(s.p_T_m[0], s.p_T_m[1], s.p_T_m[2]);
  const TrackerSampleVerdict verdict = io.filter.check(s, read_at_s);
  if (verdict == TrackerSampleVerdict::ImplausiblePosition) {
    fail(Diagnostic{tracker->description.where,
                    plugin_said(*tracker, tracked_position_fault(s.sensor_id, p_T_m, settings.tracking_range_m))}
             .to_string());
    return false;
  }
  if (verdict != TrackerSampleVerdict::Accepted) {
    status_counters.tracker_rejected.fetch_add(1, std::memory_order_relaxed);
    return true;
  }
  status_counters.tracker_samples.fetch_add(1, std::memory_order_relaxed);
  const Pose X_T_S =
      pose_from_xyz_quaternion(p_T_m, Eigen::Quaterniond(s.q_T_wxyz[0], s.q_T_wxyz[1], s.q_T_wxyz[2], s.q_T_wxyz[3]));
  if (const std::optional<FloorSlot> slot = io.floor.slot_of(s.sensor_id)) {
    // Another rig's user or base: where it stands on the floor, for the planner's keep-outs.
    Eigen::Vector2d p_W;
    if (slot->base) {
      const BasePose b = rig.base_from_sensor(X_T_S);
      p_W = Eigen::Vector2d(b.x_m, b.z_m);
    } else {
      const Eigen::Vector3d p = rig.X_W_is900() * X_T_S.translation();
      p_W = Eigen::Vector2d(p.x(), p.z());
    }
    io.floor.take(*slot, s.timestamp_s, p_W);
    floor_view.write(io.floor.view());
    return true;
  }
  if (s.sensor_id == settings.base_sensor_id) {
    if (settings.base_pose_source == BasePoseSource::Odometry) return true;  // the base's own pose rules
    if (!base_samples.push({s.timestamp_s, X_T_S})) status_counters.tracker_rejected.fetch_add(1, std::memory_order_relaxed);
    io.newest_base_sample_t_s = std::max(io.newest_base_sample_t_s, s.timestamp_s);
    base_sample_newest_t_s.store(io.newest_base_sample_t_s, std::memory_order_relaxed);
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
  return true;
}

bool HapticServer::Impl::read_tracker_counters(IoThreadState& io, double t_s) {
  if (!tracker->instance.counts() || t_s < io.next_counters_t_s) return true;
  io.next_counters_t_s = t_s + kCountersInterval_s;
  auto n = [&] {
    const InCall in_call(*tracker, "counters", t_s);
    return tracker->instance.counters(io.counter_buffer);
  }();
  if (check(n, *tracker)) return false;
  for (std::size_t i = 0; i < n.value(); ++i) {
    io.counters.names[i] = io.counter_buffer[i].name;
    io.counters.values[i] = io.counter_buffer[i].value;
  }
  io.counters.count = n.value();
  status_counters.tracker_plugin_counters.write(io.counters);
  return true;
}

bool HapticServer::Impl::read_base(IoThreadState& io, double t_s) {
  BaseState base_state{};
  const ClaimedCall claimed(*base->call_claim);
  if (!claimed.taken()) return false;  // run()'s thread is stopping the base: the run ends
  auto br = [&] {
    const InCall in_call(*base, "base_read", t_s);
    return base->instance.base_read(base_state);
  }();
  if (check(br, *base) || deactivated(br.value(), *base, "base_read")) return false;
  if (br.value() == PluginCallStatus::Ok && !base_position_plausible(base_state, settings.tracking_range_m)) {
    fail(Diagnostic{base->description.where, plugin_said(*base, base_position_fault(base_state, settings.tracking_range_m))}
             .to_string());
    return false;
  }
  if (br.value() == PluginCallStatus::Ok && settings.base_pose_source == BasePoseSource::Odometry) {
    take_odometry(io, base_state);
  }
  return br.value() != PluginCallStatus::Ok || take_lift(base_state);
}

bool HapticServer::Impl::take_lift(const BaseState& base_state) {
  // The arm's height is only known when the base and the rig agree that there is a lift,
  // and where it stands is inside the rig's range (its end stops, with a margin for the
  // controller's overshoot); anything else ends the run rather than place the arm wrongly.
  // The texts are built only on the way out.
  constexpr double kRangeMargin_m = 0.01;
  const std::optional<Lift>& lift = rig.lift();
  if (lift.has_value() != base_state.has_lift) {
    fail(Diagnostic{base->description.where,
                    plugin_said(*base, lift ? "the rig has a <lift>, but this base reports none"
                                            : "this base reports a lift, but the rig has no <lift>: declare it in "
                                              "the rig (docs/kinematics.md, \"The lift\")")}
             .to_string());
    return false;
  }
  if (!lift) return true;
  if (base_state.lift_m < lift->min_m - kRangeMargin_m || base_state.lift_m > lift->max_m + kRangeMargin_m) {
    fail(Diagnostic{base->description.where,
                    plugin_said(*base, lift_position_fault(base_state.lift_m, lift->min_m, lift->max_m))}
             .to_string());
    return false;
  }
  lift_reading.write({base_state.lift_m, base_state.lift_vmps, base_state.timestamp_s});
  return true;
}

double HapticServer::Impl::lift_m_at(double t_s) const noexcept {
  const std::array<double, 3> r = lift_reading.read();
  const double ahead_s = std::clamp(t_s - r[2], 0.0, 1.0 / settings.io_rate_hz);
  return r[0] + r[1] * ahead_s;
}

void HapticServer::Impl::take_odometry(IoThreadState& io, const BaseState& base_state) {
  // The base's own pose, in the world: the sample the base sensor would have given there.
  if (!std::isfinite(base_state.heading_rad) || !std::isfinite(base_state.timestamp_s)) {
    status_counters.tracker_rejected.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  const Pose X_T_S =
      rig.X_is900_base_sensor_from_base(BasePose{base_state.x_m, base_state.z_m, base_state.heading_rad});
  if (!base_samples.push({base_state.timestamp_s, X_T_S})) {
    status_counters.tracker_rejected.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  io.newest_base_sample_t_s = std::max(io.newest_base_sample_t_s, base_state.timestamp_s);
  base_sample_newest_t_s.store(io.newest_base_sample_t_s, std::memory_order_relaxed);
}

BaseGuardDecision HapticServer::Impl::guard_plan(IoThreadState& io, double t_s, bool& new_plan) {
  // The planner's newest command, through the guard: stale base or head data stops the
  // base at once.
  new_plan = planned_command.read(io.planned);
  const HeadState h = head.get();
  BaseGuardInput judged;
  judged.t_s = t_s;
  judged.X_WB = snapshot_for_io.latest().base;
  judged.base_age_s = t_s - io.newest_base_sample_t_s;
  if (h.known) {
    judged.p_W_head_xz_m = Eigen::Vector2d(h.p_W_m.x(), h.p_W_m.z());
    judged.head_age_s = t_s - h.t_s;
  }
  const BaseGuardDecision guarded = io.guard.apply(io.planned, judged);
  if (io.guard.counts().stops() != io.counts_published.stops() ||
      io.guard.counts().keep_out_deflections != io.counts_published.keep_out_deflections) {
    io.counts_published = io.guard.counts();
    base_stop_counts.write(io.counts_published);
  }
  return guarded;
}

bool HapticServer::Impl::send_base_command(IoThreadState& io, double t_s, bool new_plan,
                                           const BaseGuardDecision& guarded) {
  // Commands go out at the base rate (and feed the base's watchdog).
  if (!io.scheduler.should_send(t_s, new_plan, guarded.twist_B)) return true;
  BaseCommand cmd{};
  cmd.timestamp_s = t_s;
  cmd.vx_mps = guarded.twist_B.vx_mps;
  cmd.vz_mps = guarded.twist_B.vz_mps;
  cmd.omega_radps = guarded.twist_B.omega_radps;
  // The lift stops with the base: a stale hand or head stops both.
  if (rig.lift() && guarded.action != BaseGuardAction::Stopped) {
    cmd.lift_vmps = planned_lift_vmps.load(std::memory_order_relaxed);
  }
  const ClaimedCall claimed(*base->call_claim);
  if (!claimed.taken()) return false;  // run()'s thread is stopping the base: the run ends
  auto bw = [&] {
    const InCall in_call(*base, "base_write", t_s);
    return base->instance.base_write(cmd);
  }();
  if (check(bw, *base) || deactivated(bw.value(), *base, "base_write")) return false;
  io.scheduler.sent(t_s, guarded.twist_B);
  base_commands.fetch_add(1, std::memory_order_relaxed);
  if (guarded.action == BaseGuardAction::Stopped) base_stops.fetch_add(1, std::memory_order_relaxed);
  // The haptic thread drains this every tick; a full ring means it is stuck, and the
  // predictor simply runs without this command.
  (void)commands_to_haptic.push({t_s, guarded.twist_B});
  return true;
}

void HapticServer::Impl::stop_base() {
  if (base == nullptr) {
    base_stop_sent.store(true);
    return;
  }
  // Bounded: the io thread may itself be stuck inside the base.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::milliseconds(200);
  while (!base->call_claim->try_take()) {
    if (std::chrono::steady_clock::now() >= give_up) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  struct GiveBack {
    CallClaim& claim;
    ~GiveBack() { claim.give_back(); }
  } give_back{*base->call_claim};
  if (base->instance.state() == PluginState::Running) {
    const InCall in_call(*base, "base_write", host.now_s());
    base_stop_sent.store(send_base_stop(&base->instance, host));
  }
}

}  // namespace mhd
