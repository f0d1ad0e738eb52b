#include "scene_fixture.h"
#include "verification/stroke_run.h"

#include <gtest/gtest.h>

namespace mhd::test::stroke_run_test {

// tests/data/scenes/valid/minimal.xml: one sphere of radius 0.1 m at the origin.
constexpr const char* kBallScene = "tests/data/scenes/valid/minimal.xml";

class StrokeRunTest : public SceneFixture {};

// time_strokes() is how a mesh too large for the oracle gets its tick times: it must step
// the proxy exactly as the judged run does (same ticks, same contacts, same forces), or its
// figures would not stand beside the judged ones.
TEST_F(StrokeRunTest, TimingAloneStepsTheProxyAsTheJudgedRunDoes) {
  ASSERT_NO_FATAL_FAILURE(load(kBallScene));
  const StrokeSet strokes = anchor_strokes(8128, 6);
  const StrokeRunReport judged = run_strokes(scene(), oracle(), strokes, 1000.0);
  const StrokeRunReport timed = time_strokes(scene(), strokes, 1000.0);
  ASSERT_GT(judged.contact_ticks, 0U);
  EXPECT_EQ(judged.pop_throughs, 0U);
  EXPECT_EQ(judged.follow_failures, 0U);
  EXPECT_EQ(timed.strokes, judged.strokes);
  EXPECT_EQ(timed.ticks, judged.ticks);
  EXPECT_EQ(timed.contact_ticks, judged.contact_ticks);
  EXPECT_EQ(timed.contact_updates.count, judged.contact_ticks);
  EXPECT_EQ(timed.all_updates.count, judged.ticks);
  EXPECT_EQ(timed.look_ahead_updates.count, judged.ticks);
  EXPECT_EQ(timed.max_force_N, judged.max_force_N);
  EXPECT_EQ(timed.mean_contact_force_N, judged.mean_contact_force_N);
  EXPECT_EQ(timed.max_sweeps, judged.max_sweeps);
  // Without the look-ahead nothing is timed between ticks.
  EXPECT_EQ(time_strokes(scene(), strokes, 1000.0, false).look_ahead_updates.count, 0U);
}

// Strokes joined into one continuous run are still counted one by one, and each is judged
// at the tick it begins; a run of separate strokes resets the proxy at each, so none of
// them can begin behind a surface.
TEST_F(StrokeRunTest, EveryStrokeOfAContinuousRunIsCountedAsBegun) {
  ASSERT_NO_FATAL_FAILURE(load(kBallScene));
  const StrokeSet separate = anchor_strokes(8129, 5);
  StrokeSet joined;
  joined.strokes.emplace_back();
  for (const Stroke& s : separate.strokes) {
    joined.strokes.front().stroke_starts.push_back(joined.strokes.front().p_W_hip.size());
    joined.strokes.front().p_W_hip.insert(joined.strokes.front().p_W_hip.end(), s.p_W_hip.begin(), s.p_W_hip.end());
  }
  const StrokeRunReport apart = run_strokes(scene(), oracle(), separate, 1000.0);
  EXPECT_EQ(apart.strokes, 5U);
  EXPECT_EQ(apart.strokes_begun, 5U);
  EXPECT_EQ(apart.strokes_starting_behind, 0U);
  const StrokeRunReport together = run_strokes(scene(), oracle(), joined, 1000.0);
  EXPECT_EQ(together.strokes, 1U);
  EXPECT_EQ(together.strokes_begun, 5U);
  EXPECT_EQ(together.ticks, apart.ticks);
  EXPECT_LE(together.strokes_starting_behind, together.held_ticks);
}

}  // namespace mhd::test::stroke_run_test
