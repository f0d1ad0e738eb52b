#include "plugin_file.h"

#include <gtest/gtest.h>

#include <vector>

namespace mhd::test {
namespace {

TEST(ReplayPlugin, TheTableIdentifiesATrackerWithoutSimulation) {
  const PluginFile file(MHD_REPLAY_PLUGIN);
  const mhd_plugin_api& api = file.api();
  EXPECT_EQ(api.abi_version, MHD_PLUGIN_ABI_VERSION);
  EXPECT_EQ(api.struct_size, sizeof(mhd_plugin_api));
  EXPECT_EQ(api.kind, MHD_KIND_TRACKER);
  EXPECT_STREQ(api.name, "replay");
  EXPECT_NE(api.tracker_read, nullptr);
  EXPECT_EQ(api.simulate_until, nullptr);
}

TEST(ReplayPlugin, OpenNamesTheFileAndLineOfABadRow) {
  const PluginFile file(MHD_REPLAY_PLUGIN);
  FakeHost h;
  EXPECT_EQ(open_plugin(file.api(), h.host, {}).error, "parameter 'file' is required");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"file", "tests/data/replay/nan.csv"}}).error,
            "tests/data/replay/nan.csv:3: column 'py' is not finite: 'nan'");
  EXPECT_EQ(open_plugin(file.api(), h.host, {{"file", "tests/data/replay/valid.csv"}, {"loop", "1"}}).error,
            "unknown parameter 'loop' (known: file)");
}

TEST(ReplayPlugin, PlaysTheFileOnTheHostClockFromStart) {
  const PluginFile file(MHD_REPLAY_PLUGIN);
  const mhd_plugin_api& api = file.api();
  FakeHost h;  // replay needs no simulated world
  const Opened opened = open_plugin(api, h.host, {{"file", "tests/data/replay/valid.csv"}});
  ASSERT_NE(opened.instance, nullptr) << opened.error;
  mhd_plugin_instance* tracker = opened.instance;
  mhd_error err{};
  h.now_s = 50.0;
  ASSERT_EQ(api.start(tracker, &err), MHD_OK) << err.message;

  std::vector<mhd_tracker_sample> out(8);
  std::size_t count = 0;
  ASSERT_EQ(api.tracker_read(tracker, out.data(), out.size(), &count, &err), MHD_OK) << err.message;
  ASSERT_EQ(count, 2u);
  EXPECT_EQ(out[0].timestamp_s, 50.0);
  EXPECT_EQ(out[0].sequence, 7u);
  EXPECT_EQ(out[1].sensor_id, 1u);
  EXPECT_EQ(api.tracker_read(tracker, out.data(), out.size(), &count, &err), MHD_NO_DATA);
  EXPECT_EQ(count, 0u);
  h.now_s = 50.03;
  ASSERT_EQ(api.tracker_read(tracker, out.data(), out.size(), &count, &err), MHD_OK);
  ASSERT_EQ(count, 3u);
  EXPECT_NEAR(out[2].timestamp_s, 50.025, 1e-12);
  EXPECT_EQ(out[2].p_T_m[0], 1.02);
  h.now_s = 60.0;
  EXPECT_EQ(api.tracker_read(tracker, out.data(), out.size(), &count, &err), MHD_NO_DATA);
  ASSERT_EQ(api.stop(tracker, &err), MHD_OK);
  api.close(tracker);
}

}  // namespace
}  // namespace mhd::test
