// The `dds` tracker plugin's table and parameters through the real dlopen path (its
// samples are tested with real processes in dds_process_test.cpp).

#include "../sim_backends/plugin_file.h"
#include "dds_test_support.h"

#include "dds_common/dds_topics.h"

#include <gtest/gtest.h>

#include <chrono>
#include <set>
#include <string>
#include <thread>

namespace mhd::dds {
namespace {

// simulate_until publishes the scene's simulated world when asked (publish_sim_world).
TEST(DdsTrackerPlugin, TheTableIdentifiesATrackerThatCanPublishTheSimulatedWorld) {
  const mhd::test::PluginFile file(MHD_DDS_TRACKER_PLUGIN);
  EXPECT_EQ(file.api().kind, MHD_KIND_TRACKER);
  EXPECT_STREQ(file.api().name, "dds");
  EXPECT_NE(file.api().tracker_read, nullptr);
  EXPECT_NE(file.api().simulate_until, nullptr);
  EXPECT_EQ(file.entry(MHD_PLUGIN_ABI_VERSION + 1), nullptr);
}

TEST(DdsTrackerPlugin, BadParametersAreRefusedWithTheirNames) {
  const mhd::test::PluginFile file(MHD_DDS_TRACKER_PLUGIN);
  mhd::test::FakeHost h;
  const std::string unknown = mhd::test::open_plugin(file.api(), h.host, {{"rate_hz", "190"}}).error;
  EXPECT_EQ(unknown.rfind("unknown parameter 'rate_hz' (known: rig_id, domain_id, config_file, identity_dir, max_position_m", 0), 0u) << unknown;
  EXPECT_EQ(mhd::test::open_plugin(file.api(), h.host, {{"rig_id", "-1"}}).error,
            "parameter 'rig_id' must be a non-negative integer in [0, 4294967295], got '-1'");
  EXPECT_EQ(mhd::test::open_plugin(file.api(), h.host, {{"max_age_s", "0"}}).error,
            "parameter 'max_age_s' must be a number in (0, 10] (s), got '0'");
  EXPECT_EQ(mhd::test::open_plugin(file.api(), h.host, {{"config_file", "config/cyclonedds-loopback.xml"}}).error,
            "parameter 'config_file' needs 'domain_id'");
  EXPECT_EQ(mhd::test::open_plugin(file.api(), h.host, {{"publish_sim_world", "yes"}}).error,
            "parameter 'publish_sim_world' must be true or false, got 'yes'");
}

TEST(DdsTrackerPlugin, OpensWithAConfigFileAndReadsOnlyWhenStarted) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(60);
  const mhd::test::PluginFile file(MHD_DDS_TRACKER_PLUGIN);
  mhd::test::FakeHost h;
  const std::string d = std::to_string(domain);
  // Relative to the working directory (the repository root) when the host has no scene.
  const auto opened = mhd::test::open_plugin(
      file.api(), h.host, {{"domain_id", d.c_str()}, {"config_file", "config/cyclonedds-loopback.xml"}});
  ASSERT_NE(opened.instance, nullptr) << opened.error;
  mhd_tracker_sample out[4];
  std::size_t count = 7;
  mhd_error err{};
  EXPECT_EQ(file.api().tracker_read(opened.instance, out, 4, &count, &err), MHD_ERROR);
  EXPECT_STREQ(err.message, "dds is not started");
  ASSERT_EQ(file.api().start(opened.instance, &err), MHD_OK);
  EXPECT_EQ(file.api().tracker_read(opened.instance, out, 4, &count, &err), MHD_NO_DATA);  // nobody publishes
  EXPECT_EQ(count, 0u);
  EXPECT_EQ(file.api().tracker_read(opened.instance, out, 4, nullptr, &err), MHD_ERROR);
  EXPECT_STREQ(err.message, "tracker_read: NULL output");
  EXPECT_EQ(file.api().stop(opened.instance, &err), MHD_OK);
  file.api().close(opened.instance);
}

TEST(DdsTrackerPlugin, AMissingConfigFileFailsTheOpen) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(61);
  const mhd::test::PluginFile file(MHD_DDS_TRACKER_PLUGIN);
  mhd::test::FakeHost h;
  const std::string d = std::to_string(domain);
  const std::string error =
      mhd::test::open_plugin(file.api(), h.host, {{"domain_id", d.c_str()}, {"config_file", "/nonexistent/dds.xml"}})
          .error;
  EXPECT_EQ(error.rfind("dds_create_domain: ", 0), 0u) << error;
}

}  // namespace
}  // namespace mhd::dds

namespace mhd::dds {
namespace {

TEST(DdsTrackerPlugin, OtherRigsAreRefusedWhenMalformedAndTakenWhenWellFormed) {
  const mhd::test::PluginFile file(MHD_DDS_TRACKER_PLUGIN);
  mhd::test::FakeHost h;
  const auto error = [&](const char* value) {
    return mhd::test::open_plugin(file.api(), h.host, {{"rig_id", "1"}, {"other_rigs", value}}).error;
  };
  EXPECT_EQ(error("2 x"), "parameter 'other_rigs' must be rig ids in [0, 999999], got '2 x'");
  EXPECT_EQ(error("-2"), "parameter 'other_rigs' must be rig ids in [0, 999999], got '-2'");
  EXPECT_EQ(error("1000000"), "parameter 'other_rigs' must be rig ids in [0, 999999], got '1000000'");
  EXPECT_EQ(error("2 1"), "parameter 'other_rigs' names the rig's own id 1, got '2 1'");
  EXPECT_EQ(error("2 3 2"), "parameter 'other_rigs' names rig 2 twice, got '2 3 2'");
  EXPECT_EQ(error("2 3 4 5 6 7 8 9 10"), "parameter 'other_rigs' names more than 8 rigs, got '2 3 4 5 6 7 8 9 10'");
  // The dual: eight rigs, and the largest id, open.
  const std::uint32_t domain = test::use_loopback_and_unique_domain(61);
  const std::string d = std::to_string(domain);
  const auto opened = mhd::test::open_plugin(
      file.api(), h.host, {{"rig_id", "1"}, {"domain_id", d.c_str()}, {"other_rigs", "0 2 3 4 5 6 7 999999"}});
  ASSERT_NE(opened.instance, nullptr) << opened.error;
  file.api().close(opened.instance);
}

mhd_dds_TrackerSample sample_of(std::uint32_t rig, std::uint32_t sensor, std::uint64_t sequence) {
  mhd_dds_TrackerSample s{};
  s.rig_id = rig;
  s.sensor_id = sensor;
  s.sequence_number = sequence;
  s.timestamp_ns = realtime_ns();
  s.p_T_m[0] = static_cast<double>(rig);
  s.q_T_wxyz[0] = 1.0;
  return s;
}

TEST(DdsTrackerPlugin, TheOtherRigsSamplesArriveUnderTheirOwnSensorIdsAndNoOthers) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(62);
  const Participant tracker(domain);
  Publisher<mhd_dds_TrackerSample> rig1(tracker, rig_partition(1)), rig2(tracker, rig_partition(2)),
      rig3(tracker, rig_partition(3));
  const mhd::test::PluginFile file(MHD_DDS_TRACKER_PLUGIN);
  mhd::test::FakeHost h;
  const std::string d = std::to_string(domain);
  const auto opened =
      mhd::test::open_plugin(file.api(), h.host, {{"rig_id", "1"}, {"domain_id", d.c_str()}, {"other_rigs", "2"}});
  ASSERT_NE(opened.instance, nullptr) << opened.error;
  mhd_error err{};
  ASSERT_EQ(file.api().start(opened.instance, &err), MHD_OK);
  std::set<std::uint32_t> sensors;
  std::set<double> x_m;
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  for (std::uint64_t k = 1; std::chrono::steady_clock::now() < end && sensors.size() < 2; ++k) {
    rig1.write(sample_of(1, 0, k));
    rig2.write(sample_of(2, 1, k));
    rig3.write(sample_of(3, 1, k));
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    mhd_tracker_sample out[16];
    std::size_t count = 0;
    (void)file.api().tracker_read(opened.instance, out, 16, &count, &err);
    for (std::size_t i = 0; i < count; ++i) {
      sensors.insert(out[i].sensor_id);
      x_m.insert(out[i].p_T_m[0]);
    }
  }
  EXPECT_EQ(sensors, (std::set<std::uint32_t>{0u, 2001u}));
  EXPECT_EQ(x_m, (std::set<double>{1.0, 2.0}));  // rig 3's samples never arrive
  EXPECT_EQ(file.api().stop(opened.instance, &err), MHD_OK);
  file.api().close(opened.instance);
}

}  // namespace
}  // namespace mhd::dds
