// Only the object's authority in its current term moves a shared object; a rig that lost
// the authority is ignored whatever its sequence numbers, and every ignored sample is
// counted by reason. Each refusal has its dual: the same sample, correct, is obeyed.

#include "sharing/object_authority.h"

#include <gtest/gtest.h>

#include <limits>

namespace mhd::authority_test {

constexpr int kObject = 3;

SharedObjectState state_of(std::uint32_t rig, std::uint32_t epoch, std::uint64_t sequence) {
  SharedObjectState s;
  s.object = kObject;
  s.authority_rig = rig;
  s.epoch = epoch;
  s.sequence = sequence;
  s.t_s = 0.001 * static_cast<double>(sequence);
  return s;
}

ObjectAuthority shared_by_1_then_2() {
  ObjectAuthority a;
  const std::uint32_t rigs[2] = {1, 2};
  EXPECT_TRUE(a.share(kObject, rigs, 2));
  return a;
}

TEST(ObjectAuthority, TheAuthorityIsObeyedInOrderAndNobodyElse) {
  ObjectAuthority a = shared_by_1_then_2();
  EXPECT_EQ(a.authority(kObject), 1u);
  EXPECT_EQ(a.epoch(kObject), 0u);
  EXPECT_EQ(a.judge(state_of(1, 0, 1)), StateVerdict::Obeyed);
  EXPECT_EQ(a.judge(state_of(1, 0, 2)), StateVerdict::Obeyed);
  EXPECT_EQ(a.judge(state_of(1, 0, 2)), StateVerdict::Stale);  // a duplicate
  EXPECT_EQ(a.judge(state_of(1, 0, 1)), StateVerdict::Stale);  // reordered
  EXPECT_EQ(a.judge(state_of(2, 0, 9)), StateVerdict::NotAuthority);
  EXPECT_EQ(a.count(StateVerdict::Obeyed), 2u);
  EXPECT_EQ(a.count(StateVerdict::Stale), 2u);
  EXPECT_EQ(a.count(StateVerdict::NotAuthority), 1u);
}

TEST(ObjectAuthority, ARigThatLostTheAuthorityIsIgnoredForEver) {
  ObjectAuthority a = shared_by_1_then_2();
  EXPECT_EQ(a.judge(state_of(1, 0, 5)), StateVerdict::Obeyed);
  EXPECT_EQ(a.take_over(kObject, 2), 1);
  EXPECT_EQ(a.authority(kObject), 2u);
  // Rig 1 carries on in its old term with ever higher sequence numbers: never obeyed.
  for (std::uint64_t k = 6; k < 100; ++k) EXPECT_EQ(a.judge(state_of(1, 0, k)), StateVerdict::OldTerm);
  EXPECT_EQ(a.count(StateVerdict::OldTerm), 94u);
  // Its successor is, from its first sample on.
  EXPECT_EQ(a.judge(state_of(2, 1, 1)), StateVerdict::Obeyed);
  EXPECT_EQ(a.judge(state_of(2, 1, 2)), StateVerdict::Obeyed);
}

TEST(ObjectAuthority, AHandOverIsHeardThroughTheNewAuthoritysFirstState) {
  ObjectAuthority a = shared_by_1_then_2();
  EXPECT_EQ(a.judge(state_of(1, 0, 7)), StateVerdict::Obeyed);
  // Rig 2 took over elsewhere; its first state (a low sequence) starts term 1 here.
  EXPECT_EQ(a.judge(state_of(2, 1, 1)), StateVerdict::Obeyed);
  EXPECT_EQ(a.authority(kObject), 2u);
  EXPECT_EQ(a.epoch(kObject), 1u);
  EXPECT_EQ(a.judge(state_of(1, 0, 8)), StateVerdict::OldTerm);
  // A later term from a rig that may never hold the object changes nothing.
  EXPECT_EQ(a.judge(state_of(9, 2, 1)), StateVerdict::NotAllowed);
  EXPECT_EQ(a.authority(kObject), 2u);
  EXPECT_EQ(a.epoch(kObject), 1u);
  EXPECT_EQ(a.take_over(kObject, 9), -1);
}

TEST(ObjectAuthority, BrokenSamplesAreRefusedAndTheirRepairedTwinObeyed) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  ObjectAuthority a = shared_by_1_then_2();
  std::uint64_t sequence = 0;
  const auto broken = [&](auto&& breaks) {
    SharedObjectState s = state_of(1, 0, ++sequence);
    breaks(s);
    return s;
  };
  const std::vector<SharedObjectState> samples{
      broken([&](SharedObjectState& s) { s.t_s = kNaN; }),
      broken([&](SharedObjectState& s) { s.t_s = -kInf; }),
      broken([&](SharedObjectState& s) { s.X_WO.translation().x() = kInf; }),
      broken([&](SharedObjectState& s) { s.X_WO.linear()(0, 1) = kNaN; }),
      broken([&](SharedObjectState& s) { s.X_WO.linear() *= 2.0; }),                      // not a rotation
      broken([&](SharedObjectState& s) { s.X_WO.linear() = -s.X_WO.linear(); }),           // a reflection
      broken([&](SharedObjectState& s) { s.twist_W.v_W_origin_mps.y() = kNaN; }),
      broken([&](SharedObjectState& s) { s.twist_W.omega_W_radps.z() = -kInf; }),
  };
  for (const SharedObjectState& s : samples) EXPECT_EQ(a.judge(s), StateVerdict::NotFinite);
  EXPECT_EQ(a.count(StateVerdict::NotFinite), samples.size());
  EXPECT_EQ(a.judge(state_of(1, 0, ++sequence)), StateVerdict::Obeyed);

  SharedObjectState elsewhere = state_of(1, 0, ++sequence);
  elsewhere.object = kObject + 1;
  EXPECT_EQ(a.judge(elsewhere), StateVerdict::NotShared);
  elsewhere.object = -1;
  EXPECT_EQ(a.judge(elsewhere), StateVerdict::NotShared);
  elsewhere.object = kMaxSharedObjects;
  EXPECT_EQ(a.judge(elsewhere), StateVerdict::NotShared);
}

TEST(ObjectAuthority, SharingNeedsAnObjectInRangeAndDistinctRigs) {
  ObjectAuthority a;
  const std::uint32_t twice[2] = {4, 4};
  const std::uint32_t many[kMaxAuthorityRigs + 1] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  EXPECT_FALSE(a.share(kObject, twice, 2));
  EXPECT_FALSE(a.share(kObject, many, kMaxAuthorityRigs + 1));
  EXPECT_FALSE(a.share(kObject, many, 0));
  EXPECT_FALSE(a.share(kObject, nullptr, 1));
  EXPECT_FALSE(a.share(-1, many, 1));
  EXPECT_FALSE(a.share(kMaxSharedObjects, many, 1));
  EXPECT_FALSE(a.is_shared(kObject));
  EXPECT_TRUE(a.share(kMaxSharedObjects - 1, many, kMaxAuthorityRigs));
  EXPECT_TRUE(a.share(0, many, 1));
  EXPECT_TRUE(a.is_shared(0));
  EXPECT_EQ(a.take_over(kObject, 1), -1);  // not shared
}

}  // namespace mhd::authority_test
