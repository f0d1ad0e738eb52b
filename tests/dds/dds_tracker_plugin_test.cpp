// The `dds` tracker plugin's table and parameters through the real dlopen path (its
// samples are tested with real processes in dds_process_test.cpp).

#include "../sim_backends/plugin_file.h"
#include "dds_test_support.h"

#include <gtest/gtest.h>

#include <string>

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
