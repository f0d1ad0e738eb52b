// The lift in a real `mhd run` of scenes/tall_column.xml, judged from the
// recording (the tool where the arm reported it, the lift where the base
// reported it) and from the simulated base's command log (what the base and its
// lift were last told):
//  - with the lift, the hand stays inside the arm's workspace on >= 95 % of
//  contact ticks
//    while the user crouches to 0.3 m and reaches to 1.9 m; the dual: on the
//    same scene without the lift it does not;
//  - a rig and a base that disagree about the lift are refused at the first
//  base reading,
//    and the base and the lift are left still.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "hardware_run.h"
#include "kinematics/phantom_kinematics.h"
#include "recording/csv_recording_reader.h"

namespace {

namespace fs = std::filesystem;
using mhd::test::MhdRunProcess;
using mhd::test::hardware::exit_status;
using mhd::test::hardware::expect_last_command_zero;
using mhd::test::scratch_dir;
using mhd::test::hardware::has;

using Fills = std::vector<std::pair<std::string, std::string>>;

constexpr const char *kLiftParams =
    R"(      <param name="lift" value="on"/>
      <param name="lift_min_m" value="-0.7"/>
      <param name="lift_max_m" value="0.9"/>
      <param name="lift_max_speed_mps" value="0.3"/>
      <param name="lift_max_acceleration_mps2" value="1.5"/>
)";
constexpr const char *kRigLift = R"(<lift range="-0.7 0.9" max_speed="0.3" max_acceleration="1.5"/>)";
// The user's walk in and one whole crouch-and-reach (0.3 m to 1.9 m and back at
// 0.3 m/s).
constexpr double kRunDuration_s = 14.0;

/// scenes/tall_column.xml in `dir`, its includes made absolute, the base
/// logging its commands to base.csv, then `fills`.
fs::path write_scene(const fs::path &dir, Fills fills) {
  return mhd::test::hardware::write_scene_logging_the_base(dir, "tall_column.xml", std::move(fills));
}

MhdRunProcess run(const fs::path &dir, double duration_s) {
  return MhdRunProcess({.argv = {MHD_CLI, "run", (dir / "scene.xml").string(), "--duration", std::to_string(duration_s),
                                 "-q", "--record", (dir / "run.csv").string(), "--plugin-path", MHD_SIM_PLUGIN_DIR},
                        .dir = dir});
}

struct Reach {
  std::size_t contact_ticks = 0;
  std::size_t inside = 0;  ///< contact ticks with the tool inside the arm's workspace
  double lift_min_m = 0.0, lift_max_m = 0.0;
  [[nodiscard]] double share() const { return contact_ticks == 0 ? 0.0 : double(inside) / double(contact_ticks); }
};

/// The contact ticks of the recording, and how many had the tool inside the
/// workspace: the simulated arm holds its tool on the box's faces while the
/// hand is beyond them, so a tool 2 mm inside every face is a hand the arm
/// still follows.
Reach reach_of(const fs::path &recording) {
  const auto rows = mhd::read_recording(recording);
  EXPECT_TRUE(rows.ok()) << (rows.ok() ? "" : rows.error_text());
  Reach r;
  if (!rows.ok()) return r;
  const mhd::WorkspaceBox inside = mhd::phantom_premium_1_5().workspace.shrunk(0.002);
  bool first = true;
  for (const mhd::RecordingRow &row : rows.value()) {
    if (std::isfinite(row.lift_m)) {
      r.lift_min_m = first ? row.lift_m : std::min(r.lift_min_m, row.lift_m);
      r.lift_max_m = first ? row.lift_m : std::max(r.lift_max_m, row.lift_m);
      first = false;
    }
    if (row.contact == 0) continue;
    ++r.contact_ticks;
    if (inside.contains({row.p_D_tool_m[0], row.p_D_tool_m[1], row.p_D_tool_m[2]})) ++r.inside;
  }
  return r;
}

TEST(TallColumn, TheLiftKeepsACrouchingAndReachingHandInsideTheArmsWorkspace) {
  const fs::path dir = scratch_dir("tall_column", "lift");
  write_scene(dir, {});
  MhdRunProcess mhd = run(dir, kRunDuration_s);
  ASSERT_EQ(exit_status(mhd, std::chrono::seconds(60)), 0) << mhd.output();
  const Reach r = reach_of(dir / "run.csv");
  std::printf("with the lift: hand inside the arm's workspace on %.1f %% of %zu contact ticks; lift %.2f..%.2f m\n",
              100.0 * r.share(), r.contact_ticks, r.lift_min_m, r.lift_max_m);
  EXPECT_GT(r.contact_ticks, 5000u) << "the hand hardly touched the column\n" << mhd.output();
  EXPECT_GE(r.share(), 0.95) << mhd.output();
  // It is the lift that did it: it went down for the crouch and up for the
  // reach.
  EXPECT_LT(r.lift_min_m, -0.5);
  EXPECT_GT(r.lift_max_m, 0.7);
  expect_last_command_zero(dir / "base.csv",
                           mhd.output());  // base and lift left still
}

TEST(TallColumn, WithoutTheLiftTheArmLosesTheHand) {
  const fs::path dir = scratch_dir("tall_column", "no_lift");
  write_scene(dir, {{kRigLift, ""}, {kLiftParams, ""}});
  MhdRunProcess mhd = run(dir, kRunDuration_s);
  ASSERT_EQ(exit_status(mhd, std::chrono::seconds(60)), 0) << mhd.output();
  const Reach r = reach_of(dir / "run.csv");
  std::printf("without the lift: hand inside the arm's workspace on %.1f %% of %zu contact ticks\n", 100.0 * r.share(),
              r.contact_ticks);
  EXPECT_GT(r.contact_ticks, 1000u) << mhd.output();
  EXPECT_LT(r.share(), 0.6) << mhd.output();
  EXPECT_EQ(r.lift_min_m, 0.0);
  EXPECT_EQ(r.lift_max_m, 0.0);
}

/// The scene with `taken_out` removed ends at the first base reading, saying `why`, with
/// the base and its lift told to stand still last.
void expect_refused(const std::string &name, const std::string &taken_out, const std::string &why) {
  const fs::path dir = scratch_dir("tall_column", name);
  write_scene(dir, {{taken_out, ""}});
  MhdRunProcess mhd = run(dir, 5.0);
  EXPECT_EQ(exit_status(mhd), mhd::test::hardware::kExitFault) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), why)) << mhd.output();
  expect_last_command_zero(dir / "base.csv", mhd.output());
}

TEST(TallColumn, ARigWithALiftOnABaseWithoutOneIsRefused) {
  expect_refused("base_without_lift", kLiftParams, "the rig has a <lift>, but this base reports none");
}

TEST(TallColumn, ALiftStandingOutsideTheRigsRangeEndsTheRun) {
  // The base's own lift reaches 2 m and stands at 1.5 m; the rig says 0.9 m at most.
  const fs::path dir = scratch_dir("tall_column", "lift_out_of_range");
  write_scene(dir, {{R"(<param name="lift_max_m" value="0.9"/>)",
                     R"(<param name="lift_max_m" value="2"/><param name="lift_start_m" value="1.5"/>)"}});
  MhdRunProcess mhd = run(dir, 5.0);
  EXPECT_EQ(exit_status(mhd), mhd::test::hardware::kExitFault) << mhd.output();
  EXPECT_TRUE(has(mhd.output(), "base_read returned the lift at 1.5 m, outside the rig's lift range [-0.7, 0.9] m"))
      << mhd.output();
  expect_last_command_zero(dir / "base.csv", mhd.output());
}

TEST(TallColumn, ABaseWithALiftOnARigWithoutOneIsRefused) {
  expect_refused("rig_without_lift", kRigLift, "this base reports a lift, but the rig has no <lift>");
}

}  // namespace
