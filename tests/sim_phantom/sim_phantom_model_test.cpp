#include "sim_phantom_model.h"

#include "kinematics/rig.h"
#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>

namespace mhd::sim_phantom {
namespace {

PhantomSimConfig exact_config() {
  PhantomSimConfig c;
  c.position_resolution_m = 0.0;  // no quantisation: FK(IK) is exact
  return c;
}

PhantomSimModel started(const PhantomSimConfig& c, double t0 = 0.0) {
  PhantomSimModel m(c);
  m.start(t0);
  return m;
}

TEST(SimPhantomModel, TheHipFollowsAHandInsideTheWorkspace) {
  PhantomSimModel m = started(exact_config());
  const WorkspaceBox box = m.config().device.usable_workspace();
  for (int k = 0; k <= 100; ++k) {
    const double s = 0.01 * k;
    const Eigen::Vector3d hand = box.min_P_m + (box.max_P_m - box.min_P_m).cwiseProduct(
                                                   Eigen::Vector3d(s, 0.5 + 0.5 * std::sin(7.0 * s), 1.0 - s));
    m.simulate_until(0.001 * k, hand);
    EXPECT_LT((m.p_P_hip_m() - hand).norm(), 1e-9) << k;
    EXPECT_LT((phantom_tool_position(m.config().device.geometry, m.joint_angles_rad()) - m.p_P_hip_m()).norm(), 1e-15);
    EXPECT_TRUE(m.config().device.limits.contains(m.joint_angles_rad()));
    EXPECT_DOUBLE_EQ(m.time_s(), 0.001 * k);
  }
  EXPECT_EQ(m.workspace_clamps(), 0u);
  EXPECT_EQ(m.unreachable_count(), 0u);
}

TEST(SimPhantomModel, JointAnglesAreQuantisedToTheResolution) {
  PhantomSimModel m = started(PhantomSimConfig{});
  const PhantomGeometry& g = m.config().device.geometry;
  const double step = 0.03e-3 / (g.l1_m + g.l2_m);
  const Eigen::Vector3d hand(0.0312345, 0.1123456, 0.0198765);
  m.simulate_until(0.0, hand);
  for (int j = 0; j < 3; ++j) {
    const double n = m.joint_angles_rad()[j] / step;
    EXPECT_NEAR(n, std::round(n), 1e-6);
  }
  // Half a step per joint, each moving the tool by at most (l1 + l2) per radian.
  EXPECT_LE((m.p_P_hip_m() - hand).norm(), 1.5 * 0.03e-3);
  EXPECT_GT((m.p_P_hip_m() - hand).norm(), 0.0);
}

TEST(SimPhantomModel, AHandOutsideTheWorkspaceIsClampedAndCounted) {
  PhantomSimModel m = started(exact_config());
  const WorkspaceBox& box = m.config().device.workspace;
  m.simulate_until(0.0, Eigen::Vector3d(0.5, 0.13, -2.0));
  EXPECT_LT((m.p_P_hip_m() - Eigen::Vector3d(box.max_P_m.x(), 0.13, box.min_P_m.z())).norm(), 1e-9);
  EXPECT_EQ(m.workspace_clamps(), 1u);
  m.simulate_until(0.001, box.center_P_m());
  EXPECT_EQ(m.workspace_clamps(), 1u);
  EXPECT_EQ(m.unreachable_count(), 0u);
}

TEST(SimPhantomModel, AnUnreachablePointHoldsTheLastAnglesAndIsCounted) {
  PhantomSimConfig c = exact_config();
  c.device.workspace.min_P_m = Eigen::Vector3d::Constant(-2.0);  // a box larger than the arm's reach
  c.device.workspace.max_P_m = Eigen::Vector3d::Constant(2.0);
  c.device.workspace.min_P_m.y() = -1.74;  // keep the centre where it was reachable: (0, 0.13, 0)
  c.device.workspace.max_P_m.y() = 2.0;
  PhantomSimModel m(c);
  m.start(0.0);
  const Eigen::Vector3d reachable(0.05, 0.12, -0.02);
  m.simulate_until(0.0, reachable);
  const Eigen::Vector3d q = m.joint_angles_rad();
  m.simulate_until(0.001, Eigen::Vector3d(0.0, 0.13, 1.5));
  EXPECT_EQ(m.unreachable_count(), 1u);
  EXPECT_EQ(m.joint_angles_rad(), q);
  EXPECT_LT((m.p_P_hip_m() - reachable).norm(), 1e-9);
  EXPECT_EQ(m.workspace_clamps(), 0u);
}

TEST(SimPhantomModel, TorquesPushTheHipByForceOverStiffness) {
  PhantomSimConfig c = exact_config();
  c.hand_stiffness_N_per_m = 2000.0;
  PhantomSimModel m = started(c);
  const Eigen::Vector3d hand(0.02, 0.15, -0.03);
  m.simulate_until(0.0, hand);
  const Eigen::Vector3d q0 = m.joint_angles_rad();
  const Eigen::Vector3d F(3.0, -2.0, 1.5);
  const Eigen::Vector3d tau = phantom_position_jacobian(c.device.geometry, q0).transpose() * F;
  m.command(tau, 0.0005);
  m.simulate_until(0.001, hand);
  EXPECT_FALSE(m.watchdog_stopped());
  EXPECT_LT((m.force_P_N() - F).norm(), 1e-9);
  EXPECT_LT((m.p_P_hip_m() - (hand + F / 2000.0)).norm(), 1e-9);
  // The push is along F: the displacement through J of the angle change points the same way.
  const Eigen::Vector3d dp = phantom_position_jacobian(c.device.geometry, q0) * (m.joint_angles_rad() - q0);
  EXPECT_GT(dp.normalized().dot(F.normalized()), 0.999);
  // A stiffer hand gives less.
  c.hand_stiffness_N_per_m = 4000.0;
  PhantomSimModel stiff = started(c);
  stiff.command(tau, 0.0);
  stiff.simulate_until(0.001, hand);
  EXPECT_LT((stiff.p_P_hip_m() - (hand + F / 4000.0)).norm(), 1e-9);
}

TEST(SimPhantomModel, TheWatchdogZeroesStaleTorques) {
  PhantomSimModel m = started(exact_config());
  const Eigen::Vector3d hand = m.config().device.workspace.center_P_m();
  m.simulate_until(0.0, hand);
  EXPECT_TRUE(m.watchdog_stopped());  // nothing commanded yet
  m.command(Eigen::Vector3d(0.5, -0.4, 0.3), 0.0);
  m.simulate_until(0.02, hand);  // exactly command_timeout_s old: still in effect
  EXPECT_FALSE(m.watchdog_stopped());
  EXPECT_GT((m.p_P_hip_m() - hand).norm(), 1e-4);
  m.simulate_until(0.0201, hand);  // stale: the host stalled
  EXPECT_TRUE(m.watchdog_stopped());
  EXPECT_EQ(m.applied_torques_Nm(), Eigen::Vector3d::Zero());
  EXPECT_EQ(m.force_P_N(), Eigen::Vector3d::Zero());
  EXPECT_LT((m.p_P_hip_m() - hand).norm(), 1e-9);
  m.command(Eigen::Vector3d(0.5, -0.4, 0.3), 0.2);  // a fresh command applies again
  m.simulate_until(0.201, hand);
  EXPECT_FALSE(m.watchdog_stopped());
  m.start(0.3);  // start forgets commands
  m.simulate_until(0.3, hand);
  EXPECT_TRUE(m.watchdog_stopped());
}

TEST(SimPhantomModel, RejectsNonFiniteInputAndUseBeforeStart) {
  PhantomSimModel m(exact_config());
  const Eigen::Vector3d hand(0.0, 0.13, -0.01);
  try {
    m.simulate_until(0.0, hand);
    ADD_FAILURE() << "no throw";
  } catch (const std::logic_error& e) {
    EXPECT_STREQ(e.what(), "simulate_until before start");
  }
  m.start(0.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  try {
    m.command(Eigen::Vector3d(0.0, nan, 0.0), 0.0);
    ADD_FAILURE() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "device command has a non-finite value");
  }
  EXPECT_THROW(m.command(Eigen::Vector3d(std::numeric_limits<double>::infinity(), 0.0, 0.0), 0.0), std::invalid_argument);
  EXPECT_THROW(m.simulate_until(0.0, Eigen::Vector3d(nan, 0.0, 0.0)), std::invalid_argument);
}

std::string config_error(const PhantomSimConfig& c) {
  try {
    const PhantomSimModel m(c);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(SimPhantomModel, BadSettingsAreRejectedWithTheirName) {
  PhantomSimConfig c;
  c.hand_stiffness_N_per_m = 0.0;
  EXPECT_EQ(config_error(c), "hand_stiffness_N_per_m must be a positive number");
  c = PhantomSimConfig{};
  c.command_timeout_s = std::numeric_limits<double>::infinity();
  EXPECT_EQ(config_error(c), "command_timeout_s must be a positive number");
  c = PhantomSimConfig{};
  c.position_resolution_m = -1e-6;
  EXPECT_EQ(config_error(c), "position_resolution_m must be a non-negative number");
  c = PhantomSimConfig{};
  c.X_robot_phantom.translation().x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(config_error(c), "rig transforms must be finite");
  EXPECT_EQ(config_error(PhantomSimConfig{}), "");
}

TEST(SimPhantomModel, TorqueLimitsGive8Point5NewtonsAtTheNominalConfiguration) {
  const PhantomSimModel m(PhantomSimConfig{});
  const Eigen::Matrix3d J = phantom_position_jacobian(m.config().device.geometry, m.nominal_angles_rad());
  const Eigen::Vector3d limits = m.max_joint_torques_Nm();
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(limits[j], 8.5 * J.col(j).norm(), 1e-12);
    // Reached by 8.5 N along column j.
    const Eigen::Vector3d tau = J.transpose() * (8.5 * J.col(j).normalized());
    EXPECT_NEAR(std::abs(tau[j]), limits[j], 1e-12);
  }
  for (int k = 0; k < 50; ++k) {
    const Eigen::Vector3d F = 8.5 * Eigen::Vector3d(std::sin(k), std::cos(3.0 * k), std::sin(5.0 * k + 1.0)).normalized();
    EXPECT_TRUE(((J.transpose() * F).cwiseAbs().array() <= limits.array() + 1e-12).all());
  }
  EXPECT_LT((phantom_tool_position(m.config().device.geometry, m.nominal_angles_rad()) -
             m.config().device.workspace.center_P_m()).norm(), 1e-9);
}

TEST(SimPhantomModel, TheDeviceFrameMatchesThePomhiRig) {
  const Result<SceneDescription> read = read_scene_file(std::filesystem::path(MHD_SOURCE_DIR) / "scenes/rigs/pomhi.xml");
  ASSERT_TRUE(read.ok());
  const Result<Rig, std::vector<RigError>> built = Rig::from_scene(*read);
  ASSERT_TRUE(built.ok());
  const Rig& rig = *built;
  const PhantomSimModel m(PhantomSimConfig{});
  for (const BasePose base : {BasePose{0.0, 0.0, 0.0}, BasePose{1.2, -0.7, 0.9}, BasePose{-3.0, 2.0, -2.5}}) {
    const Pose expected = rig.X_W_phantom(rig.X_W_robot_from_base(base));
    EXPECT_LT((m.X_W_phantom(base).matrix() - expected.matrix()).norm(), 1e-12);
    const Eigen::Vector3d p_W(0.3 + base.x_m, 1.0, base.z_m - 0.2);
    EXPECT_LT((m.p_P_from_W(base, p_W) - rig.p_P_from_W(rig.X_W_robot_from_base(base), p_W)).norm(), 1e-12);
  }
}

}  // namespace
}  // namespace mhd::sim_phantom
