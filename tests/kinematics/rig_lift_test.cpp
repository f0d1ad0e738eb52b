// The lift between the robot and the arm (<rig><lift .../>): read in SI units, refused at
// its file:line when its range or limits are inconsistent or the rig cannot carry it, and
// in the chain a move of the arm along world up by exactly the lift's height.
#include "kinematics/rig.h"
#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace mhd {
namespace {

const std::string kPomhiFile = std::string(MHD_SOURCE_DIR) + "/scenes/rigs/pomhi.xml";

/// The POMHI rig (mm) with `lift` on line 4; a sphere to touch.
std::string pomhi_with(const std::string& lift) {
  return "<?xml version=\"1.0\"?>\n<scene version=\"1\" unit=\"mm\">\n  <include file=\"" + kPomhiFile + "\"/>\n" +
         "  <rig>" + lift + "</rig>\n" +
         "  <object name=\"ball\"><material stiffness_N_per_m=\"500\"/><sphere radius=\"50\"/></object>\n</scene>\n";
}

std::vector<std::string> messages_of(const Result<SceneDescription>& r) {
  std::vector<std::string> out;
  for (const Diagnostic& d : r.diagnostics()) out.push_back(d.to_string());
  return out;
}

Rig rig_of(const SceneDescription& scene) {
  auto rig = Rig::from_scene(scene);
  EXPECT_TRUE(rig.ok());
  return std::move(rig).value();
}

TEST(RigLift, IsReadInSiUnitsAndRaisesTheArmAlongWorldUpByItsHeight) {
  const Result<SceneDescription> read = read_scene_string(
      pomhi_with("<lift range=\"-300 600\" max_speed=\"200\" max_acceleration=\"500\"/>"), "mem/lift.xml");
  ASSERT_TRUE(read.ok()) << testing::PrintToString(messages_of(read));
  ASSERT_TRUE(read->rig_lift);
  EXPECT_DOUBLE_EQ(read->rig_lift->min_m, -0.3);
  EXPECT_DOUBLE_EQ(read->rig_lift->max_m, 0.6);
  EXPECT_DOUBLE_EQ(read->rig_lift->max_speed_mps, 0.2);
  EXPECT_DOUBLE_EQ(read->rig_lift->max_acceleration_mps2, 0.5);
  EXPECT_EQ(read->rig_lift->where.line, 4);
  const Rig rig = rig_of(*read);
  ASSERT_TRUE(rig.lift());
  EXPECT_DOUBLE_EQ(rig.lift()->max_m, 0.6);
  // Any base pose, any joint angles: the HIP moves straight up by the height, and the
  // arm's frame does not turn (forces are rendered alike at every height).
  for (const double heading_rad : {0.0, 0.7, -2.5}) {
    const Pose X_W_robot = rig.X_W_robot_from_base(BasePose{0.4, -1.2, heading_rad});
    for (const double h_m : {-0.3, 0.25, 0.6}) {
      const Eigen::Vector3d q_rad(0.2, -0.3, 0.4);
      const Eigen::Vector3d moved = rig.p_W_hip(X_W_robot, q_rad, h_m) - rig.p_W_hip(X_W_robot, q_rad, 0.0);
      EXPECT_NEAR((moved - Eigen::Vector3d(0.0, h_m, 0.0)).norm(), 0.0, 1e-12) << heading_rad << " " << h_m;
      EXPECT_TRUE(rig.X_W_phantom(X_W_robot, h_m).linear().isApprox(rig.X_W_phantom(X_W_robot).linear(), 1e-12));
      const Eigen::Vector3d p_W = rig.p_W_hip(X_W_robot, q_rad, h_m);
      EXPECT_NEAR((rig.p_P_from_W(X_W_robot, p_W, h_m) - rig.p_P_from_W(X_W_robot, rig.p_W_hip(X_W_robot, q_rad))).norm(),
                  0.0, 1e-12);
    }
  }
}

TEST(RigLift, AtHeightZeroTheChainIsTheRigsWithoutALift) {
  const Result<SceneDescription> lifted = read_scene_string(
      pomhi_with("<lift range=\"0 600\" max_speed=\"200\" max_acceleration=\"500\"/>"), "mem/lift.xml");
  const Result<SceneDescription> fixed = read_scene_string(pomhi_with(""), "mem/fixed.xml");
  ASSERT_TRUE(lifted.ok() && fixed.ok());
  EXPECT_FALSE(fixed->rig_lift);
  const Rig a = rig_of(*lifted);
  const Rig b = rig_of(*fixed);
  EXPECT_FALSE(b.lift());
  const Pose X_W_robot = a.X_W_robot_from_base(BasePose{1.0, 0.5, 0.3});
  const Eigen::Vector3d q_rad(-0.1, 0.2, 0.1);
  EXPECT_EQ(a.p_W_hip(X_W_robot, q_rad, 0.0), b.p_W_hip(X_W_robot, q_rad));
  EXPECT_TRUE(a.X_robot_phantom(0.0).isApprox(b.X_robot_phantom(0.0), 0.0));
}

struct BadLift {
  const char* name;
  const char* lift;
  const char* says;
};

class RigLiftRefused : public ::testing::TestWithParam<BadLift> {};

TEST_P(RigLiftRefused, AtItsLine) {
  const Result<SceneDescription> read = read_scene_string(pomhi_with(GetParam().lift), "mem/lift.xml");
  ASSERT_FALSE(read.ok()) << GetParam().name;
  const std::vector<std::string> messages = messages_of(read);
  ASSERT_FALSE(messages.empty());
  EXPECT_NE(messages.front().find("mem/lift.xml:4: error: "), std::string::npos) << testing::PrintToString(messages);
  EXPECT_NE(messages.front().find(GetParam().says), std::string::npos) << testing::PrintToString(messages);
}

INSTANTIATE_TEST_SUITE_P(
    RigLift, RigLiftRefused,
    ::testing::Values(
        BadLift{"zero_outside", R"(<lift range="100 600" max_speed="200" max_acceleration="500"/>)", "MIN <= 0 <= MAX"},
        BadLift{"reversed", R"(<lift range="600 -300" max_speed="200" max_acceleration="500"/>)", "MIN <= 0 <= MAX"},
        BadLift{"no_travel", R"(<lift range="0 0" max_speed="200" max_acceleration="500"/>)", "MIN < MAX"},
        BadLift{"nan_range", R"(<lift range="nan 600" max_speed="200" max_acceleration="500"/>)", "range"},
        BadLift{"inf_range", R"(<lift range="-300 inf" max_speed="200" max_acceleration="500"/>)", "range"},
        BadLift{"three_numbers", R"(<lift range="-300 0 600" max_speed="200" max_acceleration="500"/>)", "range"},
        BadLift{"no_range", R"(<lift max_speed="200" max_acceleration="500"/>)", "range"},
        BadLift{"zero_speed", R"(<lift range="0 600" max_speed="0" max_acceleration="500"/>)", "max_speed"},
        BadLift{"negative_speed", R"(<lift range="0 600" max_speed="-1" max_acceleration="500"/>)", "max_speed"},
        BadLift{"nan_speed", R"(<lift range="0 600" max_speed="nan" max_acceleration="500"/>)", "max_speed"},
        BadLift{"inf_acceleration", R"(<lift range="0 600" max_speed="200" max_acceleration="inf"/>)",
                "max_acceleration"},
        BadLift{"tiny_acceleration", R"(<lift range="0 600" max_speed="200" max_acceleration="-1e-300"/>)",
                "max_acceleration"},
        BadLift{"unknown_attribute", R"(<lift range="0 600" max_speed="200" max_acceleration="500" axis="x"/>)",
                "axis"},
        BadLift{"two_lifts",
                R"(<lift range="0 600" max_speed="200" max_acceleration="500"/><lift range="0 600" max_speed="200" max_acceleration="500"/>)",
                "a rig has one <lift>"}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(RigLift, ADesktopRigRefusesALiftAtItsLine) {
  const std::string desk =
      "<?xml version=\"1.0\"?>\n<scene version=\"1\" unit=\"m\">\n  <rig kind=\"desktop\">\n"
      "    <frame name=\"device\" parent=\"world\" position=\"0 0.75 0\"/>\n"
      "    <lift range=\"0 0.5\" max_speed=\"0.2\" max_acceleration=\"0.5\"/>\n  </rig>\n"
      "  <object name=\"ball\"><material stiffness_N_per_m=\"500\"/><sphere radius=\"0.05\"/></object>\n</scene>\n";
  // The reader (so validate and run alike) refuses it...
  const Result<SceneDescription> read = read_scene_string(desk, "mem/desk.xml");
  ASSERT_FALSE(read.ok());
  ASSERT_EQ(messages_of(read).size(), 1u) << testing::PrintToString(messages_of(read));
  EXPECT_NE(messages_of(read)[0].find("mem/desk.xml:5: error: <lift> in a desktop rig (declared at mem/desk.xml:3)"),
            std::string::npos)
      << messages_of(read)[0];
  // ...and so does the rig, for a description built in code.
  SceneDescription scene;
  scene.rig_kind = RigKindDeclaration{RigKind::Desktop, SourceLocation{"mem/desk.xml", 3}};
  scene.rig_frames.push_back(FrameDescription{"device", "world", Pose::Identity(), SourceLocation{"mem/desk.xml", 4}});
  scene.rig_lift = LiftDescription{0.0, 0.5, 0.2, 0.5, SourceLocation{"mem/desk.xml", 5}};
  const auto rig = Rig::from_scene(scene);
  ASSERT_FALSE(rig.ok());
  ASSERT_EQ(rig.error().size(), 1u);
  EXPECT_EQ(rig.error()[0].kind, RigErrorKind::LiftOnDesktop);
  EXPECT_EQ(rig.error()[0].to_string(),
            "mem/desk.xml:5: error: a desktop rig has no base to carry a <lift>: use a mobile rig");
}

TEST(RigLift, ALiftWhoseAxisIsNotVerticalIsRefusedAtItsLine) {
  const Result<SceneDescription> read = read_scene_string(
      pomhi_with("<lift range=\"0 600\" max_speed=\"200\" max_acceleration=\"500\"/>"), "mem/lift.xml");
  ASSERT_TRUE(read.ok());
  SceneDescription scene = *read;
  // Turn the robot frame 90 degrees about its x and the base back: the base is still level
  // and on the floor, but the robot's z, the lift's axis, now lies on the floor.
  const Pose turn(Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitX()));
  for (FrameDescription& f : scene.rig_frames) {
    if (f.name == "robot") f.X_PF = f.X_PF * turn;
    if (f.name == "base" || f.name == "phantom") f.X_PF = turn.inverse() * f.X_PF;
  }
  const auto rig = Rig::from_scene(scene);
  ASSERT_FALSE(rig.ok());
  ASSERT_EQ(rig.error().size(), 1u);
  EXPECT_EQ(rig.error()[0].kind, RigErrorKind::LiftNotVertical);
  EXPECT_NE(rig.error()[0].to_string().find("mem/lift.xml:4: error: the lift moves the arm along the robot frame's z, "
                                            "which is 90 degrees from world up"),
            std::string::npos)
      << rig.error()[0].to_string();
  // The same turned frames without a lift are a good rig: only the lift needs z up.
  scene.rig_lift.reset();
  EXPECT_TRUE(Rig::from_scene(scene).ok());
}

}  // namespace
}  // namespace mhd
