#include "sim_delta_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace mhd::sim_delta {
namespace {

DeltaSimModel started(const DeltaSimConfig& c, double t0 = 0.0) {
  DeltaSimModel m(c);
  m.start(t0);
  return m;
}

Eigen::Matrix3d jacobian_at(const DeltaSimConfig& c, const Eigen::Vector3d& p_D_m) {
  return *delta_jacobian(c.geometry, *delta_inverse_kinematics(c.geometry, c.limits, p_D_m));
}

TEST(SimDeltaModel, WithNoForceTheToolFollowsTheHand) {
  DeltaSimModel m = started(DeltaSimConfig{});
  const DeltaWorkspaceBox& box = m.config().workspace;
  Eigen::Vector3d previous = m.p_D_tool_m();
  for (int k = 0; k <= 100; ++k) {
    const double s = 0.01 * k;
    const Eigen::Vector3d hand =
        box.min_D_m + box.size_m().cwiseProduct(Eigen::Vector3d(s, 0.5 + 0.5 * std::sin(7.0 * s), 1.0 - s));
    m.simulate_until(0.001 * k, hand);
    EXPECT_LT((m.p_D_tool_m() - hand).norm(), 1e-12) << k;
    EXPECT_LT((*delta_forward_kinematics(m.config().geometry, m.motor_angles_rad()) - m.p_D_tool_m()).norm(), 1e-15);
    if (k > 0) {
      EXPECT_LT((m.v_D_tool_mps() - (hand - previous) / 0.001).norm(), 1e-6) << k;
    }
    previous = m.p_D_tool_m();
  }
  EXPECT_EQ(m.force_D_N(), Eigen::Vector3d::Zero());
  EXPECT_EQ(m.workspace_clamps(), 0u);
  EXPECT_EQ(m.unreachable_count(), 0u);
}

TEST(SimDeltaModel, AHandOutsideTheWorkspaceIsClampedAndCounted) {
  DeltaSimModel m = started(DeltaSimConfig{});
  const DeltaWorkspaceBox& box = m.config().workspace;
  m.simulate_until(0.0, Eigen::Vector3d(0.5, 0.01, -2.0));
  EXPECT_LT((m.p_D_tool_m() - Eigen::Vector3d(box.max_D_m.x(), 0.01, box.min_D_m.z())).norm(), 1e-12);
  EXPECT_EQ(m.workspace_clamps(), 1u);
  m.simulate_until(0.001, box.center_D_m());
  EXPECT_EQ(m.workspace_clamps(), 1u);
}

TEST(SimDeltaModel, AForceAgainstTheKinematicHandPushesByForceOverStiffness) {
  const DeltaSimConfig c;
  DeltaSimModel m = started(c);
  const Eigen::Vector3d hand = c.workspace.center_D_m() + Eigen::Vector3d(0.01, -0.005, 0.008);
  m.simulate_until(0.0, hand);
  const Eigen::Vector3d F_N(2.0, -1.5, -3.0);
  m.command(F_N, 0.0005);
  EXPECT_LT((m.commanded_torques_Nm() - jacobian_at(c, hand).transpose() * F_N).norm(), 1e-12);
  m.simulate_until(0.001, hand);
  EXPECT_FALSE(m.watchdog_stopped());
  EXPECT_LT((m.force_D_N() - F_N).norm(), 1e-9);
  EXPECT_LT((m.p_D_tool_m() - (hand + F_N / c.hand_stiffness_N_per_m)).norm(), 1e-12);
  EXPECT_EQ(m.limited_commands(), 0u);
}

TEST(SimDeltaModel, WithNoForceTheImpedanceHandBringsTheHandleToTheHand) {
  DeltaSimConfig c;
  c.hand_model = HandModel::Impedance;
  DeltaSimModel m = started(c);
  const Eigen::Vector3d from = c.workspace.center_D_m() + Eigen::Vector3d(-0.02, 0.0, -0.01);
  const Eigen::Vector3d to = c.workspace.center_D_m() + Eigen::Vector3d(0.02, 0.01, 0.015);
  m.simulate_until(0.0, from);
  EXPECT_LT((m.p_D_tool_m() - from).norm(), 1e-12);
  double t_s = 0.0;
  for (int k = 1; k <= 50; ++k) m.simulate_until(t_s += 0.001, to);
  EXPECT_GT((m.p_D_tool_m() - to).norm(), 1e-3);  // a hand with mass takes time
  for (int k = 0; k < 3000; ++k) m.simulate_until(t_s += 0.001, to);
  EXPECT_LT((m.p_D_tool_m() - to).norm(), 1e-6);
  EXPECT_LT(m.v_D_tool_mps().norm(), 1e-4);
  if (const simulation::HandImpedance* h = m.hand()) {
    EXPECT_LT((m.p_D_tool_m() - h->p_W_m()).norm(), 1e-12);  // the tool is where the hand is
  } else {
    ADD_FAILURE() << "no impedance hand";
  }
}

TEST(SimDeltaModel, AConstantForceAgainstTheImpedanceHandSettlesWhereSpringAndForceBalance) {
  DeltaSimConfig c;
  c.hand_model = HandModel::Impedance;
  DeltaSimModel m = started(c);
  const Eigen::Vector3d hand = c.workspace.center_D_m() + Eigen::Vector3d(0.0, 0.005, 0.015);
  const Eigen::Vector3d F_N(0.5, -0.8, -1.5);  // pushes the handle back towards the base
  double t_s = 0.0;
  m.simulate_until(t_s, hand);
  for (int k = 0; k < 4000; ++k) {  // the host commands every millisecond
    m.command(F_N, t_s);
    m.simulate_until(t_s += 0.001, hand);
  }
  const Eigen::Vector3d balance = hand + F_N / c.hand_impedance.stiffness_N_per_m;
  ASSERT_TRUE(c.workspace.contains(balance));
  EXPECT_LT((m.p_D_tool_m() - balance).norm(), 1e-6);
  EXPECT_LT((m.force_D_N() - F_N).norm(), 1e-6);
  EXPECT_LT(m.v_D_tool_mps().norm(), 1e-4);
  EXPECT_GT((m.p_D_tool_m() - hand).norm(), 0.01);
}

TEST(SimDeltaModel, TheWatchdogZeroesAStaleForceAndAFreshCommandBringsItBack) {
  const DeltaSimConfig c;
  DeltaSimModel m = started(c);
  const Eigen::Vector3d hand = c.workspace.center_D_m();
  m.simulate_until(0.0, hand);
  EXPECT_TRUE(m.watchdog_stopped());  // nothing commanded yet
  const Eigen::Vector3d F_N(1.0, 2.0, -2.0);
  m.command(F_N, 0.0);
  m.simulate_until(c.command_timeout_s, hand);  // exactly command_timeout_s old: still in effect
  EXPECT_FALSE(m.watchdog_stopped());
  EXPECT_GT(m.force_D_N().norm(), 1.0);
  EXPECT_GT((m.p_D_tool_m() - hand).norm(), 1e-4);
  m.simulate_until(c.command_timeout_s + 1e-4, hand);  // stale: the host stalled
  EXPECT_TRUE(m.watchdog_stopped());
  EXPECT_EQ(m.applied_torques_Nm(), Eigen::Vector3d::Zero());
  EXPECT_EQ(m.force_D_N(), Eigen::Vector3d::Zero());
  EXPECT_LT((m.p_D_tool_m() - hand).norm(), 1e-12);
  m.command(F_N, 0.2);  // a fresh command applies again
  m.simulate_until(0.201, hand);
  EXPECT_FALSE(m.watchdog_stopped());
  EXPECT_LT((m.force_D_N() - F_N).norm(), 1e-9);
  m.start(0.3);  // start forgets commands
  m.simulate_until(0.3, hand);
  EXPECT_TRUE(m.watchdog_stopped());
  EXPECT_EQ(m.force_D_N(), Eigen::Vector3d::Zero());
}

TEST(SimDeltaModel, AForcePastTheLimitIsScaledDownAlongItsDirection) {
  const DeltaSimConfig c;
  DeltaSimModel m = started(c);
  const Eigen::Vector3d hand = c.workspace.center_D_m();
  m.simulate_until(0.0, hand);
  const Eigen::Vector3d F_N(12.0, -9.0, 20.0);
  m.command(F_N, 0.0);
  m.simulate_until(0.0, hand);
  EXPECT_EQ(m.limited_commands(), 1u);
  EXPECT_NEAR(m.force_D_N().norm(), c.max_force_N, 1e-9);
  EXPECT_GT(m.force_D_N().normalized().dot(F_N.normalized()), 1.0 - 1e-12);
}

TEST(SimDeltaModel, TheDerivedMotorLimitGivesTheFullForceEverywhereInTheWorkspace) {
  const DeltaSimConfig c;
  DeltaSimModel m = started(c);
  EXPECT_NEAR(m.max_motor_torque_Nm(), c.max_force_N * m.workspace_survey().max_jacobian_column_m, 1e-15);
  const DeltaWorkspaceBox& box = c.workspace;
  double t_s = 0.0;
  for (int corner = 0; corner < 8; ++corner) {  // corners are survey points
    const Eigen::Vector3d hand((corner & 1) ? box.max_D_m.x() : box.min_D_m.x(),
                               (corner & 2) ? box.max_D_m.y() : box.min_D_m.y(),
                               (corner & 4) ? box.max_D_m.z() : box.min_D_m.z());
    m.simulate_until(t_s += 0.001, hand);
    for (int d = 0; d < 6; ++d) {
      const Eigen::Vector3d F_N = (d % 2 ? -c.max_force_N : c.max_force_N) * Eigen::Vector3d::Unit(d / 2);
      m.command(F_N, t_s);
      EXPECT_LE(m.commanded_torques_Nm().cwiseAbs().maxCoeff(), m.max_motor_torque_Nm() + 1e-12);
    }
  }
  EXPECT_EQ(m.limited_commands(), 0u);
}

TEST(SimDeltaModel, AWeakMotorScalesTheWholeCommandAndKeepsItsDirection) {
  DeltaSimConfig c;
  c.max_motor_torque_Nm = 0.05;
  DeltaSimModel m = started(c);
  const Eigen::Vector3d hand = c.workspace.center_D_m() + Eigen::Vector3d(0.02, 0.0, 0.0);
  m.simulate_until(0.0, hand);
  const Eigen::Vector3d F_N(3.0, 1.0, -4.0);
  m.command(F_N, 0.0);
  m.simulate_until(0.0, hand);
  EXPECT_EQ(m.limited_commands(), 1u);
  EXPECT_NEAR(m.commanded_torques_Nm().cwiseAbs().maxCoeff(), 0.05, 1e-12);
  EXPECT_LT(m.force_D_N().norm(), F_N.norm());
  EXPECT_GT(m.force_D_N().normalized().dot(F_N.normalized()), 1.0 - 1e-12);
}

TEST(SimDeltaModel, RejectsNonFiniteInputAndUseBeforeStart) {
  DeltaSimModel m{DeltaSimConfig{}};
  const Eigen::Vector3d hand = m.config().workspace.center_D_m();
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
  EXPECT_THROW(m.command(Eigen::Vector3d::Zero(), std::numeric_limits<double>::infinity()), std::invalid_argument);
  EXPECT_THROW(m.simulate_until(0.0, Eigen::Vector3d(nan, 0.0, 0.0)), std::invalid_argument);
  EXPECT_THROW(m.simulate_until(nan, hand), std::invalid_argument);
}

std::string config_error(const DeltaSimConfig& c) {
  try {
    const DeltaSimModel m(c);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(SimDeltaModel, BadSettingsAreRejectedWithTheirName) {
  DeltaSimConfig c;
  c.geometry.forearm_m = -0.1;
  EXPECT_EQ(config_error(c), "forearm_m must be a positive number");
  c = DeltaSimConfig{};
  c.max_motor_torque_Nm = 0.0;
  EXPECT_EQ(config_error(c), "max_motor_torque_Nm must be a positive number");
  c = DeltaSimConfig{};
  c.command_timeout_s = std::numeric_limits<double>::infinity();
  EXPECT_EQ(config_error(c), "command_timeout_s must be a positive number");
  c = DeltaSimConfig{};
  c.limits.min_rad = c.limits.max_rad;
  EXPECT_EQ(config_error(c), "joint limits must be finite with min_rad < max_rad");
  c = DeltaSimConfig{};
  c.workspace.max_D_m.x() = c.workspace.min_D_m.x();
  EXPECT_EQ(config_error(c), "the workspace box must be finite with min < max on every axis");
  c = DeltaSimConfig{};
  c.workspace.max_D_m.z() = 0.17;
  EXPECT_EQ(config_error(c), "the workspace box is not reachable everywhere");
  c = DeltaSimConfig{};
  c.workspace_samples_per_axis = 1;
  EXPECT_EQ(config_error(c), "workspace_samples_per_axis must be at least 2");
  EXPECT_EQ(config_error(DeltaSimConfig{}), "");
}

}  // namespace
}  // namespace mhd::sim_delta
