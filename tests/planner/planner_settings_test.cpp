#include "planner/planner_settings.h"

#include "kinematics/rig.h"
#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>

namespace mhd {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

TEST(PlannerSettings, DefaultsAreValid) {
  EXPECT_TRUE(validate(PlannerSettings{}).empty());
  EXPECT_DOUBLE_EQ(PlannerSettings{}.target_distance_m(), 0.675);
  EXPECT_DOUBLE_EQ(PlannerSettings{}.collision_radius_m(), 0.475);
}

TEST(PlannerSettings, ReadsEitherUnit) {
  const auto p = planner_settings_from_map({{"max_linear_speed_mps", "0.2"},
                                                            {"max_angular_speed_degps", "90"},
                                                            {"step_angle_deg", "45"},
                                                            {"stop_interval_mm", "20"},
                                                            {"arm_length_m", " 0.5 "},
                                                            {"command_period_ms", "50"}});
  ASSERT_TRUE(p.ok()) << p.error_text();
  EXPECT_DOUBLE_EQ(p->max_linear_speed_mps, 0.2);
  EXPECT_DOUBLE_EQ(p->max_angular_speed_radps, 90.0 * kRadPerDeg);
  EXPECT_DOUBLE_EQ(p->step_angle_rad, 45.0 * kRadPerDeg);
  EXPECT_DOUBLE_EQ(p->stop_interval_m, 0.02);
  EXPECT_DOUBLE_EQ(p->arm_length_m, 0.5);
  EXPECT_DOUBLE_EQ(p->command_period_s, 0.05);
}

TEST(PlannerSettings, ReportsEveryBadEntry) {
  const auto p =
      planner_settings_from_map({{"max_speed", "1"}, {"stop_interval_m", "abc"}, {"arm_length_m", "0.5x"}});
  ASSERT_EQ(p.error().size(), 3u);
  EXPECT_EQ(p.error()[0], "planner setting 'arm_length_m': '0.5x' is not a number");
  EXPECT_TRUE(p.error()[1].starts_with("unknown planner setting 'max_speed' (known: arm_length_m|mm, "));
  EXPECT_EQ(p.error()[2], "planner setting 'stop_interval_m': 'abc' is not a number");
}

TEST(PlannerSettings, ValidationNamesTheSetting) {
  const auto angle = planner_settings_from_map({{"step_angle_deg", "120"}});
  ASSERT_EQ(angle.error().size(), 1u);
  EXPECT_EQ(angle.error()[0], "step_angle_deg must be in (0, 90], got 120.000000");
  const auto speed = planner_settings_from_map({{"max_linear_speed_mps", "-1"}});
  ASSERT_EQ(speed.error().size(), 1u);
  EXPECT_EQ(speed.error()[0], "max_linear_speed_mps must be > 0, got -1.000000");
  // Robot 0.225 + human 0.5 + margin 0.05 > d' = 0.675: the target would be in the cylinder.
  const auto overlap = planner_settings_from_map({{"human_radius_m", "0.5"}});
  ASSERT_EQ(overlap.error().size(), 1u);
  EXPECT_TRUE(overlap.error()[0].starts_with("robot_radius_m + human_radius_m + safety_margin_m"));
}

TEST(PlannerSettings, PlannerKindNames) {
  PlannerKind kind = PlannerKind::Seed;
  EXPECT_TRUE(parse_planner_kind("predictive", kind));
  EXPECT_EQ(kind, PlannerKind::Predictive);
  EXPECT_FALSE(parse_planner_kind("Predictive", kind));
  EXPECT_EQ(to_string(PlannerKind::Seed), "seed");
}

TEST(PlannerSettings, DefaultUsableBoxIsPomhisProjection) {
  // PHANToM frame at (-1.6, 870, 235.8) mm in B with B's axes; usable box in P:
  // x +-160.5, z -75.5..55.5 mm: in B x -162.1..158.9, z 160.3..291.3 mm.
  const Result<SceneDescription> read = read_scene_file(std::filesystem::path(MHD_SOURCE_DIR) / "scenes/rigs/pomhi.xml");
  ASSERT_TRUE(read.ok());
  const Result<Rig, std::vector<RigError>> rig = Rig::from_scene(*read);
  ASSERT_TRUE(rig.ok());
  const PlanarBox box = usable_box_in_base(*rig);
  const PlanarBox def = PlannerSettings{}.usable_B;
  EXPECT_NEAR(box.x_min_m, -0.1621, 1e-6);
  EXPECT_NEAR(box.x_max_m, 0.1589, 1e-6);
  EXPECT_NEAR(box.z_min_m, 0.1603, 1e-6);
  EXPECT_NEAR(box.z_max_m, 0.2913, 1e-6);
  EXPECT_NEAR(def.x_min_m, box.x_min_m, 1e-6);
  EXPECT_NEAR(def.z_max_m, box.z_max_m, 1e-6);
}

}  // namespace
}  // namespace mhd
