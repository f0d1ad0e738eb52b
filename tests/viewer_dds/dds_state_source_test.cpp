// The viewer's DDS state source against a publisher of the same (loopback, unique)
// domain: states of its rig arrive as the viewer's RigState, other rigs and undrawable
// states are left out, the last state is kept when the publisher goes away, and the
// "no rig state" / "again" lines are said once each.

#include "viewer_dds/dds_state_source.h"

#include "dds_common/dds_convert.h"
#include "dds_common/dds_topics.h"
#include "../dds/dds_test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace mhd::viewer {
namespace {

mhd_dds_RigState rig_state(std::uint32_t rig, std::uint64_t sequence, double hip_x_m) {
  mhd_display_frame f{};
  f.p_W_hip_m[0] = hip_x_m;
  f.p_W_hip_m[1] = 1.1;
  f.p_W_hip_m[2] = -0.3;
  f.p_W_proxy_m[0] = hip_x_m;
  f.force_W_N[1] = 2.5;
  f.in_contact = 1;
  f.base_x_m = -0.8;
  f.base_z_m = 0.4;
  f.base_heading_rad = 0.5;
  f.p_W_head_m[1] = 1.7;
  f.q_W_head_wxyz[0] = 1.0;
  return dds::to_dds(f, rig, sequence, dds::realtime_ns());
}

struct Fixture {
  explicit Fixture(std::uint32_t salt, std::uint32_t rig = 3)
      : domain(dds::test::use_loopback_and_unique_domain(salt)),
        publisher_participant(domain),
        publisher(std::make_unique<dds::Publisher<mhd_dds_RigState>>(publisher_participant, dds::rig_partition(rig))) {
    DdsStateSourceOptions o;
    o.rig_id = rig;
    o.domain_id = domain;
    o.stale_after_s = 1.0;
    source = std::make_unique<DdsStateSource>(o, [this](const std::string& line) { lines.push_back(line); });
  }

  /// Publishes `samples` every 10 ms until the source's count of `counter` grows (at
  /// most 5 s); the source is polled at `now_s`. Returns the source's last answer.
  std::optional<RigState> publish_until(const std::vector<mhd_dds_RigState>& samples, double now_s,
                                        std::uint64_t DdsStateSourceStatus::*counter = &DdsStateSourceStatus::received) {
    const std::uint64_t before = source->status().*counter;
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    std::optional<RigState> got = source->poll(now_s);
    while (source->status().*counter == before && std::chrono::steady_clock::now() < end) {
      for (const mhd_dds_RigState& s : samples) publisher->write(s);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      got = source->poll(now_s);
    }
    return got;
  }

  std::uint32_t domain;
  dds::Participant publisher_participant;
  std::unique_ptr<dds::Publisher<mhd_dds_RigState>> publisher;
  std::vector<std::string> lines;
  std::unique_ptr<DdsStateSource> source;
};

TEST(DdsStateSource, StatesOfItsRigArriveAndAreKeptWhenThePublisherVanishes) {
  Fixture f(1);
  EXPECT_FALSE(f.source->poll(100.0).has_value()) << "nothing published yet";
  const std::optional<RigState> got = f.publish_until({rig_state(3, 0, 0.12)}, 100.2);
  ASSERT_TRUE(got.has_value()) << "no state arrived in 5 s";
  EXPECT_DOUBLE_EQ(got->p_W_hip_m.x(), 0.12);
  EXPECT_DOUBLE_EQ(got->p_W_hip_m.y(), 1.1);
  EXPECT_DOUBLE_EQ(got->p_W_hip_m.z(), -0.3);
  EXPECT_DOUBLE_EQ(got->force_W_N.y(), 2.5);
  EXPECT_TRUE(got->in_contact);
  EXPECT_DOUBLE_EQ(got->base.x_m, -0.8);
  EXPECT_DOUBLE_EQ(got->base.z_m, 0.4);
  EXPECT_DOUBLE_EQ(got->base.heading_rad, 0.5);
  EXPECT_NEAR(got->X_W_head.translation().y(), 1.7, 1e-12);
  EXPECT_TRUE(f.lines.empty()) << f.lines.front();

  // The publisher goes away: the last state stays; after 1 s of silence it is said once.
  f.publisher.reset();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_TRUE(f.source->poll(100.2).has_value());  // whatever was still on its way
  std::optional<RigState> kept = f.source->poll(100.9);
  ASSERT_TRUE(kept.has_value());
  EXPECT_TRUE(f.lines.empty()) << "0.7 s of silence is not yet 1 s: " << f.lines.front();
  EXPECT_FALSE(f.source->status().stale);
  kept = f.source->poll(101.5);
  ASSERT_TRUE(kept.has_value()) << "the last state is kept";
  EXPECT_DOUBLE_EQ(kept->p_W_hip_m.x(), 0.12);
  EXPECT_TRUE(f.source->status().stale);
  ASSERT_EQ(f.lines.size(), 1u);
  EXPECT_EQ(f.lines[0], "no rig state from rig 3 for 1.3 s (publisher gone?); keeping the last state");
  for (double t = 102.0; t < 110.0; t += 1.0) {
    ASSERT_TRUE(f.source->poll(t).has_value());
  }
  EXPECT_EQ(f.lines.size(), 1u) << "said once, not every frame";

  // A publisher comes back: its state is drawn and that is said once.
  f.publisher = std::make_unique<dds::Publisher<mhd_dds_RigState>>(f.publisher_participant, dds::rig_partition(3));
  const std::optional<RigState> back = f.publish_until({rig_state(3, 0, -0.25)}, 112.2);
  ASSERT_TRUE(back.has_value());
  EXPECT_DOUBLE_EQ(back->p_W_hip_m.x(), -0.25);
  EXPECT_FALSE(f.source->status().stale);
  ASSERT_EQ(f.lines.size(), 2u);
  EXPECT_EQ(f.lines[1], "rig state again from rig 3 after 12.0 s");
}

TEST(DdsStateSource, NothingAtAllIsSaidOnceAndTheSceneIsDrawnAlone) {
  Fixture f(2);
  EXPECT_FALSE(f.source->poll(5.0).has_value());
  EXPECT_FALSE(f.source->poll(6.5).has_value());
  ASSERT_EQ(f.lines.size(), 1u);
  EXPECT_EQ(f.lines[0], "no rig state from rig 3 yet after 1.5 s; drawing the scene only");
  EXPECT_FALSE(f.source->poll(9.0).has_value());
  EXPECT_EQ(f.lines.size(), 1u);
  ASSERT_TRUE(f.publish_until({rig_state(3, 0, 0.3)}, 9.5).has_value());
  ASSERT_EQ(f.lines.size(), 2u);
  EXPECT_EQ(f.lines[1], "first rig state from rig 3 after 4.5 s");
}

TEST(DdsStateSource, OtherRigsAndStatesThatCannotBeDrawnAreLeftOut) {
  Fixture f(3);
  // Rig 7's states are counted and ignored.
  EXPECT_FALSE(f.publish_until({rig_state(7, 0, 0.5)}, 1.0, &DdsStateSourceStatus::other_rigs).has_value());
  EXPECT_GT(f.source->status().other_rigs, 0u);
  EXPECT_EQ(f.source->status().received, 0u);
  // A NaN HIP and a zero head quaternion are dropped with the reason.
  mhd_dds_RigState nan_hip = rig_state(3, 1, 0.0);
  nan_hip.p_W_hip_m[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(f.publish_until({nan_hip}, 1.1, &DdsStateSourceStatus::dropped_invalid).has_value());
  EXPECT_EQ(f.source->status().last_error, "display frame: p_W_hip_m[1] is not finite");
  EXPECT_EQ(f.source->status().received, 0u);
  // A good state, then a bad one: the good one stays.
  ASSERT_TRUE(f.publish_until({rig_state(3, 2, 0.2)}, 1.2).has_value());
  mhd_dds_RigState zero_q = rig_state(3, 3, 0.9);
  zero_q.q_W_head_wxyz[0] = 0.0;
  const std::optional<RigState> kept = f.publish_until({zero_q}, 1.3, &DdsStateSourceStatus::dropped_invalid);
  ASSERT_TRUE(kept.has_value());
  EXPECT_DOUBLE_EQ(kept->p_W_hip_m.x(), 0.2);
  EXPECT_EQ(f.source->status().last_error, "display frame: q_W_head_wxyz has zero norm");
}

TEST(DdsStateSource, AReaderThatCannotBeMadeThrowsWithDdsReason) {
  dds::test::use_loopback_and_unique_domain(4);
  DdsStateSourceOptions o;
  o.domain_id = 233;  // past Cyclone's domain ids (0-232)
  try {
    const DdsStateSource source(o, [](const std::string&) {});
    FAIL() << "a reader on domain 233 was made";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("dds_create_participant: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace mhd::viewer
