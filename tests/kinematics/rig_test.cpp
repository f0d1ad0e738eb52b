// The rig (world -> is900 -> base_sensor -> robot -> phantom -> tool) read from
// scenes/rigs/pomhi.xml, checked against the thesis: eq. 4.1-4.4, the closed form of
// ch. 4.3 (re-derived; its constants and typos), the calibrated form of ch. 4.4, the
// Jacobian of ch. 5.1-5.2; and the planar base path, torques and build errors.

#include "kinematics/rig.h"

#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>

namespace mhd {
namespace {

constexpr double kHalfTurn = std::numbers::pi;
constexpr double kRadPerDeg = kHalfTurn / 180.0;
constexpr double L = 4191.0 / 20.0;  // the thesis's l1 = l2 in mm

const std::filesystem::path kPomhi = std::filesystem::path(MHD_SOURCE_DIR) / "scenes/rigs/pomhi.xml";

Pose homogeneous_mm(const Eigen::Matrix3d& R, const Eigen::Vector3d& t_mm) {
  Pose X = Pose::Identity();
  X.linear() = R;
  X.translation() = t_mm / 1000.0;
  return X;
}

Eigen::Matrix3d Rz(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }
Eigen::Matrix3d Ry(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).toRotationMatrix(); }
Eigen::Matrix3d Rx(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()).toRotationMatrix(); }

// The IS-900 measurement of the base station at yaw phi and position S (mm).
Pose sensor_reading(double phi, const Eigen::Vector3d& S_mm) { return homogeneous_mm(Rz(phi) * Rx(kHalfTurn), S_mm); }

Rig pomhi_rig() {
  const Result<SceneDescription> read = read_scene_file(kPomhi);
  EXPECT_TRUE(read.ok());
  Result<Rig, std::vector<RigError>> built = Rig::from_scene(read.value_or(SceneDescription{}));
  EXPECT_TRUE(built.ok());
  return *built;
}

FrameDescription frame(std::string name, std::string parent, const Eigen::Vector3d& p_mm,
                       const Eigen::Vector3d& rpy_deg, int line = 0) {
  FrameDescription f;
  f.name = std::move(name);
  f.parent = std::move(parent);
  f.X_PF = pose_from_xyz_rpy(p_mm / 1000.0, rpy_deg * kRadPerDeg);
  f.where = SourceLocation{"scene.xml", line};
  return f;
}

// The rig with the offsets as parameters (ch. 4.4.2), in the thesis's frames and mm: the
// robot at SR in the thesis's sensor frame (whose y is base_sensor's -y), the PHANToM at
// RP in the robot frame. The nominal sensor height keeps the base on the floor.
std::vector<FrameDescription> rig_frames(const Eigen::Vector3d& SR_mm, const Eigen::Vector3d& RP_mm) {
  const double robot_height_mm = 810.8;
  return {
      frame("is900", "world", {0, 2624, 0}, {90, 90, 0}),
      frame("base_sensor", "is900", {206, 0, 2624 + SR_mm.z() - robot_height_mm}, {180, 0, 180}),
      frame("robot", "base_sensor", {SR_mm.x(), -SR_mm.y(), SR_mm.z()}, {0, 0, 90}),
      frame("phantom", "robot", RP_mm, {90, 0, 0}),
      frame("base", "robot", {0, 0, -robot_height_mm}, {90, 0, 0}),
  };
}

struct ThesisInput {
  Eigen::Vector3d S_mm;  // Sx, Sy, Sz
  double phi;
  Eigen::Vector3d q;
};

ThesisInput random_input(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> position(-1000, 1000), height(1200, 1700), angle(-kHalfTurn, kHalfTurn);
  return ThesisInput{Eigen::Vector3d(position(rng), position(rng), height(rng)), angle(rng),
                     Eigen::Vector3d(angle(rng), angle(rng), angle(rng))};
}

// Ch. 4.4.2, the HIP in the world (mm) with the offsets SR and RP as variables; with the
// ruler values it is ch. 4.3's closed form (4191/20, 8/5, 2209/5 and 10091/4).
Eigen::Vector3d thesis_hip_mm(const ThesisInput& in, const Eigen::Vector3d& SR, const Eigen::Vector3d& RP) {
  const double c = std::cos(in.phi), s = std::sin(in.phi);
  const double c1 = std::cos(in.q.x()), s1 = std::sin(in.q.x()), c2 = std::cos(in.q.y()), s2 = std::sin(in.q.y());
  const double c3 = std::cos(in.q.z()), s3 = std::sin(in.q.z());
  const double reach = L * c2 + L * s3;
  const double Sx = in.S_mm.x(), Sy = in.S_mm.y(), Sz = in.S_mm.z();
  return Eigen::Vector3d(
      -c * s1 * reach + s * (-L + c1 * reach) - c * RP.x() - s * RP.y() + s * SR.x() + c * SR.y() + Sy,
      56671.0 / 20 + L * s2 - L * c3 + RP.z() + SR.z() - Sz,
      -s * s1 * reach - c * (-L + c1 * reach) - s * RP.x() + c * RP.y() - c * SR.x() + s * SR.y() - Sx);
}

const Eigen::Vector3d kRulerSR(206, 0, -370);
const Eigen::Vector3d kRulerRP(-1.6, -235.8, 59.2);
const Eigen::Vector3d kCalibratedSR(203.1, 1.8, -387.6);
const Eigen::Vector3d kCalibratedRP(-2.1, -232.8, 41.6);

TEST(Rig, PomhiSceneHasRigFramesOnly) {
  const Result<SceneDescription> read = read_scene_file(kPomhi);
  ASSERT_TRUE(read.ok()) << (read.diagnostics().empty() ? "" : read.diagnostics().front().to_string());
  EXPECT_TRUE(read->objects.empty());
  EXPECT_EQ(read->rig_frames.size(), 5u);
  EXPECT_TRUE(Rig::from_scene(*read).ok());
}

TEST(Rig, FixedFramesReproduceTheThesisMatrices) {
  const Rig rig = pomhi_rig();
  Eigen::Matrix3d R41, R44;
  R41 << 0, 1, 0, 0, 0, -1, -1, 0, 0;
  R44 << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  EXPECT_TRUE(rig.X_W_is900().isApprox(homogeneous_mm(R41, {0, 2624, 0}), 1e-12));
  EXPECT_TRUE(rig.X_robot_phantom().isApprox(homogeneous_mm(R44, {-1.6, -235.8, 59.2}), 1e-12));

  // Eq. 4.2 and 4.3 as printed each have determinant -1; only their product is a rigid
  // motion, and the rig reproduces that product for every measurement.
  Eigen::Matrix3d R43;
  R43 << 0, -1, 0, -1, 0, 0, 0, 0, 1;
  EXPECT_NEAR(R43.determinant(), -1.0, 1e-15);
  std::mt19937_64 rng(1);
  for (int i = 0; i < 100; ++i) {
    const ThesisInput in = random_input(rng);
    Eigen::Matrix3d R42;
    R42 << std::cos(in.phi), -std::sin(in.phi), 0, std::sin(in.phi), std::cos(in.phi), 0, 0, 0, -1;
    EXPECT_NEAR(R42.determinant(), -1.0, 1e-15);
    const Pose thesis = homogeneous_mm(R42, in.S_mm) * homogeneous_mm(R43, {206, 0, -370});
    const Pose ours = sensor_reading(in.phi, in.S_mm) * rig.X_base_sensor_robot();
    EXPECT_LT((thesis.matrix() - ours.matrix()).norm(), 1e-12);
  }
}

TEST(Rig, ThesisConstantsComeFromTheRigValues) {
  // Ch. 4.3 (ruler values).
  EXPECT_DOUBLE_EQ(4191.0 / 20, 209.55);                      // l1 = l2
  EXPECT_DOUBLE_EQ(8.0 / 5, 1.6);                             // -RPx
  EXPECT_NEAR(2209.0 / 5, 206 + 235.8, 1e-12);                // SRx - RPy: the matrix's -235.8, not the text's -234.8
  EXPECT_NEAR(10091.0 / 4, 2624 - 370 + 59.2 + 209.55, 1e-12);  // IS-900 height + SRz + RPz + l2
  // Ch. 4.4 and 5.1 (calibrated values).
  EXPECT_NEAR(56671.0 / 20, 2624 + 209.55, 1e-12);
  EXPECT_NEAR(5023.0 / 20, 209.55 + 41.6, 1e-12);  // l2 + RPz: Ry is the robot origin's height
  EXPECT_NEAR(1164.0 / 5, 232.8, 1e-12);           // -RPy
  EXPECT_NEAR(21.0 / 10, 2.1, 1e-12);              // -RPx
  EXPECT_NEAR(93.0 / 4, 232.8 - 209.55, 1e-12);    // J13's constant: -RPy - l1
}

TEST(Rig, HipMatchesTheClosedFormOfChapter43) {
  const Rig rig = pomhi_rig();
  std::mt19937_64 rng(2);
  for (int i = 0; i < 1000; ++i) {
    const ThesisInput in = random_input(rng);
    const Pose X_W_robot = rig.X_W_robot_from_sensor(sensor_reading(in.phi, in.S_mm));
    const Eigen::Vector3d p_W = rig.p_W_hip(X_W_robot, in.q);
    EXPECT_LT((p_W - thesis_hip_mm(in, kRulerSR, kRulerRP) / 1000.0).norm(), 1e-12);
  }
}

TEST(Rig, ToolRotationMatchesTheRederivedClosedForm) {
  // R_W_tool = Ry(pi - phi + theta1) Rx(-theta3). The thesis prints R13 and R33 with a
  // wrong sign on one term each (eq. 4.5's (3,3) typo carried through); the others agree.
  const Rig rig = pomhi_rig();
  std::mt19937_64 rng(3);
  for (int i = 0; i < 200; ++i) {
    const ThesisInput in = random_input(rng);
    const Pose X = rig.X_W_tool(rig.X_W_robot_from_sensor(sensor_reading(in.phi, in.S_mm)), in.q);
    const Eigen::Matrix3d expected = Ry(kHalfTurn - in.phi + in.q.x()) * Rx(-in.q.z());
    EXPECT_LT((X.linear() - expected).norm(), 1e-12);
    const double c = std::cos(in.phi), s = std::sin(in.phi);
    const double c1 = std::cos(in.q.x()), s1 = std::sin(in.q.x()), c3 = std::cos(in.q.z()), s3 = std::sin(in.q.z());
    const Eigen::Matrix3d R = X.linear();
    EXPECT_NEAR(R(0, 0), -c * c1 - s * s1, 1e-12);
    EXPECT_NEAR(R(0, 1), c * s1 * s3 - s * c1 * s3, 1e-12);
    EXPECT_NEAR(R(1, 0), 0, 1e-12);
    EXPECT_NEAR(R(1, 1), c3, 1e-12);
    EXPECT_NEAR(R(1, 2), s3, 1e-12);
    EXPECT_NEAR(R(2, 0), -s * c1 + c * s1, 1e-12);
    EXPECT_NEAR(R(2, 1), s * s1 * s3 + c * c1 * s3, 1e-12);
    EXPECT_NEAR(R(0, 2), -c * s1 * c3 + s * c1 * c3, 1e-12);  // printed: ... - s c1 c3
    EXPECT_NEAR(R(2, 2), -s * s1 * c3 - c * c1 * c3, 1e-12);  // printed: ... + c c1 c3
  }
}

TEST(Rig, CalibratedOffsetsMatchChapter44) {
  const Result<Rig, std::vector<RigError>> built = Rig::from_frames(rig_frames(kCalibratedSR, kCalibratedRP));
  ASSERT_TRUE(built.ok());
  std::mt19937_64 rng(4);
  for (int i = 0; i < 500; ++i) {
    const ThesisInput in = random_input(rng);
    const Eigen::Vector3d p_W =
        built->p_W_hip(built->X_W_robot_from_sensor(sensor_reading(in.phi, in.S_mm)), in.q);
    EXPECT_LT((p_W - thesis_hip_mm(in, kCalibratedSR, kCalibratedRP) / 1000.0).norm(), 1e-12);
  }
}

TEST(Rig, PlanarBasePathAgreesWithTheTrackerPath) {
  const Rig rig = pomhi_rig();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> position(-3, 3), angle(-kHalfTurn, kHalfTurn);
  for (int i = 0; i < 200; ++i) {
    const BasePose base{position(rng), position(rng), angle(rng)};
    const Pose X_is900_sensor = rig.X_is900_base_sensor_from_base(base);
    EXPECT_TRUE(rig.X_W_robot_from_sensor(X_is900_sensor).isApprox(rig.X_W_robot_from_base(base), 1e-12));
    const BasePose back = rig.base_from_sensor(X_is900_sensor);
    EXPECT_NEAR(back.x_m, base.x_m, 1e-12);
    EXPECT_NEAR(back.z_m, base.z_m, 1e-12);
    EXPECT_NEAR(wrap_angle(back.heading_rad - base.heading_rad), 0, 1e-12);
    // The measured station is level with z up, turned by the tracker's yaw phi = pi - heading.
    const Eigen::Matrix3d R = X_is900_sensor.linear();
    EXPECT_LT((R - Rz(kHalfTurn - base.heading_rad) * Rx(kHalfTurn)).norm(), 1e-12);
  }
  // The nominal station pose is the base at the origin with heading 0.
  const BasePose home = rig.base_from_sensor(rig.X_is900_base_sensor_nominal());
  EXPECT_NEAR(home.x_m, 0, 1e-12);
  EXPECT_NEAR(home.z_m, 0, 1e-12);
  EXPECT_NEAR(home.heading_rad, 0, 1e-12);
}

TEST(Rig, AtTheOriginThePhantomFacesTheUserAtHandHeight) {
  const Rig rig = pomhi_rig();
  const Pose X_W_robot = rig.X_W_robot_from_base(BasePose{});
  const Pose X_W_P = rig.X_W_phantom(X_W_robot);
  EXPECT_LT((X_W_P.linear() - Eigen::Matrix3d::Identity()).norm(), 1e-12);  // P's z (to the user) is world +z
  EXPECT_LT((X_W_P.translation() - Eigen::Vector3d(-0.0016, 0.870, 0.2358)).norm(), 1e-12);
  EXPECT_NEAR((X_W_P * rig.device().workspace.center_P_m()).y(), 1.0, 1e-12);
  // The robot: x forward (= world x at heading 0), z up.
  EXPECT_LT((X_W_robot.linear() - Rx(-kHalfTurn / 2)).norm(), 1e-12);
  EXPECT_NEAR(X_W_robot.translation().y(), 0.8108, 1e-12);
}

Eigen::Vector3d hip_from_parameters(const Rig& rig, const Eigen::Matrix<double, 7, 1>& v) {
  Pose X_W_robot = rig.X_W_robot_from_base(BasePose{v[kBaseX], v[kBaseZ], v[kBaseHeading]});
  X_W_robot.pretranslate(Eigen::Vector3d(0, v[kBaseY], 0));
  return rig.p_W_hip(X_W_robot, v.tail<3>());
}

TEST(Rig, HipJacobianMatchesCentralDifferencesOfTheChain) {
  const Rig rig = pomhi_rig();
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> position(-3, 3), angle(-kHalfTurn, kHalfTurn);
  constexpr double h = 1e-6;
  for (int i = 0; i < 300; ++i) {
    Eigen::Matrix<double, 7, 1> v;
    v << position(rng), 0.0, position(rng), angle(rng), angle(rng), angle(rng), angle(rng);
    const Rig::HipJacobian J = rig.hip_jacobian(BasePose{v[kBaseX], v[kBaseZ], v[kBaseHeading]}, v.tail<3>());
    for (int j = 0; j < 7; ++j) {
      Eigen::Matrix<double, 7, 1> dv = Eigen::Matrix<double, 7, 1>::Zero();
      dv[j] = h;
      const Eigen::Vector3d numeric = (hip_from_parameters(rig, v + dv) - hip_from_parameters(rig, v - dv)) / (2 * h);
      EXPECT_LT((J.col(j) - numeric).norm(), 1e-8) << "column " << j;
    }
  }
}

TEST(Rig, HipJacobianMatchesEquation52) {
  // Eq. 5.2 (calibrated rig), in mm, columns Rx, Rz, phi, theta1..3; phi = pi - heading.
  const Result<Rig, std::vector<RigError>> built = Rig::from_frames(rig_frames(kCalibratedSR, kCalibratedRP));
  ASSERT_TRUE(built.ok());
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> position(-3, 3), angle(-kHalfTurn, kHalfTurn);
  constexpr double H = 4191.0 / 40;  // l / 2
  for (int i = 0; i < 300; ++i) {
    const double phi = angle(rng), t1 = angle(rng), t2 = angle(rng), t3 = angle(rng);
    const BasePose base{position(rng), position(rng), kHalfTurn - phi};
    const Rig::HipJacobian J = built->hip_jacobian(base, {t1, t2, t3});
    using std::cos, std::sin;
    Eigen::Matrix<double, 3, 6> thesis;
    const double J14 = -H * cos(-t2 - phi + t1) - H * cos(t2 - phi + t1) - H * sin(t3 - phi + t1) +
                       H * sin(-t3 - phi + t1);
    const double J34 = H * sin(t2 - phi + t1) + H * sin(-t2 - phi + t1) + H * cos(-t3 - phi + t1) -
                       H * cos(t3 - phi + t1);
    thesis << 1, 0, -J14 + 93.0 / 4 * cos(phi) - 21.0 / 10 * sin(phi), J14,
        H * cos(-t2 - phi + t1) - H * cos(t2 - phi + t1), -H * sin(t3 - phi + t1) - H * sin(-t3 - phi + t1),  //
        0, 0, 0, 0, L * cos(t2), L * sin(t3),                                                                  //
        0, 1, -J34 + 93.0 / 4 * sin(phi) + 21.0 / 10 * cos(phi), J34,
        H * sin(t2 - phi + t1) - H * sin(-t2 - phi + t1), -H * cos(-t3 - phi + t1) - H * cos(t3 - phi + t1);
    Eigen::Matrix<double, 3, 6> ours;
    ours << J.col(kBaseX), J.col(kBaseZ), -J.col(kBaseHeading), J.rightCols<3>();
    ours.rightCols<4>() *= 1000.0;  // m/rad -> mm/rad
    EXPECT_LT((ours - thesis).norm(), 1e-9);
  }
}

TEST(Rig, WorldTorquesDoTheSameVirtualWorkAsTheForce) {
  const Rig rig = pomhi_rig();
  std::mt19937_64 rng(8);
  std::normal_distribution<double> normal(0, 1);
  for (int i = 0; i < 200; ++i) {
    const Pose X_W_robot = rig.X_W_robot_from_base(BasePose{normal(rng), normal(rng), 3 * normal(rng)});
    const Eigen::Vector3d q(0.5 * normal(rng), 0.5 * normal(rng), 0.5 * normal(rng));
    const Eigen::Vector3d force_W_N(3 * normal(rng), 3 * normal(rng), 3 * normal(rng));
    const Eigen::Vector3d dq = 1e-6 * Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
    const Eigen::Vector3d dp_W = rig.p_W_hip(X_W_robot, q + dq) - rig.p_W_hip(X_W_robot, q - dq);
    EXPECT_NEAR(force_W_N.dot(dp_W), rig.joint_torques_Nm(X_W_robot, q, force_W_N).dot(2 * dq), 1e-14);
    EXPECT_LT((rig.p_P_from_W(X_W_robot, rig.p_W_hip(X_W_robot, q)) -
               phantom_tool_position(rig.device().geometry, q)).norm(), 1e-14);
  }
}

std::vector<std::string> messages(const Result<Rig, std::vector<RigError>>& result) {
  std::vector<std::string> out;
  if (result.ok()) return out;
  for (const RigError& e : result.error()) out.push_back(e.to_string());
  return out;
}

TEST(Rig, ReportsEveryMissingFrame) {
  const Result<Rig, std::vector<RigError>> result = Rig::from_frames({frame("head", "is900", {0, 0, 0}, {0, 0, 0})});
  EXPECT_FALSE(result.ok());
  ASSERT_EQ(result.error().size(), 5u);
  for (const RigError& e : result.error()) EXPECT_EQ(e.kind, RigErrorKind::MissingFrame);
  EXPECT_EQ(result.error()[2].to_string(),
            "error: rig has no frame 'robot' (expected <frame name=\"robot\" parent=\"base_sensor\" .../>)");
}

TEST(Rig, ReportsAWrongParentWhereTheFrameIsDefined) {
  std::vector<FrameDescription> frames = rig_frames(kRulerSR, kRulerRP);
  frames[2].parent = "is900";
  frames[2].where.line = 17;
  const Result<Rig, std::vector<RigError>> result = Rig::from_frames(frames);
  EXPECT_EQ(messages(result),
            std::vector<std::string>{"scene.xml:17: error: rig frame 'robot' must have parent 'base_sensor', not 'is900'"});
  EXPECT_EQ(result.error()[0].kind, RigErrorKind::WrongParent);
}

TEST(Rig, ReportsABaseThatIsNotLevelOrNotOnTheFloor) {
  std::vector<FrameDescription> frames = rig_frames(kRulerSR, kRulerRP);
  frames[4] = frame("base", "robot", {0, 0, -800}, {0, 0, 0}, 30);  // robot axes, 10.8 mm up
  const Result<Rig, std::vector<RigError>> result = Rig::from_frames(frames);
  EXPECT_EQ(messages(result),
            (std::vector<std::string>{
                "scene.xml:30: error: rig frame 'base' is not level: with base_sensor at its nominal pose, its y "
                "axis is 90 degrees from world up",
                "scene.xml:30: error: rig frame 'base' is not on the floor: with base_sensor at its nominal pose, it "
                "is at y = 0.0108 m"}));
  EXPECT_EQ(result.error()[0].kind, RigErrorKind::BaseNotLevel);
  EXPECT_EQ(result.error()[1].kind, RigErrorKind::BaseNotOnFloor);
}

TEST(Rig, ReportsADuplicateFrame) {
  std::vector<FrameDescription> frames = rig_frames(kRulerSR, kRulerRP);
  frames.push_back(frame("phantom", "robot", {0, 0, 0}, {0, 0, 0}, 40));
  frames[3].where.line = 12;
  const Result<Rig, std::vector<RigError>> result = Rig::from_frames(frames);
  EXPECT_EQ(messages(result), std::vector<std::string>{
                                  "scene.xml:40: error: rig frame 'phantom' is defined twice (first at scene.xml:12)"});
}

TEST(Rig, ADesktopRigPutsTheDeviceFrameAtItsPoseInTheWorldForEver) {
  const Pose X_WD = pose_from_xyz_rpy(Eigen::Vector3d(0.1, 0.75, -0.2), Eigen::Vector3d(0.0, 0.0, 0.5));
  SceneDescription scene;
  scene.rig_kind = {RigKind::Desktop, SourceLocation{"desk.xml", 3}};
  scene.rig_frames.push_back({"device", "world", X_WD, {"desk.xml", 4}});
  const Result<Rig, std::vector<RigError>> built = Rig::from_scene(scene);
  ASSERT_TRUE(built.ok());
  const Rig& rig = *built;
  EXPECT_EQ(rig.kind(), RigKind::Desktop);
  const Pose X_W_robot = rig.X_W_robot_from_base(BasePose{});
  const Eigen::Vector3d p_D(0.01, 0.12, -0.03);
  EXPECT_TRUE(rig.p_W_from_device(X_W_robot, p_D).isApprox(X_WD * p_D, 1e-15));
  const Eigen::Vector3d force_W(1.0, -2.0, 0.5);
  EXPECT_TRUE(rig.force_P_from_W(X_W_robot, force_W).isApprox(X_WD.linear().transpose() * force_W, 1e-15));

  // Without its frame it is an error at the rig, not a rig somewhere.
  scene.rig_frames.clear();
  const Result<Rig, std::vector<RigError>> missing = Rig::from_scene(scene);
  ASSERT_FALSE(missing.ok());
  ASSERT_EQ(missing.error().size(), 1u);
  EXPECT_EQ(missing.error()[0].to_string(),
            "desk.xml:3: error: desktop rig has no frame 'device' (expected <frame name=\"device\" parent=\"world\" .../>)");
}

}  // namespace
}  // namespace mhd
