// <motion> on an object: what the reader makes of keyframes and twists (in the scene's
// unit), and the exact message, at file:line, for each bad motion; good motions are
// never refused.

#include "scene_test_support.h"
#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>

#include <numbers>
#include <string>
#include <vector>

namespace mhd {
namespace {

using test::kOneBoxFile;
using test::one_box_error;
using test::one_box_errors;
using test::one_box_scene;
using test::to_strings;
using Lines = std::vector<std::string>;

TEST(MotionReader, KeyframesInTheScenesUnitStartTheObjectAtTheFirstKey) {
  const Result<SceneDescription> r = read_scene_string(one_box_scene("    <motion repeat=\"pingpong\">\n"
                                                         "      <key t_s=\"0\" position=\"0 1000 0\"/>\n"
                                                         "      <key t_s=\"2\" position=\"400 1000 0\" rpy_deg=\"0 90 0\"/>\n"
                                                         "    </motion>\n",
                                                         "mm"),
                                              kOneBoxFile);
  ASSERT_TRUE(r.ok()) << ::testing::PrintToString(to_strings(r.diagnostics()));
  const ObjectDescription& o = r->objects[0];
  ASSERT_TRUE(o.motion);
  EXPECT_LT((o.X_WO.translation() - Eigen::Vector3d(0, 1, 0)).norm(), 1e-12);
  EXPECT_NEAR(o.motion->max_speed_mps(), 0.2, 1e-12);
  EXPECT_NEAR(o.motion->max_rate_radps(), std::numbers::pi / 4, 1e-12);
  // Played back after the end.
  EXPECT_LT((o.motion->X_WO_at(3.0).translation() - Eigen::Vector3d(0.2, 1, 0)).norm(), 1e-12);
}

TEST(MotionReader, ATwistStartsFromThePose) {
  const Result<SceneDescription> r = read_scene_string(
      one_box_scene("    <pose position=\"0 900 0\"/>\n"
                 "    <motion velocity=\"100 0 0\" angular_velocity_deg_s=\"0 180 0\"/>\n",
                 "mm"),
      kOneBoxFile);
  ASSERT_TRUE(r.ok()) << ::testing::PrintToString(to_strings(r.diagnostics()));
  const ObjectDescription& o = r->objects[0];
  ASSERT_TRUE(o.motion);
  EXPECT_LT((o.motion->X_WO_at(1.0).translation() - Eigen::Vector3d(0.1, 0.9, 0)).norm(), 1e-12);
  EXPECT_NEAR(o.motion->max_rate_radps(), std::numbers::pi, 1e-12);
  EXPECT_FALSE(read_scene_string(one_box_scene(""), kOneBoxFile)->objects[0].motion);  // still objects stay still
}

TEST(MotionReader, BadMotionsAreRefusedAtTheirLine) {
  EXPECT_EQ(one_box_errors("    <motion/>\n"),
            Lines{one_box_error(3, "<motion> needs <key> children or a velocity / angular_velocity_deg_s")});
  EXPECT_EQ(one_box_errors("    <motion velocity=\"0 0 1\"><key t_s=\"0\"/></motion>\n"),
            Lines{one_box_error(3, "<motion> is keyframed (<key>, repeat) or a twist (velocity, angular_velocity_deg_s), not both")});
  EXPECT_EQ(one_box_errors("    <pose position=\"0 1 0\"/>\n"
                      "    <motion><key t_s=\"0\"/><key t_s=\"1\"/></motion>\n"),
            Lines{one_box_error(4, "an object with keyframed <motion> takes its pose from its keys: remove its <pose>")});
  EXPECT_EQ(one_box_errors("    <motion>\n"
                      "      <key t_s=\"0\"/>\n"
                      "      <key t_s=\"0\" position=\"0.1 0 0\"/>\n"
                      "    </motion>\n"),
            Lines{one_box_error(5, "motion key 2: time must be later than the key before")});
  EXPECT_EQ(one_box_errors("    <motion repeat=\"loop\">\n"
                      "      <key t_s=\"0\"/>\n"
                      "      <key t_s=\"1\" position=\"0.1 0 0\"/>\n"
                      "    </motion>\n"),
            Lines{one_box_error(5, "motion key 2: a looping motion must end at the pose it starts from (or use pingpong)")});
  EXPECT_EQ(one_box_errors("    <motion repeat=\"bounce\"><key t_s=\"0\"/><key t_s=\"1\"/></motion>\n"),
            Lines{one_box_error(3, "attribute 'repeat' on <motion> must be hold, loop or pingpong, got 'bounce'")});
  EXPECT_EQ(one_box_errors("    <motion><key t_s=\"0\"/><frame/></motion>\n"),
            Lines{one_box_error(3, "unknown element <frame> in <motion> (expected <key>)")});
  EXPECT_EQ(one_box_errors("    <motion velocity=\"3 0 0\"/>\n"),
            Lines{one_box_error(3, "<motion> moves the object at up to 3 m/s; at most 2 m/s can be rendered")});
  EXPECT_EQ(one_box_errors("    <motion angular_velocity_deg_s=\"0 1000 0\"/>\n"),
            Lines{one_box_error(3, "<motion> turns the object at up to 1000 deg/s; at most 720 deg/s can be rendered")});
  EXPECT_EQ(one_box_errors("    <motion velocity=\"0 0 1\"/>\n    <motion velocity=\"0 0 1\"/>\n"),
            Lines{one_box_error(4, "object 'o' has more than one <motion> (the first is at line 3)")});
  const Lines missing_time = one_box_errors("    <motion><key position=\"0 0 0\"/><key t_s=\"1\"/></motion>\n");
  ASSERT_EQ(missing_time.size(), 1u);
  EXPECT_NE(missing_time[0].find("t_s"), std::string::npos) << missing_time[0];
  // The good half: the limits themselves are accepted.
  EXPECT_TRUE(read_scene_string(one_box_scene("    <motion velocity=\"2 0 0\" angular_velocity_deg_s=\"0 720 0\"/>\n"), kOneBoxFile).ok());
}

}  // namespace
}  // namespace mhd
