#pragma once
// A simulated delta haptic device (Novint Falcon-like) held by the simulated user
// (docs/sim_delta.md). Cartesian, as ABI 3 devices are: the host commands a force F_D in
// the device frame D; the model reports the tool's position and velocity in D.
//
// command(F_D, t): F_D is scaled down to max_force_N, mapped to motor torques
// tau = J_D^T F_D with J_D at the latest motor angles (as a device driver does), and
// scaled down (direction kept) so that no |tau_j| exceeds the motor limit.
// simulate_until(t, p_D_hand): the torques in effect (zero once the latest command is
// older than command_timeout_s: the device's own watchdog) make the tool force
// F = J_D^-T tau at the tool's configuration. The hand pulls the handle to where the user
// means it to be; F pushes back (HandModel, as sim_phantom):
//   kinematic: the tool is at the intended hand (clamped to the workspace box) pushed by
//     F / hand_stiffness (a stiff, massless spring);
//   impedance: the hand is a mass-spring-damper (simulation::HandImpedance, integrated in
//     D, which is inertial for a desktop device) pulled to the intended hand and pushed
//     by F held since the last evaluation; the tool is where the hand is.
// The tool point is clamped to the workspace box and solved by inverse kinematics; where
// that fails the last angles are held (counted). The reported position is the forward
// kinematics of the angles; the velocity is its finite difference between evaluations.
// Not thread-safe; allocation-free after construction; nothing here is random.

#include "delta_kinematics.h"
#include "delta_workspace.h"
#include "simulation/hand_impedance.h"

#include <Eigen/Core>

#include <cstdint>
#include <optional>

namespace mhd::sim_delta {

enum class HandModel { Kinematic, Impedance };

struct DeltaSimConfig {
  DeltaGeometry geometry;
  DeltaJointLimits limits;
  DeltaWorkspaceBox workspace;
  /// Novint's figure for the Falcon: "2+ lbs" (8.9 N).
  double max_force_N = 9.0;
  /// Per-motor torque limit. nullopt: the least that gives max_force_N in every
  /// direction at every surveyed workspace point, max_force_N * max |column of J_D|.
  std::optional<double> max_motor_torque_Nm;
  /// The workspace survey made at construction: every grid point must be reached with
  /// cond(J_D) <= max_jacobian_condition.
  int workspace_samples_per_axis = 9;
  double max_jacobian_condition = 10.0;
  HandModel hand_model = HandModel::Kinematic;
  /// Kinematic hand: its spring.
  double hand_stiffness_N_per_m = 2000.0;
  /// Impedance hand (mass, stiffness, damping; docs/simulated_hand.md).
  simulation::HandImpedanceParams hand_impedance;
  /// The device's own command watchdog: a command older than this counts as zero.
  double command_timeout_s = 0.02;
};

class DeltaSimModel {
 public:
  /// Throws std::invalid_argument naming the setting for a non-positive / non-finite
  /// value, and "the workspace box is not reachable everywhere" when the survey fails.
  explicit DeltaSimModel(const DeltaSimConfig& config);

  /// Time origin at t_s; forgets commands, keeps the angles (initially those of the
  /// workspace centre), zeroes the velocity.
  void start(double t_s);
  /// A force in D received at host time t_received_s. Throws std::invalid_argument
  /// "device command has a non-finite value" for NaN / inf.
  void command(const Eigen::Vector3d& F_D_N, double t_received_s);
  /// Evaluates the device at host time t_s with the user meaning the hand to be at
  /// p_D_hand_m. A t_s before the current time is ignored. Throws std::logic_error
  /// "simulate_until before start" before start(), std::invalid_argument for non-finite input.
  void simulate_until(double t_s, const Eigen::Vector3d& p_D_hand_m);

  [[nodiscard]] const DeltaSimConfig& config() const noexcept { return config_; }
  [[nodiscard]] double time_s() const noexcept { return time_s_; }
  [[nodiscard]] const Eigen::Vector3d& motor_angles_rad() const noexcept { return q_rad_; }
  /// Forward kinematics of motor_angles_rad().
  [[nodiscard]] const Eigen::Vector3d& p_D_tool_m() const noexcept { return p_D_tool_m_; }
  [[nodiscard]] const Eigen::Vector3d& v_D_tool_mps() const noexcept { return v_D_tool_mps_; }
  /// The latest command's torques after both limits (zero before the first command).
  [[nodiscard]] const Eigen::Vector3d& commanded_torques_Nm() const noexcept { return tau_command_Nm_; }
  /// The torques in effect at time_s() (zero when none or stale) and the tool force they made.
  [[nodiscard]] const Eigen::Vector3d& applied_torques_Nm() const noexcept { return tau_applied_Nm_; }
  [[nodiscard]] const Eigen::Vector3d& force_D_N() const noexcept { return force_D_N_; }
  [[nodiscard]] bool watchdog_stopped() const noexcept { return watchdog_stopped_; }
  /// Host time of the latest command (0 before the first).
  [[nodiscard]] double command_time_s() const noexcept { return command_time_s_; }
  /// The impedance hand; nullptr with the kinematic hand.
  [[nodiscard]] const simulation::HandImpedance* hand() const noexcept { return hand_ ? &*hand_ : nullptr; }

  /// Commands scaled down by the force or a motor torque limit.
  [[nodiscard]] std::uint64_t limited_commands() const noexcept { return limited_commands_; }
  /// Evaluations where the hand (or the pushed tool point) lay outside the workspace box.
  [[nodiscard]] std::uint64_t workspace_clamps() const noexcept { return workspace_clamps_; }
  /// Evaluations where the inverse kinematics failed and the last angles were held.
  [[nodiscard]] std::uint64_t unreachable_count() const noexcept { return unreachable_count_; }

  /// The per-motor torque limit in effect (configured or derived).
  [[nodiscard]] double max_motor_torque_Nm() const noexcept { return max_motor_torque_Nm_; }
  /// The construction-time survey of the workspace box.
  [[nodiscard]] const WorkspaceSurvey& workspace_survey() const noexcept { return survey_; }
  /// The angles at the workspace centre.
  [[nodiscard]] const Eigen::Vector3d& nominal_angles_rad() const noexcept { return q_nominal_rad_; }

 private:
  /// The force the torques in effect make with the tool at p_D_m (zero where singular).
  [[nodiscard]] Eigen::Vector3d tool_force_D_N(const Eigen::Vector3d& p_D_m) const;
  [[nodiscard]] Eigen::Vector3d kinematic_tool_D_m(const Eigen::Vector3d& p_D_hand_m, bool& clamped);
  [[nodiscard]] Eigen::Vector3d impedance_tool_D_m(double dt_s, const Eigen::Vector3d& p_D_hand_m, bool& clamped);

  DeltaSimConfig config_;
  WorkspaceSurvey survey_;
  double max_motor_torque_Nm_ = 0.0;
  Eigen::Vector3d q_nominal_rad_ = Eigen::Vector3d::Zero();

  bool started_ = false;
  bool velocity_valid_ = false;  ///< a previous evaluation since start() to difference against
  double time_s_ = 0.0;
  bool has_command_ = false;
  double command_time_s_ = 0.0;
  bool watchdog_stopped_ = true;
  std::optional<simulation::HandImpedance> hand_;
  bool hand_placed_ = false;  ///< the impedance hand was put at the intended hand since start()

  Eigen::Vector3d q_rad_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d J_D_ = Eigen::Matrix3d::Identity();  ///< at q_rad_
  Eigen::Vector3d p_D_tool_m_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d v_D_tool_mps_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d tau_command_Nm_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d tau_applied_Nm_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_D_N_ = Eigen::Vector3d::Zero();
  std::uint64_t limited_commands_ = 0;
  std::uint64_t workspace_clamps_ = 0;
  std::uint64_t unreachable_count_ = 0;
};

}  // namespace mhd::sim_delta
