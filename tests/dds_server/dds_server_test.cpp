// The haptic server over DDS with real processes on loopback (end-to-end
// tests): a tracker server process (tests/dds's dds_test_tracker_server playing a replay)
// feeds an in-process HapticServer whose tracker is the `dds` plugin, whose device is
// fault_device (joint angles held still) and whose display is `dds_state`; this process
// subscribes to the rig state as a viewer would. The tracker server is killed with
// SIGKILL and started again; a lossy publisher feeds the server a bad stream.
#include "dds_server_support.h"
#include "dds_test_support.h"

#include "dds_common/dds_topics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace mhd;
using namespace mhd::dds_server_test;
using mhd::dds::test::ChildProcess;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Rig ids of their own (tests/dds uses 1 to 6): should two concurrently running test
// processes draw the same domain, their samples still do not mix.
constexpr std::uint32_t kPipelineRig = 41, kKillRig = 42, kLossyRig = 43;

fs::path temp_dir() {
  const fs::path dir = fs::path(::testing::TempDir()) / "dds_server_test" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// Takes `rig`'s states until `done` says so or `timeout` passes; returns them all.
std::vector<mhd_dds_RigState> take_states_until(dds::Subscriber<mhd_dds_RigState>& sub, std::uint32_t rig,
                                                std::chrono::milliseconds timeout,
                                                const std::function<bool(const mhd_dds_RigState&)>& done) {
  std::vector<mhd_dds_RigState> all;
  const auto end = Clock::now() + timeout;
  while (Clock::now() < end) {
    (void)sub.reader().wait(20'000'000);
    bool finished = false;
    for (const mhd_dds_RigState& s : sub.reader().take()) {
      if (s.rig_id != rig) continue;
      all.push_back(s);
      finished = finished || done(s);
    }
    if (finished) break;
  }
  return all;
}

double norm3(const double (&v)[3]) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

/// The server and the tracker server of one test: the replay brings the base from 30 mm
/// behind the origin into the wall (after 0.6 s holding still, so the server has
/// matched the tracker server before the hand reaches the wall).
struct RigSetup {
  fs::path dir = temp_dir();
  std::uint32_t rig_id;
  std::uint32_t domain = dds::test::use_loopback_and_unique_domain(11);
  Rig rig = thesis_rig();
  fs::path replay = dir / "approach.csv";
  fs::path tracker_scene;
  fs::path base_log = dir / "base.log";
  fs::path recording = dir / "run.csv";
  LoadedScene scene;

  explicit RigSetup(std::uint32_t rig_number) : rig_id(rig_number) {
    write_approach_replay(replay, rig, 30.0, 0.6, 0.03, 0.1);
    tracker_scene = write_tracker_scene(dir, replay);
    SceneOptions o;
    o.domain_id = domain;
    o.rig_id = rig_id;
    o.base_log = base_log;
    scene = load_scene(write_server_scene(dir, o));
  }
  ServerOptions options(BasePlanFn plan = {}) const {
    ServerOptions o;
    o.plugin_path = plugin_dirs();
    o.recording = recording;
    o.plan_base = std::move(plan);
    return o;
  }
  std::vector<std::string> tracker_args() const { return tracker_server_args(tracker_scene, domain, rig_id, 30.0); }
};

TEST(DdsHapticServer, TrackerServerToHapticServerToStateSubscriberCarriesHipForceAndBasePose) {
  RigSetup s(kPipelineRig);
  ASSERT_TRUE(s.scene.compiled) << (s.scene.errors.empty() ? "" : s.scene.errors.front());
  const dds::Participant participant(s.domain);
  dds::Subscriber<mhd_dds_RigState> states(participant, dds::rig_partition(s.rig_id));

  ServerThread server(s.scene, s.options());
  ASSERT_TRUE(server.opened()) << server.errors().front();
  ChildProcess tracker(s.tracker_args(), (s.dir / "tracker.log").string());

  // Until the hand has been in the wall for a while (the base at rest at the origin).
  int contact_states = 0;
  const auto seen = take_states_until(states, s.rig_id, std::chrono::seconds(10), [&](const mhd_dds_RigState& st) {
    if (st.in_contact) ++contact_states;
    return contact_states >= 20;
  });
  const ServerReport report = server.stop();
  EXPECT_FALSE(report.error) << *report.error;
  ASSERT_GE(contact_states, 20) << "states seen: " << seen.size() << "\n" << dds::test::read_file((s.dir / "tracker.log").string());

  const Eigen::Vector3d hip = hip_at(s.rig, BasePose{});
  const mhd_dds_RigState& last = seen.back();
  EXPECT_TRUE(last.in_contact);
  // The HIP where the rig puts it with the base at the origin; the proxy on the wall's
  // face; the spring between them pushing the hand back (-x) with k * depth.
  EXPECT_NEAR(last.p_W_hip_m[0], hip.x(), 1e-3);
  EXPECT_NEAR(last.p_W_hip_m[1], hip.y(), 1e-3);
  EXPECT_NEAR(last.p_W_hip_m[2], hip.z(), 1e-3);
  EXPECT_NEAR(last.p_W_proxy_m[0], hip.x() - kWallPenetration_m, 1e-4);
  const double expected_force_N = kWallStiffness_N_per_m * kWallPenetration_m;
  EXPECT_NEAR(norm3(last.force_W_N), expected_force_N, 0.2 * expected_force_N);
  EXPECT_LT(last.force_W_N[0], -0.9 * norm3(last.force_W_N));
  EXPECT_NEAR(last.base_x_m, 0.0, 1e-3);
  EXPECT_NEAR(last.base_z_m, 0.0, 1e-3);
  EXPECT_NEAR(last.base_heading_rad, 0.0, 1e-3);
  // Numbered in order.
  for (std::size_t i = 1; i < seen.size(); ++i) {
    EXPECT_GT(seen[i].sequence_number, seen[i - 1].sequence_number);
  }
  // The approach was seen too: states with the base still behind the origin, no contact.
  EXPECT_TRUE(std::any_of(seen.begin(), seen.end(), [](const mhd_dds_RigState& st) {
    return !st.in_contact && st.base_x_m < -0.01 && std::isfinite(st.p_W_hip_m[0]);
  }));
  EXPECT_GT(report.status.tracker_samples, 100u);
  EXPECT_EQ(report.status.tracker_rejected, 0u);
  EXPECT_EQ(report.hip_jumps, 0u);
}

TEST(DdsHapticServer, KilledTrackerServerFadesForceIn50MsStopsBaseIn100MsAndTrackingResumes) {
  RigSetup s(kKillRig);
  ASSERT_TRUE(s.scene.compiled) << (s.scene.errors.empty() ? "" : s.scene.errors.front());
  const dds::Participant participant(s.domain);
  dds::Subscriber<mhd_dds_RigState> states(participant, dds::rig_partition(s.rig_id));

  constexpr double kPlannedVx_mps = 0.05;  // the planner keeps asking the base to move
  ServerThread server(s.scene, s.options([](const BasePlanInput&) { return BaseTwist{kPlannedVx_mps, 0.0, 0.0}; }));
  ASSERT_TRUE(server.opened()) << server.errors().front();
  auto tracker = std::make_unique<ChildProcess>(s.tracker_args(), (s.dir / "tracker.log").string());
  int contact_states = 0;
  (void)take_states_until(states, s.rig_id, std::chrono::seconds(10), [&](const mhd_dds_RigState& st) {
    if (st.in_contact) ++contact_states;
    return contact_states >= 25;  // 0.4 s in the wall
  });
  ASSERT_GE(contact_states, 25);

  tracker->kill_now();  // SIGKILL: no goodbye on the wire
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  tracker = std::make_unique<ChildProcess>(s.tracker_args(), (s.dir / "tracker2.log").string());
  // Tracking resumes: states in contact again once the replayed base is back at the origin.
  contact_states = 0;
  (void)take_states_until(states, s.rig_id, std::chrono::seconds(10), [&](const mhd_dds_RigState& st) {
    if (st.in_contact && norm3(st.force_W_N) > 1.0) ++contact_states;
    return contact_states >= 10;
  });
  const ServerReport report = server.stop();
  EXPECT_FALSE(report.error) << *report.error;
  EXPECT_GE(contact_states, 10) << "no force after the tracker server came back";
  EXPECT_GT(report.stale_ticks, 0u);
  EXPECT_GT(report.base_stops, 0u);

  const std::vector<Row> rows = read_recording(s.recording);
  ASSERT_GT(rows.size(), 1000u);
  // The gap: the oldest tracking in the run is the kill's (0.4 s at least; a loaded
  // machine may stall the tracker server for a while too, but not that long).
  const auto oldest = std::max_element(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
    return a.tracker_age_s < b.tracker_age_s;
  });
  ASSERT_GT(oldest->tracker_age_s, 0.3);
  const double t_last_sample = oldest->t_s - oldest->tracker_age_s;
  const auto gap = std::find_if(rows.begin(), rows.end(), [&](const Row& r) { return r.t_s >= t_last_sample; });
  const auto resumed = std::find_if(oldest, rows.end(), [](const Row& r) { return r.tracker_age_s < 0.02; });
  ASSERT_NE(resumed, rows.end()) << "tracking did not resume";
  EXPECT_GT(resumed->t_s - t_last_sample, 0.3);  // the 400 ms without a tracker server
  std::cout << "last sample before the kill -> first fresh sample after the restart (0.4 s later): "
            << resumed->t_s - t_last_sample << " s; tracker samples rejected by the server: "
            << report.status.tracker_rejected << " (haptic thread: " << report.haptic_scheduling << ")\n";

  // Before the kill: full force in the wall with fresh samples.
  std::size_t full_force_rows = 0;
  for (auto it = rows.begin(); it != gap; ++it) {
    if (it->t_s > t_last_sample - 0.2 && it->t_s <= t_last_sample && it->safety_gain == 1.0 &&
        it->force_W_N.norm() > 0.8 * kWallStiffness_N_per_m * kWallPenetration_m) {
      ++full_force_rows;
    }
  }
  EXPECT_GT(full_force_rows, 50u);
  // After the last sample: from 30 ms the gain falls, never rising, and from 50 ms
  // until tracking resumes it is zero, with exactly zero force.
  std::size_t fading_rows = 0, zero_rows = 0;
  double previous_gain = 1.0;
  for (auto it = rows.begin(); it != resumed; ++it) {
    const double since_s = it->t_s - t_last_sample;
    if (since_s < 0.03) continue;  // (a fade-in still running may raise the gain until then)
    EXPECT_LE(it->safety_gain, previous_gain) << "t = " << since_s << " s after the last sample";
    previous_gain = it->safety_gain;
    if (since_s > 0.031 && since_s < 0.049) {
      EXPECT_LT(it->safety_gain, 1.0);
      if (it->safety_gain > 0.0) ++fading_rows;
    }
    if (since_s >= 0.05) {
      EXPECT_EQ(it->safety_gain, 0.0) << "t = " << since_s << " s after the last sample";
      EXPECT_EQ(it->force_W_N.norm(), 0.0) << "t = " << since_s << " s after the last sample";
      ++zero_rows;
    }
  }
  EXPECT_GT(fading_rows, 5u);
  const auto first_zero = std::find_if(gap, resumed, [&](const Row& r) {
    return r.t_s > t_last_sample && r.force_W_N.norm() == 0.0;
  });
  if (first_zero != resumed) {
    std::cout << "force zero " << (first_zero->t_s - t_last_sample) * 1e3 << " ms after the last sample\n";
  }
  EXPECT_GT(zero_rows, 200u);
  // Afterwards: full gain again with fresh samples.
  EXPECT_TRUE(std::any_of(resumed, rows.end(), [](const Row& r) { return r.safety_gain == 1.0 && r.tracker_age_s < 0.02; }));

  // The base, from its own log: moving as planned before the kill, a zero command within
  // 100 ms of the last sample, nothing but zero until tracking resumed, moving again after.
  const std::vector<LoggedCommand> commands = read_command_log(s.base_log);
  ASSERT_FALSE(commands.empty());
  EXPECT_TRUE(std::any_of(commands.begin(), commands.end(), [&](const LoggedCommand& c) {
    return c.t_s < t_last_sample && c.t_s > t_last_sample - 0.5 && c.vx_mps == kPlannedVx_mps;
  }));
  const auto stop = std::find_if(commands.begin(), commands.end(),
                                 [&](const LoggedCommand& c) { return c.t_s > t_last_sample && c.zero(); });
  ASSERT_NE(stop, commands.end());
  EXPECT_LE(stop->t_s - t_last_sample, 0.1);
  std::cout << "base commanded zero " << (stop->t_s - t_last_sample) * 1e3 << " ms after the last sample\n";
  for (auto it = commands.begin(); it != commands.end(); ++it) {
    // (the io thread may command a moment before the haptic tick records the sample)
    if (it->t_s > t_last_sample + 0.1 && it->t_s < resumed->t_s - 0.005) {
      EXPECT_TRUE(it->zero()) << "at " << it->t_s << " s";
    }
  }
  EXPECT_TRUE(std::any_of(commands.begin(), commands.end(),
                          [&](const LoggedCommand& c) { return c.t_s > resumed->t_s && c.vx_mps == kPlannedVx_mps; }));
  EXPECT_TRUE(commands.back().zero());  // and the server ended with the base stopped
}

TEST(DdsHapticServer, LossyTrackerStreamNeverMakesTheHipLeap) {
  const fs::path dir = temp_dir();
  const std::uint32_t domain = dds::test::use_loopback_and_unique_domain(23);
  SceneOptions o;
  o.domain_id = domain;
  o.rig_id = kLossyRig;
  o.log_base = false;
  o.state_display = false;
  const LoadedScene scene = load_scene(write_server_scene(dir, o));
  ASSERT_TRUE(scene.compiled) << (scene.errors.empty() ? "" : scene.errors.front());
  ServerOptions options;
  options.plugin_path = plugin_dirs();
  options.recording = dir / "run.csv";
  ServerThread server(scene, options);
  ASSERT_TRUE(server.opened()) << server.errors().front();
  // tests/dds/lossy_stream.h: sensor 0 moving +x by 1 mm per sample, sent at 500 Hz,
  // with samples lost, swapped, 0.3 s late, NaN, 1000 m away, not unit, 1 s ahead and
  // of another rig.
  ChildProcess publisher({MHD_DDS_TEST_LOSSY_PUBLISHER, "--domain-id", std::to_string(domain), "--rig-id",
                          std::to_string(kLossyRig), "--count", "600"},
                         (dir / "publisher.log").string());
  const std::optional<int> rc = publisher.wait_for(std::chrono::seconds(20));
  const ServerReport report = server.stop();
  ASSERT_EQ(rc, 0) << dds::test::read_file((dir / "publisher.log").string());
  EXPECT_FALSE(report.error) << *report.error;
  EXPECT_GT(report.status.tracker_samples, 200u);
  // The plugin's own drops reach the server's status through the ABI's counters call:
  // every kind of bad sample the stream sends (deterministically, several of each).
  std::map<std::string, std::uint64_t> counters;
  for (const PluginCounter& c : report.status.tracker_plugin_counters) counters[c.name] = c.value;
  EXPECT_GT(counters["accepted"], 200u);
  for (const char* reason : {"dropped_non_finite", "dropped_out_of_range", "dropped_bad_quaternion", "dropped_future",
                             "dropped_unknown_rig"}) {
    EXPECT_GT(counters[reason], 0u) << reason;
  }
  EXPECT_NE(dropped_counts_text(report.status.tracker_plugin_counters).find("non_finite "), std::string::npos);

  const std::vector<Row> rows = read_recording(options.recording);
  const auto first = std::find_if(rows.begin(), rows.end(), [](const Row& r) { return r.p_W_hip.allFinite(); });
  ASSERT_NE(first, rows.end());
  // The stream moves the sensor 1 mm per sample number; with 8 sends of every 10
  // numbers 2 ms apart (one lost, one pair sent together) that is at most 0.625 m/s.
  // Bound each tick's HIP step by 1 m/s over the tick plus 0.25 mm: a used bad sample
  // (0.3 s stale, 1000 m away, a reordered one fed as a backwards step) would leap by
  // millimetres to metres. Left out: the predictor's start-up, its first 10 samples,
  // where its output follows a least-squares fit and may jump by design
  // (base_pose_predictor.h, startup_samples). A tick whose tracker_age_s fell took in
  // at least one new sample, so the check starts after the 10th such tick.
  // The server's own count of HIP jumps must match the recording's, judged as ForceSafety
  // judges them: a step over hip_jump_m (10 mm) per millisecond of the tick, never less
  // than 10 mm (force_safety.h). On a loaded machine the first samples come in bursts and
  // the start-up fit may leap, and a tick 12 ms late sees the base 7 mm further (none of
  // either seen unloaded); a 12 mm step in a 2 ms tick is no jump to either.
  int arrivals = 0;
  double hip_travel_m = 0.0;
  std::size_t steps = 0, recorded_jumps = 0;
  for (auto it = first + 1; it != rows.end(); ++it) {
    const auto prev = it - 1;
    const double jump_threshold_m = 0.01 * std::max(1.0, (it->t_s - prev->t_s) / 0.001);
    if ((it->p_W_hip - prev->p_W_hip).norm() > jump_threshold_m) ++recorded_jumps;
    if (arrivals < 10) {
      if (it->tracker_age_s < prev->tracker_age_s) ++arrivals;
      continue;
    }
    ASSERT_TRUE(it->p_W_hip.allFinite()) << "the HIP was lost at t = " << it->t_s;
    const double step_m = (it->p_W_hip - prev->p_W_hip).norm();
    const double bound_m = 1.0 * (it->t_s - prev->t_s) + 0.25e-3;
    EXPECT_LE(step_m, bound_m) << "at t = " << it->t_s << " s (dt " << it->t_s - prev->t_s << " s)";
    hip_travel_m += step_m;
    ++steps;
  }
  EXPECT_EQ(report.hip_jumps, recorded_jumps);
  EXPECT_EQ(report.recording_dropped, 0u);
  EXPECT_GT(steps, 500u);
  EXPECT_GT(hip_travel_m, 0.2);  // the HIP did follow the stream (0.6 m in all)
}

}  // namespace
