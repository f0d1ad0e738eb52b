// The `dds_state` display plugin through the real dlopen path: each frame it is given
// arrives at a RigState reader of the same domain, numbered and stamped.

#include "../sim_backends/plugin_file.h"
#include "dds_common/dds_convert.h"
#include "dds_common/dds_topics.h"
#include "dds_test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

namespace mhd::dds {
namespace {

using namespace std::chrono_literals;

TEST(DdsStatePlugin, TheTableIdentifiesADisplayAndUnknownParametersAreRefused) {
  const mhd::test::PluginFile file(MHD_DDS_STATE_PLUGIN);
  EXPECT_EQ(file.api().kind, MHD_KIND_DISPLAY);
  EXPECT_STREQ(file.api().name, "dds_state");
  EXPECT_NE(file.api().display_write, nullptr);
  mhd::test::FakeHost h;
  const auto opened = mhd::test::open_plugin(file.api(), h.host, {{"rate", "60"}});
  EXPECT_EQ(opened.instance, nullptr);
  EXPECT_EQ(opened.error.rfind("unknown parameter 'rate' (known: rig_id", 0), 0u) << opened.error;
  EXPECT_EQ(mhd::test::open_plugin(file.api(), h.host, {{"domain_id", "233"}}).error,
            "parameter 'domain_id' must be a non-negative integer in [0, 232], got '233'");
  EXPECT_EQ(mhd::test::open_plugin(file.api(), h.host, {{"config_file", "x.xml"}}).error,
            "parameter 'config_file' needs 'domain_id'");
}

TEST(DdsStatePlugin, EachFrameIsPublishedAsTheRigsState) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(50);
  const Participant viewer(domain);
  Subscriber<mhd_dds_RigState> sub(viewer, kAllRigsPartition);

  const mhd::test::PluginFile file(MHD_DDS_STATE_PLUGIN);
  mhd::test::FakeHost h;
  h.now_s = 10.0;
  const std::string d = std::to_string(domain);
  const auto opened = mhd::test::open_plugin(file.api(), h.host, {{"domain_id", d.c_str()}, {"rig_id", "4"}});
  ASSERT_NE(opened.instance, nullptr) << opened.error;
  mhd_error err{};
  mhd_display_frame frame{};
  frame.timestamp_s = 9.99;  // 10 ms ago on the host clock
  frame.force_W_N[2] = -3.0;
  frame.in_contact = 1;
  frame.p_W_head_m[1] = 1.65;
  frame.q_W_head_wxyz[0] = 1.0;
  EXPECT_EQ(file.api().display_write(opened.instance, &frame, &err), MHD_ERROR);  // not started
  EXPECT_STREQ(err.message, "dds_state is not started");
  ASSERT_EQ(file.api().start(opened.instance, &err), MHD_OK);

  std::vector<mhd_dds_RigState> got;
  const auto end = std::chrono::steady_clock::now() + 3s;
  while (got.size() < 3 && std::chrono::steady_clock::now() < end) {
    ASSERT_EQ(file.api().display_write(opened.instance, &frame, &err), MHD_OK) << err.message;
    sub.reader().wait(DDS_MSECS(20));
    for (const auto& s : sub.reader().take()) got.push_back(s);
  }
  file.api().stop(opened.instance, &err);
  file.api().close(opened.instance);
  ASSERT_GE(got.size(), 3u);
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].rig_id, 4u);
    EXPECT_EQ(got[i].force_W_N[2], -3.0);
    EXPECT_TRUE(got[i].in_contact);
    EXPECT_EQ(got[i].p_W_head_m[1], 1.65);
    // Stamped 10 ms before it was written, on CLOCK_REALTIME.
    const double age_s = static_cast<double>(realtime_ns() - got[i].timestamp_ns) * 1e-9;
    EXPECT_GT(age_s, 0.0099);
    EXPECT_LT(age_s, 5.0);
    if (i > 0) {
      EXPECT_GT(got[i].sequence_number, got[i - 1].sequence_number);
    }
  }
}

}  // namespace
}  // namespace mhd::dds
