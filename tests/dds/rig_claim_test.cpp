// One process per rig id (rig_claim.h), in one process with claimants standing in for
// processes: the oldest live claim holds the rig, a younger one is refused naming the
// holder and counted by it, even one that goes at once; a claim of another rig is no conflict; a withdrawn claim
// frees the rig; two claims made at once settle on exactly one holder.

#include "dds_common/rig_claim.h"
#include "dds_test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <optional>
#include <thread>

namespace mhd::dds::rig_claim_test {

using Standing = RigClaim::Standing;
constexpr std::int64_t kSettle_ns = 300'000'000;

Claimant claimant(std::uint32_t pid) { return Claimant{0x1234, pid, "bench"}; }

// Updates every claim until `done` holds or 3 s pass.
bool settle(const std::vector<RigClaim*>& claims, const std::function<bool()>& done) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while (std::chrono::steady_clock::now() < end) {
    for (RigClaim* c : claims) (void)c->update(realtime_ns());
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

TEST(RigClaim, TheOldestClaimHoldsAYoungerOneIsRefusedAndCounted) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(91);
  const Participant a_process(domain), b_process(domain), c_process(domain);
  const std::int64_t t0 = realtime_ns();
  RigClaim a(a_process, 5, kSettle_ns, claimant(100), t0);
  EXPECT_EQ(a.update(t0), Standing::Settling);  // nothing published yet
  RigClaim b(b_process, 5, kSettle_ns, claimant(200), t0 + 1000);
  RigClaim c(c_process, 5, kSettle_ns, claimant(300), t0 + 2000);
  ASSERT_TRUE(settle({&a, &b, &c}, [&] {
    return b.update(realtime_ns()) == Standing::Refused && c.update(realtime_ns()) == Standing::Refused &&
           a.refused() == 2;
  }));
  EXPECT_EQ(b.refusal().rfind("rig 5 is already claimed by bench:100 (since ", 0), 0u) << b.refusal();
  EXPECT_NE(b.refusal().find("this process (bench:200) may not run as rig 5"), std::string::npos) << b.refusal();
  EXPECT_EQ(b.update(realtime_ns()), Standing::Refused);  // for good
  EXPECT_EQ(b.refused(), 0u);
  EXPECT_TRUE(a.refusal().empty());
  // The holder holds once its claim has settled, and counts each refused claimant once.
  std::this_thread::sleep_for(std::chrono::nanoseconds(kSettle_ns));
  EXPECT_EQ(a.update(realtime_ns()), Standing::Holding);
  EXPECT_EQ(a.refused(), 2u);
}

TEST(RigClaim, AClaimantRefusedAndGoneAtOnceIsStillCountedByTheHolder) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(95);
  const Participant a_process(domain);
  RigClaim a(a_process, 6, kSettle_ns, claimant(100), realtime_ns());
  // Processes that claim, hear the holder and end as soon as they are refused, while
  // the holder runs its loop.
  constexpr std::uint64_t kClaimants = 4;
  for (std::uint64_t i = 0; i < kClaimants; ++i) {
    test::ChildProcess b({MHD_DDS_TEST_RIG_CLAIMANT, "--domain-id", std::to_string(domain), "--rig-id", "6"});
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    std::optional<int> rc;
    while (!rc && std::chrono::steady_clock::now() < end) {
      EXPECT_NE(a.update(realtime_ns()), Standing::Refused);
      rc = b.wait_for(std::chrono::milliseconds(5));
    }
    ASSERT_EQ(rc, 0) << "claimant " << i;
  }
  // Each was counted before it ended: no later read is needed.
  EXPECT_EQ(a.refused(), kClaimants);
}

TEST(RigClaim, ClaimsOfOtherRigsAreNoConflict) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(92);
  const Participant a_process(domain), b_process(domain);
  const std::int64_t t0 = realtime_ns();
  RigClaim a(a_process, 1, kSettle_ns, claimant(100), t0);
  RigClaim b(b_process, 2, kSettle_ns, claimant(200), t0 + 1000);
  EXPECT_TRUE(settle({&a, &b}, [&] {
    return a.update(realtime_ns()) == Standing::Holding && b.update(realtime_ns()) == Standing::Holding;
  }));
  EXPECT_EQ(a.refused(), 0u);
  EXPECT_EQ(b.refused(), 0u);
}

TEST(RigClaim, AWithdrawnClaimFreesTheRig) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(93);
  const Participant a_process(domain), b_process(domain), c_process(domain);
  auto a = std::make_unique<RigClaim>(a_process, 3, kSettle_ns, claimant(100), realtime_ns());
  {
    RigClaim b(b_process, 3, kSettle_ns, claimant(200), realtime_ns() + 1000);
    ASSERT_TRUE(settle({a.get(), &b}, [&] { return b.update(realtime_ns()) == Standing::Refused; }));
  }
  a.reset();  // the holder's process ends
  RigClaim c(c_process, 3, kSettle_ns, claimant(300), realtime_ns());
  EXPECT_TRUE(settle({&c}, [&] { return c.update(realtime_ns()) == Standing::Holding; }));
}

TEST(RigClaim, TwoClaimsAtOnceSettleOnOneHolder) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(94);
  const Participant a_process(domain), b_process(domain);
  const std::int64_t t0 = realtime_ns();
  // The same instant: the lower (host, pid) holds.
  RigClaim a(a_process, 4, kSettle_ns, claimant(200), t0);
  RigClaim b(b_process, 4, kSettle_ns, claimant(100), t0);
  ASSERT_TRUE(settle({&a, &b}, [&] { return a.update(realtime_ns()) == Standing::Refused; }));
  std::this_thread::sleep_for(std::chrono::nanoseconds(kSettle_ns));
  EXPECT_EQ(b.update(realtime_ns()), Standing::Holding);
  EXPECT_EQ(b.refused(), 1u);
  EXPECT_NE(a.refusal().find("claimed by bench:100"), std::string::npos) << a.refusal();
}

}  // namespace mhd::dds::rig_claim_test
