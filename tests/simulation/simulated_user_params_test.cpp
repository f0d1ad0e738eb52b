// <simulated_user> params into a SimulatedUserConfig, each problem at its line.
#include "simulation_config/simulated_user_params.h"

#include <gtest/gtest.h>

#include <numbers>

namespace mhd::simulation {
namespace {

ParamBlock block(std::initializer_list<std::pair<const char*, const char*>> params) {
  ParamBlock b;
  b.where = {"u.xml", 5};
  int line = 6;
  for (const auto& [name, value] : params) {
    b.params.emplace(name, value);
    b.param_where.emplace(name, SourceLocation{"u.xml", line++});
  }
  return b;
}

TEST(SimulatedUserParams, FillsTheConfiguration) {
  const auto r = simulated_user_config_from(block({{"path", "0 1 0.5; 2 1 0.5"}, {"loop_path", "true"}, {"seed", "9"},
                                                   {"start_heading_deg", "90"}, {"hand_height_m", "0.95"},
                                                   {"gaze_target_m", "1 1.5 -2"}}));
  ASSERT_TRUE(r.ok()) << r.error_text();
  const SimulatedUserConfig& c = *r;
  ASSERT_EQ(c.path.size(), 2u);
  EXPECT_DOUBLE_EQ(c.path[1].x_m, 2.0);
  EXPECT_TRUE(c.loop_path);
  EXPECT_EQ(c.seed, 9u);
  EXPECT_NEAR(c.start.heading_rad, std::numbers::pi / 2.0, 1e-15);
  EXPECT_DOUBLE_EQ(c.hand_height_m, 0.95);
  ASSERT_TRUE(c.gaze_target_W);
  EXPECT_DOUBLE_EQ(c.gaze_target_W->z(), -2.0);
}

TEST(SimulatedUserParams, ReadsAHandHeightSweepAndRefusesAMalformedOne) {
  const auto r = simulated_user_config_from(block(
      {{"hand_height_sweep_m", "0.3 1.9"}, {"hand_height_sweep_speed_mps", "0.4"}, {"hand_height_sweep_hold_s", "0"}}));
  ASSERT_TRUE(r.ok()) << r.error_text();
  ASSERT_TRUE(r->hand_height_sweep);
  EXPECT_DOUBLE_EQ(r->hand_height_sweep->low_m, 0.3);
  EXPECT_DOUBLE_EQ(r->hand_height_sweep->high_m, 1.9);
  EXPECT_DOUBLE_EQ(r->hand_height_sweep->speed_mps, 0.4);
  EXPECT_DOUBLE_EQ(r->hand_height_sweep->hold_s, 0.0);
  EXPECT_FALSE(simulated_user_config_from(block({})).value().hand_height_sweep);
  for (const char* bad : {"0.3", "0.3 1.9 2", "low high", "nan 1", "1.9 0.3"}) {
    const auto refused = simulated_user_config_from(block({{"hand_height_sweep_m", bad}}));
    EXPECT_FALSE(refused.ok()) << bad;
    if (!refused.ok()) {
      EXPECT_NE(refused.error_text().find("u.xml:"), std::string::npos) << refused.error_text();
    }
  }
}

TEST(SimulatedUserParams, NamesEachBadParamAtItsLine) {
  const auto r = simulated_user_config_from(block({{"path", "0 1"}, {"hand_reach_m", "-1"}, {"walk_speed", "1"}}));
  EXPECT_FALSE(r.ok());
  std::vector<std::string> messages;
  for (const auto& d : r.error()) messages.push_back(d.to_string());
  EXPECT_EQ(messages, (std::vector<std::string>{
                          "u.xml:6: error: param 'path' in <simulated_user>: waypoint 1: expected 'x z speed_mps', got '0 1'",
                          "u.xml:7: error: param 'hand_reach_m' in <simulated_user> must be a non-negative number, got '-1'",
                          "u.xml:8: error: unknown param 'walk_speed' in <simulated_user> (known: area_half_size_m, "
                          "eye_height_m, gaze_target_m, hand_height_m, hand_height_sweep_hold_s, hand_height_sweep_m, "
                        "hand_height_sweep_speed_mps, hand_motion_amplitude_m, hand_reach_m, loop_path, "
                          "max_speed_mps, path, seed, side_step_probability, side_step_speed_max_mps, stand_probability, "
                          "start_heading_deg, start_x_m, start_z_m, walk_speed_max_mps, walk_speed_min_mps)"}));
}

TEST(SimulatedUserParams, AConfigurationTheUserRefusesIsAnErrorAtTheBlock) {
  // Each value is fine alone; a path faster than the maximum speed is not.
  const auto r = simulated_user_config_from(block({{"path", "0 0 1; 1 0 2"}, {"max_speed_mps", "1.5"}}));
  EXPECT_FALSE(r.ok());
  ASSERT_EQ(r.error().size(), 1u);
  EXPECT_EQ(r.error()[0].where.line, 5);
  EXPECT_NE(r.error()[0].message.find("<simulated_user>: "), std::string::npos);
}

}  // namespace
}  // namespace mhd::simulation
