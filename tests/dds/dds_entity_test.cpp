// The RAII layer over ddsc in one process: errors become DdsError with Cyclone's
// text, samples go through writer -> reader, and keyed rigs keep their commands apart.

#include "dds_common/dds_topics.h"
#include "dds_test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

namespace mhd::dds {
namespace {

using namespace std::chrono_literals;

/// Takes from `reader` until `want` samples arrived or 3 s passed.
template <class T>
std::vector<T> take_at_least(Reader<T>& reader, std::size_t want) {
  std::vector<T> got;
  const auto end = std::chrono::steady_clock::now() + 3s;
  while (got.size() < want && std::chrono::steady_clock::now() < end) {
    reader.wait(DDS_MSECS(50));
    for (const T& s : reader.take()) got.push_back(s);
  }
  return got;
}

TEST(DdsEntity, AFailingCallThrowsDdsErrorWithCyclonesText) {
  try {
    (void)check(DDS_RETCODE_BAD_PARAMETER, "dds_create_reader");
    FAIL() << "no exception";
  } catch (const DdsError& e) {
    EXPECT_STREQ(e.what(), "dds_create_reader: Bad Parameter");
    EXPECT_EQ(e.code(), DDS_RETCODE_BAD_PARAMETER);
  }
  EXPECT_EQ(check(5, "x"), 5);
}

TEST(DdsEntity, ABrokenConfigurationFailsToCreateTheDomain) {
  (void)test::use_loopback_and_unique_domain();
  try {
    const Participant p(231, "<CycloneDDS><Domain><General><NoSuchSetting>1</NoSuchSetting></General></Domain></CycloneDDS>");
    FAIL() << "no exception";
  } catch (const DdsError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("dds_create_domain: ", 0), 0u) << e.what();
  }
  EXPECT_THROW(Participant(DDS_DOMAIN_DEFAULT, "file:///x.xml"), DdsError);
}

TEST(DdsEntity, RigStateGoesFromWriterToReader) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(1);
  const Participant pub_side(domain);
  const Participant sub_side(domain);
  Subscriber<mhd_dds_RigState> sub(sub_side, rig_partition(5));
  Publisher<mhd_dds_RigState> pub(pub_side, rig_partition(5));
  mhd_dds_RigState s{};
  s.rig_id = 5;
  s.force_W_N[1] = 1.5;
  s.in_contact = true;
  const auto end = std::chrono::steady_clock::now() + 3s;
  std::vector<mhd_dds_RigState> got;
  // Best-effort: publish until the reader has matched and taken one.
  while (got.empty() && std::chrono::steady_clock::now() < end) {
    pub.write(s);
    ++s.sequence_number;
    sub.reader().wait(DDS_MSECS(20));
    for (const auto& r : sub.reader().take()) got.push_back(r);
  }
  ASSERT_FALSE(got.empty());
  EXPECT_EQ(got.front().rig_id, 5u);
  EXPECT_EQ(got.front().force_W_N[1], 1.5);
  EXPECT_TRUE(got.front().in_contact);
}

TEST(DdsEntity, ReliableBaseCommandsOfTwoRigsStayApartByKey) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(2);
  const Participant a(domain);
  const Participant b(domain);
  // Both rigs' commands through one writer and one reader: the key keeps them apart.
  Subscriber<mhd_dds_BaseCommand> sub(b, kAllRigsPartition);
  Publisher<mhd_dds_BaseCommand> pub(a, rig_partition(1));
  const auto end = std::chrono::steady_clock::now() + 3s;
  while (pub.writer().matched_readers() == 0 && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(5ms);
  ASSERT_EQ(pub.writer().matched_readers(), 1u);
  for (std::uint64_t i = 0; i < 10; ++i) {
    mhd_dds_BaseCommand c{};
    c.rig_id = static_cast<std::uint32_t>(1 + i % 2);
    c.sequence_number = i;
    c.vx_mps = c.rig_id == 1 ? 0.1 : -0.2;
    pub.write(c);
  }
  const std::vector<mhd_dds_BaseCommand> got = take_at_least(sub.reader(), 10);
  ASSERT_EQ(got.size(), 10u);  // reliable, keep-last 8 per rig: nothing lost
  std::uint64_t last[3] = {0, 0, 0};
  bool first[3] = {true, true, true};
  for (const auto& c : got) {
    ASSERT_TRUE(c.rig_id == 1 || c.rig_id == 2);
    EXPECT_EQ(c.vx_mps, c.rig_id == 1 ? 0.1 : -0.2);
    if (!first[c.rig_id]) {
      EXPECT_GT(c.sequence_number, last[c.rig_id]);  // in order per rig
    }
    first[c.rig_id] = false;
    last[c.rig_id] = c.sequence_number;
  }
}

}  // namespace
}  // namespace mhd::dds
