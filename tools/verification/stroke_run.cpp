#include "verification/stroke_run.h"

#include "proxy/proxy_look_ahead.h"
#include "realtime/thread_page_faults.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

namespace mhd::verify {
namespace {

double quantile(const std::vector<double>& sorted, double q) {
  const auto index = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size()))) - 1;
  return sorted[std::min(index, sorted.size() - 1)];
}

}  // namespace

LatencySummary summarize_latency(std::vector<double>& samples_us) {
  LatencySummary s;
  if (samples_us.empty()) return s;
  std::sort(samples_us.begin(), samples_us.end());
  s.count = samples_us.size();
  s.median_us = quantile(samples_us, 0.5);
  s.p99_us = quantile(samples_us, 0.99);
  s.p999_us = quantile(samples_us, 0.999);
  s.max_us = samples_us.back();
  return s;
}

namespace {

// The ticks of every stroke, and with an oracle the exact counts.
StrokeRunReport drive_strokes(const CompiledScene& scene, const SurfaceCrossingOracle* oracle,
                              const StrokeSet& strokes, double rate_Hz, bool look_ahead) {
  using Clock = std::chrono::steady_clock;
  StrokeRunReport report;
  std::vector<double> contact_us;
  std::vector<double> all_us;
  std::vector<double> look_ahead_us;
  // Room for every tick's time, written once up front: no growth of these, and none of
  // their page faults, between the ticks.
  std::size_t tick_count = 0;
  for (const Stroke& stroke : strokes.strokes) tick_count += stroke.p_W_hip.size();
  for (std::vector<double>* v : {&contact_us, &all_us, &look_ahead_us}) {
    v->assign(tick_count, 0.0);
    v->clear();
  }
  double contact_force_sum = 0.0;
  const double dt_s = 1.0 / rate_Hz;
  const auto objects = static_cast<std::size_t>(scene.world.object_count());
  report.contact_ticks_by_object.assign(objects, 0);
  report.force_sum_by_object_N.assign(objects, 0.0);
  const FollowTolerance follow = follow_tolerance(scene.materials);
  TickRecord record;
  // This thread's alone: the ticks run here, and the process may have others (a loader's).
  const realtime::PageFaults faults_before = realtime::current_thread_page_faults();
  for (const Stroke& stroke : strokes.strokes) {
    if (stroke.p_W_hip.empty()) continue;
    ++report.strokes;
    record.clear();
    if (oracle != nullptr) record.reserve(stroke.p_W_hip.size());
    ProxyState state;
    reset_proxy(state, stroke.p_W_hip.front());
    ProxyLookAhead ahead;
    for (const Eigen::Vector3d& hip : stroke.p_W_hip) {
      const auto t0 = Clock::now();
      const ProxyOutput out = step_proxy(scene.world, scene.materials, scene.proxy, state, hip, dt_s);
      const auto t1 = Clock::now();
      const double us = std::chrono::duration<double, std::micro>(t1 - t0).count();
      all_us.push_back(us);
      ++report.ticks;
      if (out.in_contact) {
        contact_us.push_back(us);
        ++report.contact_ticks;
        contact_force_sum += out.force_W.norm();
        if (out.contact_object >= 0 && static_cast<std::size_t>(out.contact_object) < objects) {
          ++report.contact_ticks_by_object[static_cast<std::size_t>(out.contact_object)];
          report.force_sum_by_object_N[static_cast<std::size_t>(out.contact_object)] += out.force_W.norm();
        }
      }
      if (out.force_clamped) ++report.clamped_ticks;
      report.max_force_N = std::max(report.max_force_N, out.force_W.norm());
      report.max_plane_count = std::max(report.max_plane_count, out.plane_count);
      if (out.budget_exhausted) ++report.budget_exhausted_ticks;
      report.max_sweeps = std::max(report.max_sweeps, out.sweeps);
      if (oracle != nullptr) record.push_back(make_tick_sample(hip, out, state));  // only the oracle reads it
      if (look_ahead) {
        const auto t2 = Clock::now();
        (void)ahead.run(scene.world, scene.materials, scene.proxy, state, dt_s);
        look_ahead_us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t2).count());
      }
    }
    if (oracle == nullptr) continue;
    report.pop_throughs += count_crossings(*oracle, record);
    report.ticks_inside += count_ticks_inside(*oracle, record);
    report.held_ticks += count_held_ticks(*oracle, record);
    const std::array<std::size_t, 1> first{0};
    const std::span<const std::size_t> starts = stroke.stroke_starts.empty()
                                                    ? std::span<const std::size_t>(first)
                                                    : std::span<const std::size_t>(stroke.stroke_starts);
    report.strokes_begun += starts.size();
    report.strokes_starting_behind += count_strokes_starting_behind(*oracle, record, starts);
    const FollowCheck follow_check = find_follow_failures(*oracle, record, follow);
    report.follow_failures += follow_check.failures.size();
    report.max_free_gap_m = std::max(report.max_free_gap_m, follow_check.max_free_gap_m);
  }
  if (oracle == nullptr) {
    const realtime::PageFaults faults = realtime::current_thread_page_faults() - faults_before;
    report.minor_page_faults = faults.minor;
    report.major_page_faults = faults.major;
  }
  report.mean_contact_force_N =
      report.contact_ticks > 0 ? contact_force_sum / static_cast<double>(report.contact_ticks) : 0.0;
  report.contact_updates = summarize_latency(contact_us);
  report.all_updates = summarize_latency(all_us);
  report.look_ahead_updates = summarize_latency(look_ahead_us);
  return report;
}

}  // namespace

StrokeRunReport run_strokes(const CompiledScene& scene, const SurfaceCrossingOracle& oracle,
                            const StrokeSet& strokes, double rate_Hz, bool look_ahead) {
  return drive_strokes(scene, &oracle, strokes, rate_Hz, look_ahead);
}

StrokeRunReport time_strokes(const CompiledScene& scene, const StrokeSet& strokes, double rate_Hz, bool look_ahead) {
  return drive_strokes(scene, nullptr, strokes, rate_Hz, look_ahead);
}

}  // namespace mhd::verify
