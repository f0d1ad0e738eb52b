// The `dds_link` link plugin through the real dlopen path: two instances (rigs 1 and 2)
// in one domain hand each other every message whole, on each one's host clock; a sample
// written in rig 2's partition under another rig's id is refused and counted; a message
// of another rig is never sent; and the parameters are checked.

#include "../sim_backends/plugin_file.h"
#include "dds_common/dds_convert.h"
#include "dds_common/dds_topics.h"
#include "dds_test_support.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <thread>
#include <string>
#include <vector>

namespace mhd::dds::dds_link_test {

using namespace std::chrono_literals;

mhd_link_message a_state(std::uint32_t rig, std::uint64_t sequence, double t_s) {
  mhd_link_message m{};
  m.kind = MHD_LINK_STATE;
  m.object_id = 7;
  m.rig_id = rig;
  m.term = 3;
  m.sequence = sequence;
  m.timestamp_s = t_s;
  m.p_W_m[0] = 0.25;
  m.q_W_wxyz[0] = std::sqrt(0.5);
  m.q_W_wxyz[2] = std::sqrt(0.5);
  m.v_W_mps[2] = -0.1;
  m.w_W_radps[1] = 0.5;
  return m;
}

// Reads `link` until `want` messages came or 3 s passed.
std::vector<mhd_link_message> read_until(const mhd_plugin_api& api, mhd_plugin_instance* link, std::size_t want) {
  std::vector<mhd_link_message> got;
  mhd_error err{};
  const auto end = std::chrono::steady_clock::now() + 3s;
  while (got.size() < want && std::chrono::steady_clock::now() < end) {
    std::array<mhd_link_message, 8> out{};
    std::size_t n = 0;
    const mhd_status s = api.link_read(link, out.data(), out.size(), &n, &err);
    EXPECT_TRUE(s == MHD_OK || s == MHD_NO_DATA) << err.message;
    got.insert(got.end(), out.begin(), out.begin() + static_cast<std::ptrdiff_t>(n));
    std::this_thread::sleep_for(2ms);
  }
  return got;
}

std::uint64_t counter(const mhd_plugin_api& api, mhd_plugin_instance* link, const char* name) {
  std::array<mhd_counter, 8> out{};
  std::size_t n = 0;
  mhd_error err{};
  EXPECT_EQ(api.counters(link, out.data(), out.size(), &n, &err), MHD_OK);
  for (std::size_t i = 0; i < n && i < out.size(); ++i) {
    if (std::string(out[i].name) == name) return out[i].value;
  }
  ADD_FAILURE() << "no counter " << name;
  return 0;
}

TEST(DdsLinkPlugin, TheTableIdentifiesALinkAndItsParametersAreChecked) {
  const mhd::test::PluginFile file(MHD_DDS_LINK_PLUGIN);
  EXPECT_EQ(file.api().kind, MHD_KIND_LINK);
  EXPECT_STREQ(file.api().name, "dds_link");
  EXPECT_NE(file.api().link_send, nullptr);
  EXPECT_NE(file.api().link_read, nullptr);
  mhd::test::FakeHost h;
  EXPECT_EQ(mhd::test::open_plugin(file.api(), h.host, {{"rig_id", "1"}}).error,
            "parameter 'other_rigs' must name the rigs this one shares with");
  EXPECT_EQ(mhd::test::open_plugin(file.api(), h.host, {{"rig_id", "1"}, {"other_rigs", "2 1"}}).error,
            "parameter 'other_rigs' names the rig's own id 1, got '2 1'");
  EXPECT_EQ(mhd::test::open_plugin(file.api(), h.host, {{"rig_id", "1"}, {"other_rigs", "2 x"}}).error,
            "parameter 'other_rigs' must be rig ids in [0, 999999], got '2 x'");
}

TEST(DdsLinkPlugin, TwoRigsHandEachOtherEveryMessageWholeOnTheirOwnClocks) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(52);
  const std::string d = std::to_string(domain);
  const mhd::test::PluginFile file(MHD_DDS_LINK_PLUGIN);
  const mhd_plugin_api& api = file.api();
  // Rig 2's host clock runs 100 s ahead of rig 1's: a time must arrive on the reader's.
  mhd::test::FakeHost h1, h2;
  h1.now_s = 10.0;
  h2.now_s = 110.0;
  const mhd::test::StartedPlugin one(api, h1.host, {{"domain_id", d.c_str()}, {"rig_id", "1"}, {"other_rigs", "2"}});
  const mhd::test::StartedPlugin two(api, h2.host, {{"domain_id", d.c_str()}, {"rig_id", "2"}, {"other_rigs", "1"}});
  std::vector<mhd_link_message> got;
  mhd_error err{};
  const auto end = std::chrono::steady_clock::now() + 5s;
  for (std::uint64_t k = 1; got.empty() && std::chrono::steady_clock::now() < end; ++k) {
    const mhd_link_message m = a_state(1, k, 9.99);  // 10 ms ago on rig 1's clock
    ASSERT_EQ(api.link_send(one.get(), &m, 1, &err), MHD_OK) << err.message;
    got = read_until(api, two.get(), 1);
  }
  ASSERT_FALSE(got.empty());
  const mhd_link_message& m = got.front();
  EXPECT_EQ(m.kind, static_cast<std::uint32_t>(MHD_LINK_STATE));
  EXPECT_EQ(m.object_id, 7u);
  EXPECT_EQ(m.rig_id, 1u);
  EXPECT_EQ(m.term, 3u);
  EXPECT_EQ(m.p_W_m[0], 0.25);
  EXPECT_EQ(m.q_W_wxyz[2], std::sqrt(0.5));
  EXPECT_EQ(m.v_W_mps[2], -0.1);
  EXPECT_EQ(m.w_W_radps[1], 0.5);
  EXPECT_NEAR(m.timestamp_s, 109.99, 0.5);  // rig 2's clock, 10 ms and the delivery ago
  EXPECT_LE(m.timestamp_s, 109.99 + 1e-3);
  // A push the other way, and rig 1 never hears its own messages back.
  mhd_link_message push{};
  push.kind = MHD_LINK_PUSH;
  push.object_id = 7;
  push.rig_id = 2;
  push.sequence = 1;
  push.timestamp_s = 110.0;
  push.f_W_N[0] = -4.0;
  push.p_O_m[2] = 0.05;
  push.q_W_wxyz[0] = 1.0;
  ASSERT_EQ(api.link_send(two.get(), &push, 1, &err), MHD_OK) << err.message;
  const std::vector<mhd_link_message> back = read_until(api, one.get(), 1);
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].kind, static_cast<std::uint32_t>(MHD_LINK_PUSH));
  EXPECT_EQ(back[0].rig_id, 2u);
  EXPECT_EQ(back[0].f_W_N[0], -4.0);
  EXPECT_EQ(back[0].p_O_m[2], 0.05);
  EXPECT_NEAR(back[0].timestamp_s, 10.0, 0.5);
  EXPECT_GE(counter(api, two.get(), "link_received"), 1u);
  EXPECT_GE(counter(api, one.get(), "link_sent"), counter(api, two.get(), "link_received"));
}

TEST(DdsLinkPlugin, ASampleUnderAnotherRigsIdInARigsPartitionIsRefusedAndCounted) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(53);
  const std::string d = std::to_string(domain);
  const mhd::test::PluginFile file(MHD_DDS_LINK_PLUGIN);
  const mhd_plugin_api& api = file.api();
  mhd::test::FakeHost h;
  const mhd::test::StartedPlugin one(api, h.host, {{"domain_id", d.c_str()}, {"rig_id", "1"}, {"other_rigs", "2"}});
  // A writer in rig 2's partition that claims to be rig 3, then one that is rig 2.
  const Participant forger(domain);
  Publisher<mhd_dds_SharedObject> in_rig2(forger, rig_partition(2));
  std::uint64_t refused = 0;
  std::vector<mhd_link_message> got;
  const auto end = std::chrono::steady_clock::now() + 5s;
  while ((refused == 0 || got.empty()) && std::chrono::steady_clock::now() < end) {
    mhd_dds_SharedObject s{};
    s.rig_id = 3;
    s.object_id = 7;
    s.kind = MHD_LINK_STATE;
    s.q_W_wxyz[0] = 1.0;
    s.timestamp_ns = realtime_ns();
    in_rig2.write(s);
    s.rig_id = 2;
    in_rig2.write(s);
    const std::vector<mhd_link_message> more = read_until(api, one.get(), 1);
    got.insert(got.end(), more.begin(), more.end());
    refused = counter(api, one.get(), "link_refused_wrong_rig");
  }
  EXPECT_GT(refused, 0u);
  ASSERT_FALSE(got.empty());
  for (const mhd_link_message& m : got) EXPECT_EQ(m.rig_id, 2u);  // only rig 2's own
}

TEST(DdsLinkPlugin, AMessageOfAnotherRigIsNeverSent) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(54);
  const std::string d = std::to_string(domain);
  const mhd::test::PluginFile file(MHD_DDS_LINK_PLUGIN);
  const mhd_plugin_api& api = file.api();
  mhd::test::FakeHost h;
  const mhd::test::StartedPlugin one(api, h.host, {{"domain_id", d.c_str()}, {"rig_id", "1"}, {"other_rigs", "2"}});
  const mhd_link_message m = a_state(2, 1, 0.0);
  mhd_error err{};
  EXPECT_EQ(api.link_send(one.get(), &m, 1, &err), MHD_ERROR);
  EXPECT_STREQ(err.message,
               "a message of rig 2 given to the link of rig 1 (the scene's <sharing rig_id> and the plugin's rig_id "
               "must agree)");
  EXPECT_EQ(counter(api, one.get(), "link_sent"), 0u);
}

}  // namespace mhd::dds::dds_link_test
