// Fault injection: each fault, injected through the real dlopen path
// into mhd::HapticServer (or into `mhd run`, killed with SIGKILL), must end in the safe
// state: zero torque last written to the device, the base commanded to stop, and a
// message naming the plugin and its scene line. The safe state is checked from the
// hardware's side: fi_device and fi_base log every command they get, with its time.
// The timing bounds are those of docs/haptic_server.md (force 0 at 50 ms of
// tracker silence, base stopped within 100 ms, a killed run's recording <= 100 ms old),
// measured on the host clock the server stamps its commands and rows with; each test
// prints its figures ("figure: ...") for docs/reliability/fault_injection.md.
//
// The existing tests/haptic_server cases cover a device or base failing out of contact
// and a tracker going silent for good; these add the faults while force is non-zero, a
// tracker that comes back, jittery and lossy trackers, failing writes and kill -9.
#include "fault_injection_support.h"

#include "kinematics/rig.h"
#include "planner/planner_settings.h"
#include "recording/csv_recording_reader.h"
#include "scene_xml/scene_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <sys/wait.h>
#include <thread>

namespace {

using namespace mhd;
using namespace mhd::fault_injection_test;
using ::testing::HasSubstr;

constexpr double kPressAt_s = 0.05;   // the probe device presses 4 mm into the block from here
constexpr double kContactForce_N = 2.0;  // 1000 N/m x 4 mm = 4 N at full gain; above this: pressing
// The planner keeps asking the base to drive forward at 5 cm/s: a stop is the guard's doing.
const BasePlanFn kMovingBase = [](const BasePlanInput&) { return BaseTwist{0.05, 0.0, 0.0}; };

void figure(const std::string& text) { std::cout << "figure: " << text << std::endl; }

std::vector<LogRow> without_markers(const std::vector<LogRow>& rows) {
  std::vector<LogRow> out;
  for (const LogRow& r : rows) {
    if (!r.is_marker()) out.push_back(r);
  }
  return out;
}

std::optional<double> marker_time(const std::vector<LogRow>& rows) {
  for (const LogRow& r : rows) {
    if (r.is_marker()) return r.t_s;
  }
  return std::nullopt;
}

/// A delivered base-sensor sample, from fi_tracker's delivery log.
struct Delivery {
  double timestamp_s, arrival_s;
};

std::vector<Delivery> base_deliveries(const fs::path& log) {
  std::vector<Delivery> out;
  for (const LogRow& r : read_log(log)) {
    if (r.c == 0.0) out.push_back({r.t_s, r.a});
  }
  return out;
}

/// Rows from the first with a HIP (a base pose known) plus `settle_s`.
std::vector<RecordingRow> rows_after_start(const std::vector<RecordingRow>& rows, double settle_s) {
  std::vector<RecordingRow> out;
  double first_s = -1.0;
  for (const RecordingRow& r : rows) {
    if (first_s < 0.0 && std::isfinite(r.p_W_hip[0])) first_s = r.t_s;
    if (first_s >= 0.0 && r.t_s >= first_s + settle_s) out.push_back(r);
  }
  return out;
}

/// The largest HIP step per millisecond of tick between consecutive rows.
double max_hip_step_per_ms(const std::vector<RecordingRow>& rows) {
  double worst = 0.0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double d = std::hypot(rows[i].p_W_hip[0] - rows[i - 1].p_W_hip[0], rows[i].p_W_hip[1] - rows[i - 1].p_W_hip[1],
                                rows[i].p_W_hip[2] - rows[i - 1].p_W_hip[2]);
    worst = std::max(worst, d / std::max(1.0, rows[i].dt_s / 0.001));
  }
  return worst;
}

bool row_finite(const RecordingRow& r) {
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (!std::isfinite(r.p_W_hip[k]) || !std::isfinite(r.force_W_N[k]) || !std::isfinite(r.force_D_N[k])) return false;
  }
  return std::isfinite(r.safety_gain);
}

/// A tracker <plugin> for fi_tracker with the given extra <param> lines. It measures the
/// head too (the guard moves the base only on fresh head data), of a user standing 3 m
/// behind the base, outside its keep-out whatever the data's age.
std::string fi_tracker_xml(const fs::path& log, const std::string& params) {
  return fmt::format(R"(
    <plugin kind="tracker" name="fi_tracker">
      <param name="delivery_log" value="{}"/>
      <param name="head_p_W_m" value="-3 1.7 0"/>
{}    </plugin>)", log.string(), params);
}

std::string fi_base_xml(const fs::path& log, const std::string& params = "") {
  return fmt::format(R"(
    <plugin kind="base" name="fi_base">
      <param name="command_log" value="{}"/>
{}    </plugin>)", log.string(), params);
}

std::string param(const std::string& name, const std::string& value) {
  return fmt::format("      <param name=\"{}\" value=\"{}\"/>\n", name, value);
}

// ---- 1. tracker silent -----------------------------------------------------------------

TEST(TrackerFaults, SilentTrackerZeroesForceWithin50msStopsTheBaseWithin100msAndRecovers) {
  const fs::path dir = temp_dir();
  const PressGeometry g = press_geometry(0.004);
  const fs::path device_log = dir / "device.log", base_log = dir / "base.log", tracker_log = dir / "tracker.log";
  const fs::path file = write_scene(
      dir, g,
      fi_device_xml(g, device_log, kPressAt_s) +
          fi_tracker_xml(tracker_log, param("silent_after_s", "0.4") + param("resume_after_s", "0.7")) +
          fi_base_xml(base_log),
      "");
  const RunResult run = run_server(load(file), 1.1, dir / "run.csv", kMovingBase);
  ASSERT_TRUE(run.opened);
  const ServerReport& r = run.report;
  EXPECT_FALSE(r.error) << *r.error;  // silence is not a fault: the run goes on
  EXPECT_EQ(r.ended_by, RunEnd::Duration);
  EXPECT_TRUE(r.zero_force_sent);
  EXPECT_TRUE(r.base_stop_sent);
  EXPECT_GT(r.stale_ticks, 100u);
  EXPECT_GT(r.base_stops, 0u);

  // The silence, from the tracker's side: the last sample before it, the first after.
  const std::vector<Delivery> samples = base_deliveries(tracker_log);
  std::size_t gap = 0;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    if (samples[i].timestamp_s - samples[i - 1].timestamp_s > 0.1) gap = i;
  }
  ASSERT_GT(gap, 0u) << "no silence in the tracker's deliveries";
  const double last_s = samples[gap - 1].timestamp_s;     // measured before the silence
  const double resumed_s = samples[gap].arrival_s;         // the first sample after it arrives
  ASSERT_GT(resumed_s - last_s, 0.25);

  // Pressing when the tracker fell silent.
  const std::vector<RecordingRow> rows = read_rows(dir / "run.csv");
  ASSERT_GT(rows.size(), 500u);
  std::size_t pressing = 0, near_silence = 0;
  for (const RecordingRow& row : rows) {
    if (row.t_s > last_s - 0.05 && row.t_s <= last_s) {
      ++near_silence;
      if (force_N(row) > kContactForce_N && row.safety_gain == 1.0) ++pressing;
    }
  }
  EXPECT_GT(near_silence, 20u);
  EXPECT_EQ(pressing, near_silence) << "not pressing at full gain when the tracker fell silent";

  // The device: no torque from 50 ms after the last sample until samples are back.
  const std::vector<LogRow> device = without_markers(read_log(device_log));
  double last_torque_s = last_s;
  std::size_t zero_commands = 0, late_torques = 0;
  for (const LogRow& c : device) {
    if (c.t_s <= last_s || c.t_s >= resumed_s) continue;
    if (c.is_zero()) {
      ++zero_commands;
    } else {
      last_torque_s = std::max(last_torque_s, c.t_s);
      if (c.t_s >= last_s + 0.05) ++late_torques;
    }
  }
  EXPECT_EQ(late_torques, 0u);
  EXPECT_LT(last_torque_s - last_s, 0.05);
  EXPECT_GT(zero_commands, 150u);
  figure(fmt::format("silent tracker: last torque {:.1f} ms after the last sample", 1e3 * (last_torque_s - last_s)));

  // The fade itself (recording): full gain until 30 ms, then falling, never rising, to 0.
  double previous_gain = 1.0;
  for (const RecordingRow& row : rows) {
    if (row.t_s <= last_s || row.t_s >= resumed_s) continue;
    const double age_s = row.t_s - last_s;
    if (age_s < 0.029) {
      EXPECT_EQ(row.safety_gain, 1.0) << "at " << age_s << " s";
    }
    EXPECT_LE(row.safety_gain, previous_gain) << "at " << age_s << " s";
    if (age_s >= 0.05) {
      EXPECT_EQ(force_N(row), 0.0) << "at " << age_s << " s";
    }
    previous_gain = row.safety_gain;
  }

  // The base: moving before, stopped within 100 ms of the last sample, until samples resume.
  const std::vector<LogRow> base = without_markers(read_log(base_log));
  ASSERT_FALSE(base.empty());
  EXPECT_TRUE(std::any_of(base.begin(), base.end(), [&](const LogRow& c) { return c.t_s < last_s && c.a == 0.05; }));
  std::optional<double> stop_s;
  std::size_t moving_while_stopped = 0;
  for (const LogRow& c : base) {
    // A command stamped at the io tick that picks up the first sample after the silence
    // may carry a time up to one tick before that sample's arrival: 2 ms of margin.
    if (c.t_s <= last_s || c.t_s >= resumed_s - 0.002) continue;
    if (!stop_s && c.is_zero()) stop_s = c.t_s;
    if (stop_s && !c.is_zero()) ++moving_while_stopped;
  }
  ASSERT_TRUE(stop_s) << "the base was not stopped during the silence";
  EXPECT_LE(*stop_s - last_s, 0.1);
  EXPECT_EQ(moving_while_stopped, 0u);
  figure(fmt::format("silent tracker: base stop command {:.1f} ms after the last sample", 1e3 * (*stop_s - last_s)));

  // No HIP leap when samples resume (the predictor holds the pose through the silence).
  const double step = max_hip_step_per_ms(rows_after_start(rows, 0.2));
  EXPECT_LT(step, 0.001);
  figure(fmt::format("silent tracker: max HIP step after start-up {:.3f} mm/ms; {} HIP jumps in all (start-up)",
                     1e3 * step, r.hip_jumps));

  // Recovery: full force again once samples are back (fade-in 0.1 s), and the base moves.
  std::size_t recovered = 0, after = 0;
  for (const RecordingRow& row : rows) {
    if (row.t_s < resumed_s + 0.15) continue;
    ++after;
    if (row.safety_gain == 1.0 && force_N(row) > kContactForce_N) ++recovered;
  }
  EXPECT_GT(after, 100u);
  EXPECT_EQ(recovered, after);
  EXPECT_TRUE(std::any_of(base.begin(), base.end(), [&](const LogRow& c) { return c.t_s > resumed_s && c.a == 0.05; }));
  // And the end of the run leaves the hardware safe.
  ASSERT_FALSE(device.empty());
  EXPECT_TRUE(device.back().is_zero());
  EXPECT_TRUE(base.back().is_zero());
}

// ---- 2. tracker jittery ----------------------------------------------------------------

/// What a jittery run's recording says about the force's gain.
struct GainFigures {
  std::size_t ticks = 0, reduced = 0, off = 0, pressing = 0, not_finite = 0, over_limit = 0, above_proxy = 0;
  std::size_t dips = 0;      ///< runs of ticks at reduced gain
  std::size_t jolts = 0;     ///< ticks where the gain rose by more than 0.1 at once
  double min_gain = 1.0, max_rise = 0.0;
  double max_rise_per_s = 0.0;  ///< the steepest rise per second of the tick's own dt_s
  double hip_step_m_per_ms = 0.0;
};

GainFigures gain_figures(const std::vector<RecordingRow>& rows, double max_force_N) {
  GainFigures f;
  f.ticks = rows.size();
  bool in_dip = false;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const RecordingRow& row = rows[i];
    if (!row_finite(row)) ++f.not_finite;
    if (force_N(row) > max_force_N + 1e-9) ++f.over_limit;
    const double proxy_N = std::hypot(row.cmd_force_W_N[0], row.cmd_force_W_N[1], row.cmd_force_W_N[2]);
    if (force_N(row) > proxy_N + 1e-9) ++f.above_proxy;
    if (row.safety_gain < 1.0) ++f.reduced;
    if (row.safety_gain == 0.0) ++f.off;
    if (force_N(row) > kContactForce_N) ++f.pressing;
    f.min_gain = std::min(f.min_gain, row.safety_gain);
    if (row.safety_gain < 1.0 && !in_dip) ++f.dips;
    in_dip = row.safety_gain < 1.0;
    if (i > 0) {
      const double rise = row.safety_gain - rows[i - 1].safety_gain;
      f.max_rise = std::max(f.max_rise, rise);
      if (rise > 0.1) ++f.jolts;
      if (rise > 0.0 && row.dt_s > 0.0) f.max_rise_per_s = std::max(f.max_rise_per_s, rise / row.dt_s);
    }
  }
  f.hip_step_m_per_ms = max_hip_step_per_ms(rows);
  return f;
}

struct JitterRun {
  RunResult run;
  double min_delay_s = 1.0, max_delay_s = 0.0, worst_age_s = 0.0;  ///< from the tracker's deliveries
  GainFigures gain;
};

JitterRun run_jittery(const std::string& delay_ms, const std::string& jitter_ms) {
  JitterRun out;
  const fs::path dir = temp_dir();
  const PressGeometry g = press_geometry(0.004);
  const fs::path tracker_log = dir / "tracker.log";
  const fs::path file = write_scene(
      dir, g,
      fi_device_xml(g, dir / "device.log", kPressAt_s) +
          fi_tracker_xml(tracker_log, param("delay_ms", delay_ms) + param("jitter_ms", jitter_ms) + param("seed", "5")) +
          fi_base_xml(dir / "base.log"),
      "");
  out.run = run_server(load(file), 1.2, dir / "run.csv", kMovingBase);
  const std::vector<Delivery> samples = base_deliveries(tracker_log);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    out.min_delay_s = std::min(out.min_delay_s, samples[i].arrival_s - samples[i].timestamp_s);
    out.max_delay_s = std::max(out.max_delay_s, samples[i].arrival_s - samples[i].timestamp_s);
    if (i > 0) out.worst_age_s = std::max(out.worst_age_s, samples[i].arrival_s - samples[i - 1].timestamp_s);
  }
  out.gain = gain_figures(rows_after_start(read_rows(dir / "run.csv"), 0.2), out.run.settings.tick.safety.max_force_N);
  figure(fmt::format("jittery tracker {} +- {} ms: delay {:.1f}..{:.1f} ms, worst age before an arrival {:.1f} ms; "
                     "{} of {} ticks at reduced gain in {} dips, min gain {:.2f}, {} ticks at zero, "
                     "{} gain rises > 0.1 per tick (largest {:.2f}); max HIP step {:.3f} mm/ms; "
                     "{} HIP jumps in all (start-up)",
                     delay_ms, jitter_ms, 1e3 * out.min_delay_s, 1e3 * out.max_delay_s, 1e3 * out.worst_age_s,
                     out.gain.reduced, out.gain.ticks, out.gain.dips, out.gain.min_gain, out.gain.off, out.gain.jolts,
                     out.gain.max_rise, 1e3 * out.gain.hip_step_m_per_ms, out.run.report.hip_jumps));
  return out;
}

/// What any jitter must leave intact: finite values, the limit, no HIP leap.
void expect_sound(const JitterRun& j) {
  ASSERT_TRUE(j.run.opened);
  const ServerReport& r = j.run.report;
  EXPECT_FALSE(r.error) << *r.error;
  EXPECT_TRUE(r.zero_force_sent);
  EXPECT_TRUE(r.base_stop_sent);
  EXPECT_GT(j.gain.ticks, 500u);
  EXPECT_EQ(j.gain.not_finite, 0u);
  EXPECT_EQ(j.gain.over_limit, 0u);
  EXPECT_EQ(j.gain.above_proxy, 0u);  // safety only ever takes force away
  EXPECT_LT(j.gain.hip_step_m_per_ms, 0.001);  // 1 mm per ms: a tenth of the jump threshold
}

TEST(TrackerFaults, JitterOf20msAroundTheNominalArrivalNeverTurnsTheForceOff) {
  // Each sample arrives 4 ms latency + U(-20, +20) ms (never before it was measured), in
  // order: late ones hold back the next, which then arrive bunched.
  const JitterRun j = run_jittery("0", "20");
  expect_sound(j);
  EXPECT_GT(j.max_delay_s - j.min_delay_s, 0.015);  // the jitter is there
  // The newest measurement is at most max delay + one period old when the next arrives
  // (worst_age, ~30 ms), plus the io thread's pickup (allowed 10 ms on a loaded machine):
  // below the 50 ms timeout, so the force never goes off, and the fade (from 30 ms, 1 per
  // 20 ms) takes at most (worst_age + 10 ms - 30 ms) / 20 ms of it. The age is measured,
  // not assumed: on a loaded machine the tracker's own thread can deliver later than the
  // jitter says (a 40 ms delay seen in CI), and the claims are judged for the age there was.
  if (j.worst_age_s + 0.010 < 0.050) {
    EXPECT_EQ(j.gain.off, 0u);
  }
  EXPECT_GE(j.gain.min_gain, 1.0 - std::max(0.0, j.worst_age_s + 0.010 - 0.03) / 0.02 - 1e-9);
  EXPECT_GE(j.gain.pressing, j.gain.ticks * 99 / 100);
}

TEST(TrackerFaults, JitterOf20msOnA20msLateTrackerDipsTheGainButNeverStepsItUp) {
  // Each sample 4 ms + 20 ms +- 20 ms late: the newest measurement is up to ~50 ms old
  // just before the next arrives, at the timeout. Figures for the dips (see
  // docs/reliability/fault_injection.md); asserted: what stays safe, and that the force
  // still reaches the hand most of the time.
  const JitterRun j = run_jittery("20", "20");
  expect_sound(j);
  EXPECT_GT(j.max_delay_s - j.min_delay_s, 0.03);
  EXPECT_GT(j.gain.pressing, j.gain.ticks / 4);
  // A late sample brings the gain back at the fade rate, 1 per 20 ms (before the fix it
  // snapped back by up to 1.0, a 4 N step), times the fade-in ramp (1 per 0.5 s) where
  // both rise at once. Judged per second of each tick's own dt_s, as the recording
  // gives it: a tick that a loaded machine runs 5 ms late rightly rises by 0.25, where a
  // bound per tick failed it. 1 % for the recording's decimal rounding.
  const ForceSafetySettings& fade = j.run.settings.tick.safety;
  EXPECT_LE(j.gain.max_rise_per_s, 1.01 * (1.0 / fade.tracker_fade_s + 1.0 / fade.fade_in_s));
  EXPECT_GT(j.gain.max_rise_per_s, 0.0);  // it did come back
}

// ---- 3. tracker lossy ------------------------------------------------------------------

/// The ticks whose reduced gain the tracker does not explain. A tick's gain below 1 is
/// explained when the newest sample delivered by then (`delivered_age_s(t)`) was at least
/// `fade_from_s` old, or when it rises from the tick before: the way back from an
/// explained fade (the stale fade's 1 per tracker_fade_s, and from zero the fade-in ramp)
/// spans ticks whose samples are fresh again. A fall, or a flat dip, while the samples
/// are fresh is unexplained.
std::vector<std::string> unexplained_fades(const std::vector<RecordingRow>& rows,
                                           const std::function<double(double)>& delivered_age_s, double fade_from_s) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const RecordingRow& row = rows[i];
    if (!(row.safety_gain < 1.0)) continue;
    const bool rising = i > 0 && row.safety_gain > rows[i - 1].safety_gain;
    const double age_s = delivered_age_s(row.t_s);
    if (rising || age_s >= fade_from_s) continue;
    out.push_back(fmt::format("gain {} at {} s (tick before: {}): server age {} s, newest sample delivered {} s old",
                              row.safety_gain, row.t_s, i > 0 ? rows[i - 1].safety_gain : 1.0, row.tracker_age_s,
                              age_s));
  }
  return out;
}

std::vector<RecordingRow> gain_rows(const std::vector<double>& gains) {
  std::vector<RecordingRow> rows(gains.size());
  for (std::size_t i = 0; i < gains.size(); ++i) {
    rows[i].t_s = 0.001 * static_cast<double>(i);
    rows[i].safety_gain = gains[i];
  }
  return rows;
}

TEST(FadeJudgement, TheWayBackFromAnExplainedFadeIsExplainedThoughTheSamplesAreFreshAgain) {
  // Stale from 2 ms to 4 ms (off at 4 ms), fresh from 5 ms on while the fade-in ramp rises.
  const auto age = [](double t_s) { return t_s >= 0.0015 && t_s < 0.0045 ? 0.05 : 0.005; };
  EXPECT_TRUE(unexplained_fades(gain_rows({1.0, 1.0, 0.5, 0.2, 0.0, 0.01, 0.02, 0.03, 0.04, 1.0}), age, 0.03).empty());
}

TEST(FadeJudgement, AFallOrAFlatDipWhileTheSamplesAreFreshIsUnexplained) {
  const auto fresh = [](double) { return 0.005; };
  EXPECT_EQ(unexplained_fades(gain_rows({1.0, 0.9, 1.0}), fresh, 0.03).size(), 1u);        // a fall
  EXPECT_EQ(unexplained_fades(gain_rows({1.0, 0.9, 0.9, 0.9}), fresh, 0.03).size(), 3u);   // and a flat dip
  EXPECT_EQ(unexplained_fades(gain_rows({0.5, 0.6, 0.5, 0.6}), fresh, 0.03).size(), 2u);   // the first tick, and the fall
}


TEST(TrackerFaults, LossyTrackerKeepsRenderingAndFadesOnlyInLongGaps) {
  const fs::path dir = temp_dir();
  const PressGeometry g = press_geometry(0.004);
  const fs::path device_log = dir / "device.log", base_log = dir / "base.log", tracker_log = dir / "tracker.log";
  const fs::path file = write_scene(
      dir, g,
      fi_device_xml(g, device_log, kPressAt_s) +
          fi_tracker_xml(tracker_log, param("rate_hz", "190") + param("loss", "0.3") + param("seed", "11")) +
          fi_base_xml(base_log),
      "");
  const RunResult run = run_server(load(file), 1.2, dir / "run.csv", kMovingBase);
  ASSERT_TRUE(run.opened);
  const ServerReport& r = run.report;
  EXPECT_FALSE(r.error) << *r.error;
  EXPECT_TRUE(r.zero_force_sent);
  EXPECT_TRUE(r.base_stop_sent);

  // The loss, from the tracker's side (the model numbers every measurement).
  std::vector<LogRow> delivered = read_log(tracker_log);  // the base sensor's (each sensor numbers its own)
  std::erase_if(delivered, [](const LogRow& d) { return d.c != 0.0; });
  ASSERT_GT(delivered.size(), 100u);
  const double spanned = delivered.back().b - delivered.front().b + 1.0;
  const double loss = 1.0 - static_cast<double>(delivered.size()) / spanned;
  EXPECT_GT(loss, 0.2);
  EXPECT_LT(loss, 0.4);
  const std::vector<Delivery> samples = base_deliveries(tracker_log);
  double longest_gap = 0.0;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    longest_gap = std::max(longest_gap, samples[i].timestamp_s - samples[i - 1].timestamp_s);
  }

  // At time t, the age of the newest sample the tracker had delivered by t - pickup_s
  // (from the tracker's log alone): the server cannot know a sample before it arrives,
  // and its io thread may pick one up late on a loaded machine.
  const auto delivered_age = [&](double t_s, double pickup_s) {
    double newest = -1.0;
    for (const Delivery& d : samples) {
      if (d.arrival_s <= t_s - pickup_s) newest = std::max(newest, d.timestamp_s);
    }
    return newest < 0.0 ? 1.0 : t_s - newest;
  };

  const std::vector<RecordingRow> rows = rows_after_start(read_rows(dir / "run.csv"), 0.2);
  ASSERT_GT(rows.size(), 500u);
  std::size_t reduced = 0, off = 0, pressing = 0;
  for (const RecordingRow& row : rows) {
    EXPECT_TRUE(row_finite(row));
    if (force_N(row) > kContactForce_N) ++pressing;
    if (row.safety_gain == 0.0) ++off;
    if (row.safety_gain < 1.0) ++reduced;
  }
  // A fade needs the newest measurement 30 ms old; with 4 ms latency that takes a gap of
  // more than 26 ms (5 samples in a row lost at 190 Hz).
  const std::vector<std::string> unexplained =
      unexplained_fades(rows, [&](double t_s) { return delivered_age(t_s, 0.010); }, 0.030);
  for (const std::string& u : unexplained) ADD_FAILURE() << u;
  EXPECT_TRUE(unexplained.empty()) << "the force faded while the tracker's newest sample was fresh";
  const ForceSafetySettings& fade = run.settings.tick.safety;
  EXPECT_LE(gain_figures(rows, fade.max_force_N).max_rise_per_s,
            1.01 * (1.0 / fade.tracker_fade_s + 1.0 / fade.fade_in_s));
  if (longest_gap < 0.04) {
    EXPECT_EQ(off, 0u);
  }
  EXPECT_GT(pressing, rows.size() * 9 / 10);
  const double step = max_hip_step_per_ms(rows);
  EXPECT_LT(step, 0.001);
  figure(fmt::format("lossy tracker: {:.0f} % lost, longest gap {:.1f} ms; {} of {} ticks at reduced gain, "
                     "{} at zero; max HIP step {:.3f} mm/ms; {} HIP jumps in all (start-up)",
                     100.0 * loss, 1e3 * longest_gap, reduced, rows.size(), off, 1e3 * step, r.hip_jumps));
}

// ---- 4, 5. base and device failing while the device pushes -------------------------------

struct InContactRun {
  RunResult run;
  fs::path scene;
  std::vector<LogRow> device, base;  // with the fault marker
  std::vector<RecordingRow> rows;
};

/// When the in-contact faults strike, seconds after start: late enough that the first
/// tracker sample, the 0.1 s fade-in and the press are done even on a loaded machine (at
/// 0.35 s a loaded CI machine was once not yet pushing: the check below failed, not the engine).
constexpr const char* kFaultAfter_s = "0.8";

/// The probe device pressing from 0.05 s, the base driving; the fault strikes at kFaultAfter_s.
InContactRun run_fault_in_contact(const std::string& device_params, const std::string& base_params) {
  InContactRun out;
  const fs::path dir = temp_dir();
  const PressGeometry g = press_geometry(0.004);
  const fs::path device_log = dir / "device.log", base_log = dir / "base.log";
  out.scene = write_scene(dir, g,
                          fi_device_xml(g, device_log, kPressAt_s, device_params) +
                              fi_tracker_xml(dir / "tracker.log", "") + fi_base_xml(base_log, base_params),
                          "");
  out.run = run_server(load(out.scene), 10.0, dir / "run.csv", kMovingBase);
  out.device = read_log(device_log);
  out.base = read_log(base_log);
  out.rows = read_rows(dir / "run.csv");
  return out;
}

/// What every in-contact fault must end in; `fault_s` is when it struck.
void expect_safe_end(const InContactRun& f, double fault_s, const std::string& what) {
  const ServerReport& r = f.run.report;
  EXPECT_EQ(r.ended_by, RunEnd::Fault);
  // Pushing when the fault struck: every tick of the 50 ms before it. (Over 20 ms, a
  // loaded 2-core CI machine once ran only 2 of the haptic thread's ticks.)
  std::size_t before = 0, pushing = 0;
  for (const RecordingRow& row : f.rows) {
    if (row.t_s >= fault_s - 0.05 && row.t_s < fault_s) {
      ++before;
      if (force_N(row) > kContactForce_N) ++pushing;
    }
  }
  EXPECT_GT(before, 5u);
  EXPECT_EQ(pushing, before) << "not in contact when the fault struck";
  // The device's last command: zero torque, soon after the fault.
  const std::vector<LogRow> device = without_markers(f.device);
  ASSERT_FALSE(device.empty());
  EXPECT_TRUE(device.back().is_zero());
  EXPECT_LE(device.back().t_s - fault_s, 0.1);
  // The base: it was driving; its last command is a stop, soon after the fault.
  const std::vector<LogRow> base = without_markers(f.base);
  ASSERT_FALSE(base.empty());
  EXPECT_TRUE(std::any_of(base.begin(), base.end(), [](const LogRow& c) { return c.a == 0.05; }));
  EXPECT_TRUE(base.back().is_zero());
  EXPECT_LE(base.back().t_s - fault_s, 0.1);
  figure(fmt::format("{}: zero torque {:.1f} ms, base stop {:.1f} ms after the fault", what,
                     1e3 * (device.back().t_s - fault_s), 1e3 * (base.back().t_s - fault_s)));
}

std::string where(const InContactRun& f, const std::string& plugin) {
  return fmt::format("{}:{}: error: plugin '{}'", f.scene.string(), line_of(f.scene, "name=\"" + plugin + "\""), plugin);
}

TEST(BaseFaults, BaseReadErrorWhilePushingEndsTheRunInTheSafeState) {
  const InContactRun f = run_fault_in_contact("", param("fault", "error") + param("fault_after_s", kFaultAfter_s));
  ASSERT_TRUE(f.run.opened);
  ASSERT_TRUE(f.run.report.error);
  EXPECT_THAT(*f.run.report.error, HasSubstr(where(f, "fi_base")));
  EXPECT_THAT(*f.run.report.error, HasSubstr("injected fault: base controller not responding"));
  const auto fault_s = marker_time(f.base);
  ASSERT_TRUE(fault_s);
  expect_safe_end(f, *fault_s, "base_read error");
  EXPECT_TRUE(f.run.report.zero_force_sent);
  EXPECT_TRUE(f.run.report.base_stop_sent);  // the base still takes commands
}

TEST(BaseFaults, BaseWriteErrorWhilePushingEndsTheRunAndSaysTheStopIsUnconfirmed) {
  const InContactRun f =
      run_fault_in_contact("", param("fault", "error") + param("fault_after_s", kFaultAfter_s) + param("fault_on", "write"));
  ASSERT_TRUE(f.run.opened);
  ASSERT_TRUE(f.run.report.error);
  EXPECT_THAT(*f.run.report.error, HasSubstr(where(f, "fi_base")));
  EXPECT_THAT(*f.run.report.error, HasSubstr("injected fault: base controller not responding"));
  const auto fault_s = marker_time(f.base);
  ASSERT_TRUE(fault_s);
  expect_safe_end(f, *fault_s, "base_write error");  // the stop was sent (and logged) ...
  EXPECT_TRUE(f.run.report.zero_force_sent);
  EXPECT_FALSE(f.run.report.base_stop_sent);  // ... but the failing base did not confirm it
}

TEST(DeviceFaults, DeviceNanWhilePushingEndsTheRunInTheSafeState) {
  const InContactRun f = run_fault_in_contact(param("fault", "nan") + param("fault_after_s", kFaultAfter_s), "");
  ASSERT_TRUE(f.run.opened);
  ASSERT_TRUE(f.run.report.error);
  EXPECT_EQ(*f.run.report.error, where(f, "fi_device") + ": device_read returned a non-finite p_D_tool_m[1]");
  const auto fault_s = marker_time(f.device);
  ASSERT_TRUE(fault_s);
  expect_safe_end(f, *fault_s, "device_read NaN");
  // Nothing but the zero command after the NaN read: the NaN never reached a torque.
  for (const LogRow& c : without_markers(f.device)) {
    if (c.t_s >= *fault_s) {
      EXPECT_TRUE(c.is_zero()) << "torque at " << c.t_s;
    }
  }
  EXPECT_TRUE(f.run.report.zero_force_sent);
  EXPECT_TRUE(f.run.report.base_stop_sent);
}

TEST(DeviceFaults, DeviceReadErrorWhilePushingEndsTheRunInTheSafeState) {
  const InContactRun f = run_fault_in_contact(param("fault", "error") + param("fault_after_s", kFaultAfter_s), "");
  ASSERT_TRUE(f.run.opened);
  ASSERT_TRUE(f.run.report.error);
  EXPECT_THAT(*f.run.report.error, HasSubstr(where(f, "fi_device")));
  EXPECT_THAT(*f.run.report.error, HasSubstr("injected fault: encoder read failed"));
  const auto fault_s = marker_time(f.device);
  ASSERT_TRUE(fault_s);
  expect_safe_end(f, *fault_s, "device_read error");
  EXPECT_TRUE(f.run.report.zero_force_sent);
  EXPECT_TRUE(f.run.report.base_stop_sent);
}

TEST(DeviceFaults, DeviceWriteErrorWhilePushingStillSendsZeroTorque) {
  const InContactRun f = run_fault_in_contact(
      param("fault", "error") + param("fault_after_s", kFaultAfter_s) + param("fault_on", "write"), "");
  ASSERT_TRUE(f.run.opened);
  ASSERT_TRUE(f.run.report.error);
  EXPECT_THAT(*f.run.report.error, HasSubstr(where(f, "fi_device")));
  EXPECT_THAT(*f.run.report.error, HasSubstr("injected fault: amplifier not responding"));
  const auto fault_s = marker_time(f.device);
  ASSERT_TRUE(fault_s);
  expect_safe_end(f, *fault_s, "device_write error");
  EXPECT_FALSE(f.run.report.zero_force_sent);  // the zero was sent, the failing device did not confirm it
  EXPECT_TRUE(f.run.report.base_stop_sent);
}

// ---- the device's force limit, seen from the device -------------------------------------

/// The probe device pressing `depth_m` into the block (1 N per mm at full gain) while it
/// reports `max_force_N` as its limit; the scene gives <haptics max_force_N> only when
/// `scene_max_force_N` is set.
struct LimitRun {
  RunResult run;
  std::vector<LogRow> device;      ///< what the device received, from its side
  std::vector<RecordingRow> rows;  ///< what the server computed and sent
};

LimitRun press_with_device_limit(const std::string& max_force_N,
                                 const std::optional<std::string>& scene_max_force_N = std::nullopt,
                                 double depth_m = 0.004) {
  const fs::path dir = temp_dir();
  const PressGeometry g = press_geometry(depth_m);
  const fs::path device_log = dir / "device.log";
  const fs::path file = write_scene(
      dir, g,
      fi_device_xml(g, device_log, kPressAt_s, param("max_force_N", max_force_N)) +
          fi_tracker_xml(dir / "tracker.log", "") + fi_base_xml(dir / "base.log"),
      "", scene_max_force_N ? "  <haptics max_force_N=\"" + *scene_max_force_N + "\"/>" : std::string());
  LimitRun out;
  out.run = run_server(load(file), 0.8, dir / "run.csv", kMovingBase);
  out.device = without_markers(read_log(device_log));
  out.rows = read_rows(dir / "run.csv");
  return out;
}

double norm(const LogRow& c) { return std::sqrt(c.a * c.a + c.b * c.b + c.c * c.c); }
double norm(const std::array<double, 3>& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
double distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return norm(std::array<double, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]});
}

/// The recording's row of the tick that sent `c` (the log keeps the time to 1 ns), or null.
const RecordingRow* row_of(const std::vector<RecordingRow>& rows, const LogRow& c) {
  const auto it = std::lower_bound(rows.begin(), rows.end(), c.t_s - 1e-9,
                                   [](const RecordingRow& r, double t_s) { return r.t_s < t_s; });
  return it != rows.end() && std::abs(it->t_s - c.t_s) <= 1e-9 ? &*it : nullptr;
}

TEST(DeviceForceLimit, AForceAboveTheDevicesLimitReachesTheDeviceClampedToExactlyTheLimit) {
  const LimitRun l = press_with_device_limit("2");
  ASSERT_TRUE(l.run.opened);
  EXPECT_EQ(l.run.settings.tick.safety.max_force_N, 2.0);
  EXPECT_TRUE(l.run.warnings.empty()) << "the scene asked for nothing";
  std::size_t at_limit = 0, asked_more = 0;
  for (const LogRow& c : l.device) {
    EXPECT_LE(norm(c), 2.0 * (1.0 + 1e-12)) << "at t = " << c.t_s;
    const RecordingRow* r = row_of(l.rows, c);
    // The spring (1000 N/m) stretched more than 2.5 mm: without the limit, more than 2.5 N.
    if (r == nullptr || r->safety_gain != 1.0 || 1000.0 * distance(r->proxy_W_m, r->p_W_hip) <= 2.5) continue;
    ++asked_more;  // the spring asked for more than the limit, at full gain
    if (std::abs(norm(c) - 2.0) <= 2.0 * 1e-12) ++at_limit;
  }
  EXPECT_GT(asked_more, 100u) << "the press never asked for more than the limit";
  EXPECT_EQ(at_limit, asked_more);
}

TEST(DeviceForceLimit, ASceneAskingForMoreThanTheDeviceAllowsIsWarnedAndGetsTheDevicesLimit) {
  const LimitRun l = press_with_device_limit("2", "8.5");
  ASSERT_TRUE(l.run.opened);
  EXPECT_EQ(l.run.settings.tick.safety.max_force_N, 2.0);
  ASSERT_EQ(l.run.warnings.size(), 1u);
  EXPECT_THAT(l.run.warnings[0].message,
              HasSubstr("<haptics max_force_N> is 8.5 N, more than device 'fi_device' allows (2 N, its device_info)"));
  double most_N = 0.0;
  for (const LogRow& c : l.device) most_N = std::max(most_N, norm(c));
  EXPECT_NEAR(most_N, 2.0, 2.0 * 1e-12) << "4 N asked, 2 N allowed";
}

// One source for the limit: a scene that gives none gets the device's whole limit, not
// the thesis arm's 8.5 N on top of it.
TEST(DeviceForceLimit, ASceneThatGivesNoLimitGetsTheDevicesWholeLimit) {
  const LimitRun l = press_with_device_limit("12", std::nullopt, 0.011);  // 11 N asked
  ASSERT_TRUE(l.run.opened);
  EXPECT_EQ(l.run.settings.tick.safety.max_force_N, 12.0);
  EXPECT_TRUE(l.run.warnings.empty());
  double most_N = 0.0;
  for (const LogRow& c : l.device) most_N = std::max(most_N, norm(c));
  EXPECT_GT(most_N, 10.0) << "the device got no more than " << most_N << " N";
  EXPECT_LE(most_N, 12.0);
}

TEST(DeviceForceLimit, ASceneLimitBelowTheDevicesLowersIt) {
  const LimitRun l = press_with_device_limit("12", "3", 0.011);
  ASSERT_TRUE(l.run.opened);
  EXPECT_EQ(l.run.settings.tick.safety.max_force_N, 3.0);
  EXPECT_TRUE(l.run.warnings.empty());
  double most_N = 0.0;
  for (const LogRow& c : l.device) most_N = std::max(most_N, norm(c));
  EXPECT_NEAR(most_N, 3.0, 3.0 * 1e-9);
}

TEST(DeviceForceLimit, AForceBelowTheLimitReachesTheDeviceUnchanged) {
  const LimitRun l = press_with_device_limit("8.5");
  ASSERT_TRUE(l.run.opened);
  EXPECT_EQ(l.run.settings.tick.safety.max_force_N, 8.5);
  EXPECT_TRUE(l.run.warnings.empty());
  std::size_t pressing = 0, unchanged = 0;
  for (const LogRow& c : l.device) {
    const RecordingRow* r = row_of(l.rows, c);
    if (r == nullptr || r->safety_gain != 1.0 || norm(r->cmd_force_W_N) <= kContactForce_N) continue;
    ++pressing;
    // What the device got is what the server sent, and that is the proxy's force, unscaled.
    if (c.a == r->force_D_N[0] && c.b == r->force_D_N[1] && c.c == r->force_D_N[2] &&
        std::abs(norm(c) - norm(r->cmd_force_W_N)) <= 1e-12 * norm(c)) {
      ++unchanged;
    }
  }
  EXPECT_GT(pressing, 100u) << "the press never pushed";
  EXPECT_EQ(unchanged, pressing);
}

// ---- the base planner keeps the hand in the device's own workspace ---------------------

/// A short run of a scene with <planner kind="seed"/> and the fi_device reporting
/// `device_params` (its workspace), as ServerSettings shows it after open.
RunResult run_with_scene_planner(const std::string& device_params) {
  const fs::path dir = temp_dir();
  const PressGeometry g = press_geometry(0.004);
  const fs::path file =
      write_scene(dir, g,
                  fi_device_xml(g, dir / "device.log", kPressAt_s, device_params) +
                      fi_tracker_xml(dir / "tracker.log", "") + fi_base_xml(dir / "base.log"),
                  "", "  <planner kind=\"seed\"/>");
  return run_server(load(file), 0.2, dir / "run.csv", BasePlanFn{});
}

Rig pomhi_rig() {
  const Result<SceneDescription> read = read_scene_file(fs::path(MHD_SOURCE_DIR) / "scenes/rigs/pomhi.xml");
  EXPECT_TRUE(read.ok()) << read.error_text();
  Result<Rig, std::vector<RigError>> rig = Rig::from_scene(*read);
  EXPECT_TRUE(rig.ok()) << rig.error_text();
  return std::move(rig).value();
}

bool same_box(const PlanarBox& a, const PlanarBox& b) {
  return std::abs(a.x_min_m - b.x_min_m) < 1e-12 && std::abs(a.x_max_m - b.x_max_m) < 1e-12 &&
         std::abs(a.z_min_m - b.z_min_m) < 1e-12 && std::abs(a.z_max_m - b.z_max_m) < 1e-12;
}

TEST(DevicePlannerWorkspace, TheScenesPlannerKeepsTheHandInTheWorkspaceTheDeviceReports) {
  // A 250 x 150 x 150 mm box, off a PHANToM's: another arm on the same rig frames.
  const RunResult run =
      run_with_scene_planner(param("workspace_min_m", "-0.05 0.0 -0.10") + param("workspace_max_m", "0.20 0.15 0.05"));
  ASSERT_TRUE(run.opened);
  ASSERT_TRUE(run.settings.planner_usable_B);
  const Rig rig = pomhi_rig();
  const double margin_m = rig.device().usable_margin_m;
  const WorkspaceBox usable_P{Eigen::Vector3d(-0.05 + margin_m, margin_m, -0.10 + margin_m),
                              Eigen::Vector3d(0.20 - margin_m, 0.15 - margin_m, 0.05 - margin_m)};
  EXPECT_TRUE(same_box(*run.settings.planner_usable_B, usable_box_in_base(rig, usable_P)));
  EXPECT_FALSE(same_box(*run.settings.planner_usable_B, usable_box_in_base(rig))) << "the PHANToM model's box";
}

TEST(DevicePlannerWorkspace, APhantomsOwnReportGivesThePlannerTheRigModelsBox) {
  const RunResult run = run_with_scene_planner("");
  ASSERT_TRUE(run.opened);
  ASSERT_TRUE(run.settings.planner_usable_B);
  EXPECT_TRUE(same_box(*run.settings.planner_usable_B, usable_box_in_base(pomhi_rig())));
}

// ---- 6. kill -9 of `mhd run` -----------------------------------------------------------

#ifdef MHD_CLI
TEST(ProcessFaults, KilledServerLeavesARecordingReadableUpToAtMost100msBeforeTheKill) {
  const fs::path dir = temp_dir();
  const fs::path scene = fs::path(MHD_SOURCE_DIR) / "tests/data/fault_injection/kill_run.xml";
  // Three kills at different phases of the 50 ms flush period.
  for (const int extra_ms : {0, 17, 36}) {
    const fs::path work = dir / std::to_string(extra_ms);
    fs::create_directories(work);
    const fs::path recording = work / "run.csv";
    ChildProcess child({MHD_CLI, "run", scene.string(), "--duration", "30", "-q", "--record", recording.string(),
                        "--plugin-path", MHD_FAULT_INJECTION_PLUGIN_DIR, "--plugin-path", MHD_SIM_PLUGIN_DIR},
                       work, work / "output.txt");
    // Wait for the plugins to be open (the clock probe) and the recording to grow.
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!(fs::exists(work / "clock.txt") && fs::exists(recording) && fs::file_size(recording) > 20000)) {
      ASSERT_LT(std::chrono::steady_clock::now(), give_up) << "mhd run did not start: " << (work / "output.txt");
      ASSERT_FALSE(child.wait_for(std::chrono::milliseconds(10))) << "mhd run ended early: " << (work / "output.txt");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(600 + extra_ms));
    const auto killed_at = child.kill9();
    const auto status = child.wait_for(std::chrono::seconds(10));
    ASSERT_TRUE(status);
    ASSERT_TRUE(WIFSIGNALED(*status) && WTERMSIG(*status) == SIGKILL);

    // The kill time on the server's host clock.
    double host_s = 0.0, monotonic_s = 0.0;
    std::ifstream(work / "clock.txt") >> host_s >> monotonic_s;
    ASSERT_GT(monotonic_s, 0.0);
    const double kill_s = std::chrono::duration<double>(killed_at.time_since_epoch()).count() - monotonic_s + host_s;

    // The raw file: complete lines, then maybe a torn one.
    std::ifstream raw(recording, std::ios::binary);
    std::stringstream text;
    text << raw.rdbuf();
    const std::string content = text.str();
    const std::size_t complete_lines = static_cast<std::size_t>(std::count(content.begin(), content.end(), '\n'));
    const std::size_t torn_bytes = content.size() - (content.rfind('\n') + 1);

    const Result<std::vector<RecordingRow>> read = read_recording(recording);
    ASSERT_TRUE(read.ok()) << read.diagnostics().front().to_string();
    ASSERT_GT(read.value().size(), 500u);
    EXPECT_EQ(read.value().size(), complete_lines - 1);  // every complete line but the header; the torn one skipped
    for (std::size_t i = 1; i < read.value().size(); ++i) ASSERT_GT(read.value()[i].t_s, read.value()[i - 1].t_s);
    const double age_s = kill_s - read.value().back().t_s;
    EXPECT_LE(age_s, 0.1);
    EXPECT_GT(age_s, -0.005);  // the clocks agree: no row from after the kill
    figure(fmt::format("kill -9: {} rows readable, last row {:.1f} ms before the kill, torn last line {} bytes",
                       read.value().size(), 1e3 * age_s, torn_bytes));
  }
}
#endif

}  // namespace
