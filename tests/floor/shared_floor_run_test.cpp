// scenes/shared_floor.xml in a real `mhd run`: the simulated tracker reports another rig
// (its user and its base, standing in this base's way) beside this rig's own sensors.
// Judged from outside: the base's distance to the other rig's base from the recording,
// and what the base was told from its command log.
//  - seen (<server other_rig_sensors="2:3">), the base never comes within 0.45 m of it;
//    the dual: blind to it (no other_rig_sensors), the same run drives into it;
//  - the other rig's data lost for 2 s: the base is told to stand still once it is
//    0.3 s old, and to move again once it is back (the dual);
//  - a declared rig the tracker never reports: the base is never told to move.
#include "hardware_run.h"
#include "recording/csv_recording_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;
using mhd::test::MhdRunProcess;
using mhd::test::hardware::exit_status;
using mhd::test::hardware::expect_last_command_zero;
using mhd::test::scratch_dir;
using mhd::test::hardware::rows_of;
using mhd::test::hardware::write_scene_logging_the_base;

using Fills = std::vector<std::pair<std::string, std::string>>;

constexpr double kOtherBaseX_m = 0.6;  // scenes/shared_floor.xml's bystander base
constexpr double kOtherBaseZ_m = -0.35;
constexpr double kBaseContact_m = 0.45;  // two robot radii
constexpr const char* kSeen = R"(<param name="other_rig_sensors" value="2:3"/>)";

/// scenes/shared_floor.xml with `fills`, the base logging to base.csv, run for `duration_s`.
MhdRunProcess run(const fs::path& dir, Fills fills, double duration_s) {
  write_scene_logging_the_base(dir, "shared_floor.xml", std::move(fills));
  return MhdRunProcess({.argv = {MHD_CLI, "run", (dir / "scene.xml").string(), "--duration",
                                 std::to_string(duration_s), "-q", "--record", (dir / "run.csv").string(),
                                 "--plugin-path", MHD_SIM_PLUGIN_DIR},
                        .dir = dir});
}

/// The least distance between this rig's base (as the recording has it) and the other's.
double least_distance_to_other_base_m(const fs::path& recording) {
  const auto rows = mhd::read_recording(recording);
  EXPECT_TRUE(rows.ok()) << (rows.ok() ? "" : rows.error_text());
  double least = std::numeric_limits<double>::infinity();
  if (!rows.ok()) return least;
  for (const mhd::RecordingRow& row : rows.value()) {
    if (!std::isfinite(row.base_x_m) || !std::isfinite(row.base_z_m)) continue;
    least = std::min(least, std::hypot(row.base_x_m - kOtherBaseX_m, row.base_z_m - kOtherBaseZ_m));
  }
  return least;
}

/// Commands of the base's log within [from_s, to_s): how many, and how many moved it.
std::pair<int, int> commands_between(const fs::path& log, double from_s, double to_s) {
  int all = 0, moving = 0;
  for (const auto& row : rows_of(log, "command")) {
    if (row.t_s < from_s || row.t_s >= to_s) continue;
    ++all;
    if (!row.is_zero()) ++moving;
  }
  return {all, moving};
}

TEST(SharedFloorRun, TheBaseNeverComesWithinContactOfTheOtherRigsBase) {
  const fs::path dir = scratch_dir("shared_floor", "seen");
  MhdRunProcess mhd = run(dir, {}, 8.0);
  ASSERT_EQ(exit_status(mhd, std::chrono::seconds(60)), 0) << mhd.output();
  const double least = least_distance_to_other_base_m(dir / "run.csv");
  std::printf("seeing the other rig: least distance between the bases %.3f m\n", least);
  EXPECT_GE(least, kBaseContact_m);
  EXPECT_LT(least, kBaseContact_m + 0.2);  // it did come near: the other base was in its way
  EXPECT_GT(commands_between(dir / "base.csv", 0.0, 8.0).second, 10);  // and it followed the hand
  expect_last_command_zero(dir / "base.csv", mhd.output());
}

TEST(SharedFloorRun, BlindToTheOtherRigTheBaseDrivesIntoIt) {
  const fs::path dir = scratch_dir("shared_floor", "blind");
  MhdRunProcess mhd = run(dir, {{kSeen, ""}}, 8.0);
  ASSERT_EQ(exit_status(mhd, std::chrono::seconds(60)), 0) << mhd.output();
  const double least = least_distance_to_other_base_m(dir / "run.csv");
  std::printf("blind to the other rig: least distance between the bases %.3f m\n", least);
  EXPECT_LT(least, kBaseContact_m);
}

TEST(SharedFloorRun, LosingTheOtherRigsDataHoldsTheBaseUntilItIsBack) {
  const fs::path dir = scratch_dir("shared_floor", "dropout");
  MhdRunProcess mhd = run(dir,
                          {{R"(<param name="seed" value="7"/>)",
                            R"(<param name="seed" value="7"/><param name="dropout_sensor" value="bystander_base"/>)"
                            R"(<param name="dropout_start_s" value="1.5"/><param name="dropout_duration_s" value="2"/>)"}},
                          6.0);
  ASSERT_EQ(exit_status(mhd, std::chrono::seconds(60)), 0) << mhd.output();
  // Stale from 1.8 s (0.3 s after the last sample): a planner tick (0.1 s) later at most,
  // every command is a stop until the data is back at 3.5 s.
  const auto [held, held_moving] = commands_between(dir / "base.csv", 2.0, 3.5);
  EXPECT_GT(held, 10);
  EXPECT_EQ(held_moving, 0) << mhd.output();
  const auto [before, before_moving] = commands_between(dir / "base.csv", 0.0, 1.5);
  const auto [after, after_moving] = commands_between(dir / "base.csv", 3.8, 6.0);
  EXPECT_GT(before_moving, 5);  // dual: it moved before, and moves again after
  EXPECT_GT(after_moving, 5);
  EXPECT_GE(least_distance_to_other_base_m(dir / "run.csv"), kBaseContact_m);
}

TEST(SharedFloorRun, ARigTheTrackerNeverReportsHoldsTheBaseAllRun) {
  const fs::path dir = scratch_dir("shared_floor", "never_seen");
  MhdRunProcess mhd = run(dir, {{kSeen, R"(<param name="other_rig_sensors" value="7:8"/>)"}}, 3.0);
  ASSERT_EQ(exit_status(mhd, std::chrono::seconds(60)), 0) << mhd.output();
  const auto [all, moving] = commands_between(dir / "base.csv", 0.0, 10.0);
  EXPECT_GT(all, 10);
  EXPECT_EQ(moving, 0) << mhd.output();
}

}  // namespace
