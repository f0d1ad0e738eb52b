// Real processes on loopback (config/cyclonedds-loopback.xml), each test in a domain of
// its own: `mhd tracker-server` (as dds_test_tracker_server) publishing the simulated
// IS-900, the `dds` tracker plugin loaded through dlopen receiving it, two rigs in one
// domain, and a lossy publisher whose bad samples are dropped and counted.

#include "../sim_backends/plugin_file.h"
#include "dds_common/tracker_subscriber.h"
#include "dds_test_support.h"
#include "tracker_plugin_on_clock.h"
#include "lossy_stream.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace mhd::dds {
namespace {

using namespace std::chrono_literals;
using test::ChildProcess;

std::vector<std::string> server_args(const char* scene, std::uint32_t domain, std::uint32_t rig, double duration_s) {
  return {MHD_DDS_TEST_TRACKER_SERVER,
          "tracker-server",
          std::string(MHD_SOURCE_DIR) + "/tests/dds/data/" + scene,
          "--domain-id",
          std::to_string(domain),
          "--rig-id",
          std::to_string(rig),
          "--duration",
          std::to_string(duration_s),
          "--plugin-path",
          MHD_DDS_TEST_PLUGIN_DIR};
}

/// A child's output file, removed when the test ends.
struct OutputFile : test::OutputFile {
  explicit OutputFile(const char* name) : test::OutputFile(std::filesystem::temp_directory_path().string(), name) {}
};

/// The `dds` tracker plugin of rig `rig` on `domain`, through the real dlopen path.
struct DdsTrackerPlugin : test::TrackerPluginOnClock {
  DdsTrackerPlugin(std::uint32_t domain, std::uint32_t rig)
      : TrackerPluginOnClock(MHD_DDS_TRACKER_PLUGIN,
                             {{"domain_id", std::to_string(domain).c_str()}, {"rig_id", std::to_string(rig).c_str()}}) {}
};

void expect_increasing_per_sensor(const std::vector<mhd_tracker_sample>& samples) {
  std::map<std::uint32_t, std::uint64_t> last;
  for (const mhd_tracker_sample& s : samples) {
    const auto it = last.find(s.sensor_id);
    if (it != last.end()) {
      EXPECT_GT(s.sequence, it->second) << "sensor " << s.sensor_id;
    }
    last[s.sensor_id] = s.sequence;
  }
}

TEST(DdsProcesses, TheDdsTrackerPluginReceivesTheTrackerServersPoses) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(10);
  DdsTrackerPlugin plugin(domain, 1);
  const OutputFile log("server");
  ChildProcess server(server_args("sim_tracker_rig1.xml", domain, 1, 20.0), log.path());
  // 400 samples: about 1 s of both sensors at 190 Hz, so the restarted server's
  // sequences below are well behind these.
  const std::vector<mhd_tracker_sample> got = plugin.read_for(10s, 400);
  ASSERT_GE(got.size(), 400u) << log.text();
  std::size_t head = 0;
  for (const mhd_tracker_sample& s : got) {
    ASSERT_TRUE(s.sensor_id == 0 || s.sensor_id == 1);
    const double qn = std::hypot(std::hypot(s.q_T_wxyz[0], s.q_T_wxyz[1]), std::hypot(s.q_T_wxyz[2], s.q_T_wxyz[3]));
    EXPECT_NEAR(qn, 1.0, 1e-9);
    if (s.sensor_id == 1) {
      ++head;
      // The thesis tracker frame: z_T points down from 2.624 m; the eyes are at 1.65 m.
      EXPECT_NEAR(s.p_T_m[2], 2.624 - 1.65, 0.05);
    } else {
      // The base sensor, 1.1808 m above the floor.
      EXPECT_NEAR(s.p_T_m[2], 2.624 - 1.1808, 0.05);
    }
  }
  EXPECT_GT(head, 100u);
  expect_increasing_per_sensor(got);

  // The server goes away and comes back (its sequences start over): samples resume.
  server.kill_now();
  std::this_thread::sleep_for(400ms);  // longer than restart_after_s
  EXPECT_TRUE(plugin.read_for(300ms, 1).empty());
  ChildProcess again(server_args("sim_tracker_rig1.xml", domain, 1, 20.0), log.path());
  const std::vector<mhd_tracker_sample> resumed = plugin.read_for(8s, 20);
  ASSERT_GE(resumed.size(), 20u) << log.text();
  EXPECT_LT(resumed.front().sequence, got.back().sequence);
  expect_increasing_per_sensor(resumed);
}

TEST(DdsProcesses, TheTrackerServerPassesAReplayedRecordingThroughUnchanged) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(15);
  DdsTrackerPlugin plugin(domain, 6);
  const OutputFile log("replay");
  ChildProcess server(server_args("replay_tracker.xml", domain, 6, 20.0), log.path());
  const std::vector<mhd_tracker_sample> got = plugin.read_for(8s, 50);
  ASSERT_GE(got.size(), 50u) << log.text();
  for (const mhd_tracker_sample& s : got) {
    // The recording's row `sequence`, as written in tests/dds/data/replay_3s.csv.
    const double a = 0.2 * 0.01 * static_cast<double>(s.sequence);
    EXPECT_EQ(s.sensor_id, 0u);
    EXPECT_NEAR(s.p_T_m[0], std::cos(a), 1e-6);
    EXPECT_NEAR(s.p_T_m[1], std::sin(a), 1e-6);
    EXPECT_EQ(s.p_T_m[2], 1.5);
    EXPECT_NEAR(s.q_T_wxyz[0], std::cos(a / 2), 1e-8);
    EXPECT_NEAR(s.q_T_wxyz[3], std::sin(a / 2), 1e-8);
  }
  expect_increasing_per_sensor(got);
  // Released on the recording's 100 Hz clock: 50 samples span about 0.49 s.
  EXPECT_NEAR(got[49].timestamp_s - got[0].timestamp_s, 0.01 * static_cast<double>(got[49].sequence - got[0].sequence),
              0.02);
}

TEST(DdsProcesses, TwoRigsInOneDomainStayApart) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(20);
  const Participant participant(domain);
  TrackerValidationLimits limits1;
  limits1.rig_id = 1;
  TrackerValidationLimits limits2 = limits1;
  limits2.rig_id = 2;
  TrackerSubscriber rig1(participant, limits1);
  TrackerSubscriber rig2(participant, limits2);
  const OutputFile log1("rig1");
  const OutputFile log2("rig2");
  ChildProcess server1(server_args("sim_tracker_rig1.xml", domain, 1, 20.0), log1.path());
  ChildProcess server2(server_args("sim_tracker_rig2.xml", domain, 2, 20.0), log2.path());
  std::vector<mhd_tracker_sample> got1;
  std::vector<mhd_tracker_sample> got2;
  mhd_tracker_sample buffer[32];
  const auto end = std::chrono::steady_clock::now() + 8s;
  while ((got1.size() < 150 || got2.size() < 150) && std::chrono::steady_clock::now() < end) {
    const std::int64_t now_ns = realtime_ns();
    const std::size_t n1 = rig1.poll(buffer, 0.0, now_ns);
    got1.insert(got1.end(), buffer, buffer + n1);
    const std::size_t n2 = rig2.poll(buffer, 0.0, now_ns);
    got2.insert(got2.end(), buffer, buffer + n2);
    std::this_thread::sleep_for(1ms);
  }
  ASSERT_GE(got1.size(), 150u) << log1.text();
  ASSERT_GE(got2.size(), 150u) << log2.text();
  for (const mhd_tracker_sample& s : got1) EXPECT_LT(std::abs(s.p_T_m[1]), 5.0);  // thesis frame
  for (const mhd_tracker_sample& s : got2) EXPECT_GT(s.p_T_m[1], 10.0);           // 10 m below the floor
  expect_increasing_per_sensor(got1);
  expect_increasing_per_sensor(got2);
  // Each rig's endpoints live in the rig's partition: neither reader even receives the
  // other rig's samples, so none is dropped as another rig's.
  EXPECT_EQ(rig1.counts().dropped_total(), 0u);
  EXPECT_EQ(rig2.counts().dropped_total(), 0u);
}

TEST(DdsProcesses, ALossyPublishersBadSamplesAreDroppedAndCountedAndTheRestIsSmooth) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(30);
  const Participant participant(domain);
  TrackerValidationLimits limits;
  limits.rig_id = 3;
  TrackerSubscriber subscriber(participant, limits);
  constexpr std::uint64_t kCount = 400;
  const OutputFile log("lossy");
  ChildProcess publisher({MHD_DDS_TEST_LOSSY_PUBLISHER, "--domain-id", std::to_string(domain), "--rig-id", "3",
                          "--count", std::to_string(kCount)},
                         log.path());
  std::vector<mhd_tracker_sample> got;
  mhd_tracker_sample buffer[32];
  std::optional<int> exit_status;
  const auto end = std::chrono::steady_clock::now() + 15s;
  while (!exit_status && std::chrono::steady_clock::now() < end) {
    const std::size_t n = subscriber.poll(buffer, 0.0, realtime_ns());
    got.insert(got.end(), buffer, buffer + n);
    exit_status = publisher.wait_for(1ms);
  }
  const std::size_t n = subscriber.poll(buffer, 0.0, realtime_ns());
  got.insert(got.end(), buffer, buffer + n);
  ASSERT_EQ(exit_status, std::optional<int>(0)) << log.text();

  std::uint64_t good = 0;
  for (std::uint64_t i = 0; i < kCount; ++i) good += test::lossy_kind(i) == test::LossyKind::Good ? 1 : 0;
  const DropCounts& c = subscriber.counts();
  EXPECT_EQ(c.accepted, got.size());
  EXPECT_LE(c.accepted, good);
  EXPECT_GE(c.accepted, good / 2) << c.summary();  // loopback loses little, even when loaded
  for (const DropReason r : {DropReason::UnknownRig, DropReason::NonFinite, DropReason::OutOfRange,
                             DropReason::BadQuaternion, DropReason::Stale, DropReason::Future,
                             DropReason::SequenceBackwards}) {
    EXPECT_GT(c[r], 0u) << to_string(r) << ": " << c.summary();
  }
  // Only good samples get through, in order, and the pose never leaps.
  for (std::size_t i = 0; i < got.size(); ++i) {
    ASSERT_EQ(test::lossy_kind(got[i].sequence), test::LossyKind::Good) << "sequence " << got[i].sequence;
    EXPECT_DOUBLE_EQ(got[i].p_T_m[0], test::lossy_x_m(got[i].sequence));
    if (i > 0) {
      EXPECT_GT(got[i].sequence, got[i - 1].sequence);
      // Good samples are at most 2 apart; 50 would take a 100 ms outage.
      EXPECT_LE(got[i].p_T_m[0] - got[i - 1].p_T_m[0], 0.05) << "leap at sequence " << got[i].sequence;
    }
  }
}

TEST(DdsProcesses, TheMonitorShowsARigsTrackerSamplesAndState) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(35);
  const OutputFile server_log("monitor_server");
  const OutputFile log("monitor");
  ChildProcess server(server_args("sim_tracker_rig1.xml", domain, 5, 20.0), server_log.path());
  ChildProcess monitor({MHD_DDS_MONITOR, "--rig-id", "5", "--domain-id", std::to_string(domain), "--duration", "2.5"},
                       log.path());
  // The haptic server's part: rig 5's state at about 60 Hz.
  const Participant participant(domain);
  Publisher<mhd_dds_RigState> state(participant, rig_partition(5));
  mhd_dds_RigState s{};
  s.rig_id = 5;
  s.force_W_N[1] = 3.0;
  s.in_contact = true;
  s.p_W_hip_m[1] = 1.1;
  std::optional<int> exit_status;
  while (!exit_status) {
    s.timestamp_ns = realtime_ns();
    state.write(s);
    ++s.sequence_number;
    exit_status = monitor.wait_for(16ms);
  }
  ASSERT_EQ(exit_status, std::optional<int>(0)) << log.text();
  const std::string out = log.text();
  EXPECT_NE(out.find("rig 5 tracker/s: sensor 0: "), std::string::npos) << out;
  EXPECT_NE(out.find("hip 0.000 1.100 0.000 m  force 3.00 N  contact"), std::string::npos) << out;
}

TEST(DdsProcesses, ARateForAPluginWithoutOneIsRefusedByThePlugin) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(42);
  const OutputFile log("replay_rate");
  std::vector<std::string> args = server_args("replay_tracker.xml", domain, 1, 1.0);
  args.insert(args.end(), {"--rate-hz", "100"});
  ChildProcess server(args, log.path());
  ASSERT_EQ(server.wait_for(10s), std::optional<int>(1));
  EXPECT_NE(log.text().find("mhd tracker-server: error: plugin 'replay'"), std::string::npos) << log.text();
  EXPECT_NE(log.text().find("unknown parameter 'rate_hz' (known: file)\n"), std::string::npos) << log.text();
}

TEST(DdsProcesses, TheTrackerServerRefusesASceneWithoutATracker) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(40);
  const OutputFile log("no_tracker");
  ChildProcess server(server_args("no_tracker.xml", domain, 1, 1.0), log.path());
  ASSERT_EQ(server.wait_for(10s), std::optional<int>(1));
  EXPECT_NE(log.text().find("mhd tracker-server: error: " + std::string(MHD_SOURCE_DIR) +
                                      "/tests/dds/data/no_tracker.xml: the scene names 0 tracker plugins, "
                                      "the tracker server needs one"),
            std::string::npos)
      << log.text();
}

TEST(DdsProcesses, TheTrackerServerPrintsTheDiagnosticsOfASceneThatDoesNotRead) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(41);
  const OutputFile log("broken");
  ChildProcess server(server_args("broken_scene.xml", domain, 1, 1.0), log.path());
  ASSERT_EQ(server.wait_for(10s), std::optional<int>(1));
  EXPECT_NE(log.text().find(std::string(MHD_SOURCE_DIR) + "/tests/dds/data/broken_scene.xml:6: error: unknown plugin kind "
                            "'radar' (expected device, tracker, base, display or link)\n"),
            std::string::npos)
      << log.text();
}

TEST(DdsProcesses, WithoutAHapticServerASharedWorldTrackerPublishesNothingAndSaysWhy) {
  // --shared-world measures only a world that arrived: the simulated user of the scene is
  // not run, and before a world there is no base to measure.
  const std::uint32_t domain = test::use_loopback_and_unique_domain(42);
  const OutputFile log("shared_world_alone");
  std::vector<std::string> args = server_args("sim_tracker_rig1.xml", domain, 1, 1.0);
  args.emplace_back("--shared-world");
  ChildProcess server(args, log.path());
  ASSERT_EQ(server.wait_for(10s), std::optional<int>(0)) << log.text();
  EXPECT_NE(log.text().find("published 0 samples of 'sim_is900'"), std::string::npos) << log.text();
  EXPECT_NE(log.text().find("shared world: 0 states measured, 0 refused (none arrived: does the rig's dds tracker "
                            "set publish_sim_world?)"),
            std::string::npos)
      << log.text();
  EXPECT_EQ(log.text().find("publishing rig 1"), std::string::npos) << log.text();
}

}  // namespace
}  // namespace mhd::dds
