// The RAII layer over ddsc in one process: errors become DdsError with Cyclone's
// text, samples go through writer -> reader, and keyed rigs keep their commands apart.

#include "dds_common/dds_topics.h"
#include "dds_test_support.h"

#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <memory>
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

/// A UDP port held as another process's participant would hold it.
class HeldPort {
 public:
  explicit HeldPort(std::uint16_t port) : fd_(::socket(AF_INET, SOCK_DGRAM, 0)) {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_ANY);
    address.sin_port = htons(port);
    bound_ = fd_ >= 0 && ::bind(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0;
  }
  ~HeldPort() {
    if (fd_ >= 0) ::close(fd_);
  }
  HeldPort(const HeldPort&) = delete;
  HeldPort& operator=(const HeldPort&) = delete;
  [[nodiscard]] bool bound() const { return bound_; }

 private:
  int fd_;
  bool bound_ = false;
};

TEST(DdsEntity, AllParticipantIndicesTakenIsNamedAsTheCause) {
  // One participant index allowed; a stranger holds its discovery port (RTPS: 7400 +
  // 250 domain + 10 + 2 index). Cyclone says only "Error"; the cause is in its log.
  const std::uint32_t domain = test::use_loopback_and_unique_domain(17);
  const std::string config =
      "<CycloneDDS><Domain><General><Interfaces><NetworkInterface address=\"127.0.0.1\"/></Interfaces>"
      "<AllowMulticast>false</AllowMulticast></General><Discovery><ParticipantIndex>auto</ParticipantIndex>"
      "<MaxAutoParticipantIndex>0</MaxAutoParticipantIndex><Peers><Peer address=\"127.0.0.1\"/></Peers>"
      "</Discovery></Domain></CycloneDDS>";
  {
    const HeldPort stranger(static_cast<std::uint16_t>(7400 + 250 * domain + 10));
    ASSERT_TRUE(stranger.bound());
    try {
      const Participant p(domain, config);
      FAIL() << "created with its only index taken";
    } catch (const DdsError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("participant index"), std::string::npos) << what;
      EXPECT_NE(what.find("MaxAutoParticipantIndex"), std::string::npos) << what;
      EXPECT_EQ(what.find("ertificate"), std::string::npos) << what;
      EXPECT_EQ(what.find("identity"), std::string::npos) << what;
    }
  }
}

TEST(DdsEntity, TwentyIdleStrangersOnThisHostDoNotLockTheRigOut) {
  // Each stranger holds one participant index: its discovery and data ports.
  const std::uint32_t domain = test::use_loopback_and_unique_domain(23);
  std::vector<std::unique_ptr<HeldPort>> strangers;
  for (std::uint32_t index = 0; index < 20; ++index) {
    for (std::uint32_t port : {10u, 11u}) {
      strangers.push_back(std::make_unique<HeldPort>(static_cast<std::uint16_t>(7400 + 250 * domain + port + 2 * index)));
      ASSERT_TRUE(strangers.back()->bound()) << "index " << index;
    }
  }
  EXPECT_NO_THROW(const Participant p(domain)) << "config/cyclonedds-loopback.xml";
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
