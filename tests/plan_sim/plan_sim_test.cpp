#include "plan_sim.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <numbers>

namespace mhd::plan_sim {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(PlanSim, StandingStillIsFollowedAtOnce) {
  const CaseFigures r = simulate_case(PlannerKind::Seed, PlannerSettings{}, MapSpec{}, {0.0, 0.0});
  EXPECT_TRUE(r.followed);
  EXPECT_EQ(r.time_s, 0.0);
}

TEST(PlanSim, StepBackOfTenCentimetres) {
  // The user steps back to (-0.1, 0): the hand is 0.325 m along B's +z; it is back inside
  // (z <= 0.2913) once the base has come 0.0337 m nearer.
  // Seed: 0.1 m from the target, 0.5 * 0.1 / 0.2 = 0.25 m/s: 0.025 m in the first tick;
  // then 0.075 m away, 0.1875 m/s: 0.0087 m more in 0.046 s -> checks every 10 ms: 0.15 s.
  // Predictive: 0.5 m/s: 0.0337 / 0.5 = 0.067 s -> 0.07 s.
  const CaseFigures seed = simulate_case(PlannerKind::Seed, PlannerSettings{}, MapSpec{}, {-0.1, 0.0});
  const CaseFigures pred = simulate_case(PlannerKind::Predictive, PlannerSettings{}, MapSpec{}, {-0.1, 0.0});
  ASSERT_TRUE(seed.followed);
  ASSERT_TRUE(pred.followed);
  EXPECT_NEAR(seed.time_s, 0.15, 1e-9);
  EXPECT_NEAR(pred.time_s, 0.07, 1e-9);
}

TEST(PlanSim, TooFarForTheSlowestBase) {
  PlannerSettings slow;
  slow.max_linear_speed_mps = 0.1;
  // 1 m in 1 s at 0.1 m/s: impossible.
  EXPECT_FALSE(simulate_case(PlannerKind::Seed, slow, MapSpec{}, {-1.0, 0.0}).followed);
  EXPECT_FALSE(simulate_case(PlannerKind::Predictive, slow, MapSpec{}, {-1.0, 0.0}).followed);
}

TEST(PlanSim, MapsAreSymmetricSafeAndThePredictivePlannerFollowsMore) {
  MapSpec spec;
  spec.cell_m = 0.05;  // coarse: 60 x 60 over +-1.5 m
  const FollowMap seed = simulate_map(PlannerKind::Seed, PlannerSettings{}, spec);
  const FollowMap pred = simulate_map(PlannerKind::Predictive, PlannerSettings{}, spec);
  ASSERT_EQ(seed.cells_per_side, 60);
  EXPECT_GT(seed.followed_cells, 0);
  EXPECT_GT(pred.followed_cells, seed.followed_cells);
  EXPECT_EQ(seed.base_entries, 0);
  EXPECT_EQ(pred.base_entries, 0);
  // The start is symmetric about z = 0 (user facing +x, base on the x axis).
  const int n = seed.cells_per_side;
  int asymmetric = 0;
  for (int iz = 0; iz < n; ++iz)
    for (int ix = 0; ix < n; ++ix)
      asymmetric += seed.followed[static_cast<std::size_t>(iz * n + ix)] !=
                    seed.followed[static_cast<std::size_t>((n - 1 - iz) * n + ix)];
  EXPECT_LE(asymmetric, n / 10);  // ties on the symmetry line may break either way
  EXPECT_DOUBLE_EQ(seed.followed_area_m2(), seed.followed_cells * 0.0025);
}

TEST(PlanSim, TableFormats) {
  const std::vector<TableRow> rows{{PlannerKind::Seed, 0.0, 0.5, 90.0 * kDeg, 1.0, 400, 0},
                                   {PlannerKind::Predictive, 0.0, 0.5, 90.0 * kDeg, 1.5, 600, 0}};
  EXPECT_EQ(table_csv(rows),
            "planner,facing_change_deg,max_linear_speed_mps,max_angular_speed_degps,followed_cells,followed_area_m2,"
            "base_entries\n"
            "seed,0,0.50,90,400,1.0000,0\n"
            "predictive,0,0.50,90,600,1.5000,0\n");
  const std::string text = table_text(rows);
  EXPECT_NE(text.find("facing change 0 deg"), std::string::npos);
  EXPECT_NE(text.find("1.000 1.500  1.50"), std::string::npos) << text;
}

TEST(PlanSim, MapCsvDescribesTheSceneAndListsFollowedCells) {
  MapSpec spec;
  spec.cell_m = 0.1;
  const PlannerSettings settings;
  const FollowMap map = simulate_map(PlannerKind::Predictive, settings, spec);
  ASSERT_GT(map.followed_cells, 0);
  const std::string csv = map_csv(map, PlannerKind::Predictive, settings, spec);
  EXPECT_EQ(csv.rfind("# mhd plan-sim follow map", 0), 0u);
  EXPECT_NE(csv.find("\n# planner=predictive\n"), std::string::npos);
  EXPECT_NE(csv.find("\n# cell_m=0.1\n"), std::string::npos);
  EXPECT_NE(csv.find("\n# base_start_x_m=0.675\n"), std::string::npos) << csv;
  const auto header = csv.find("\nx_m,z_m,follow_time_s\n");
  ASSERT_NE(header, std::string::npos);
  const std::string body = csv.substr(header + 23);
  EXPECT_EQ(static_cast<int>(std::count(body.begin(), body.end(), '\n')), map.followed_cells);
}

}  // namespace
}  // namespace mhd::plan_sim
