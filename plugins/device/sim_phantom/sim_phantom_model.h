#pragma once
// A simulated PHANToM Premium 1.5 held by the simulated user (docs/sim_phantom.md).
//
// The tool point (HIP) follows the user's hand. Each simulate_until(t) takes where the user
// means the hand to be (the world's hand, seen from the device with the base pose and the
// rig's fixed transforms, see X_W_phantom()). The commanded joint torques make a tool force
// F_P = J_P^-T tau (J_P at the hand's configuration). Two hand models (HandModel):
//   kinematic: the tool is at the intended hand, clamped to the workspace box, pushed by
//     F_P / hand_stiffness (a stiff, massless spring);
//   impedance: the hand is a mass-spring-damper (simulation::HandImpedance) in the world
//     frame, pulled to the intended hand and pushed by the tool force held since the last
//     evaluation (the device's zero-order hold); the tool is where the hand is.
// The tool point is clamped to the workspace box and solved by
// the closed-form inverse kinematics; when it has no solution within the joint limits the
// last reachable angles are held (counted). Joint angles are quantised to the encoder
// resolution and the reported HIP is the forward kinematics of the quantised angles.
// Torques received more than command_timeout_s before t count as zero (the device's own
// command watchdog): a stalled host must not leave force applied. Not thread-safe; nothing here is random.

#include "kinematics/base_pose.h"
#include "kinematics/phantom_kinematics.h"
#include "simulation/hand_impedance.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <optional>

namespace mhd::sim_phantom {

/// scenes/rigs/pomhi.xml: the phantom frame in the robot frame (eq. 4.4).
[[nodiscard]] Eigen::Isometry3d pomhi_X_robot_phantom();
/// scenes/rigs/pomhi.xml: the floor frame "base" in the robot frame.
[[nodiscard]] Eigen::Isometry3d pomhi_X_robot_base();

enum class HandModel { Kinematic, Impedance };

struct PhantomSimConfig {
  PhantomModel device = phantom_premium_1_5();
  double max_force_N = 8.5;
  HandModel hand_model = HandModel::Kinematic;
  /// Kinematic hand: its spring.
  double hand_stiffness_N_per_m = 2000.0;
  /// Impedance hand (mass, stiffness, damping; docs/simulated_hand.md).
  simulation::HandImpedanceParams hand_impedance;
  /// The device's own command watchdog: torques older than this count as zero.
  double command_timeout_s = 0.02;
  /// Tool-point resolution; each joint angle is quantised to resolution / (l1 + l2)
  /// (the angle step that moves the tool by at most this much). 0: no quantisation.
  double position_resolution_m = 0.03e-3;
  Eigen::Isometry3d X_robot_phantom = pomhi_X_robot_phantom();
  Eigen::Isometry3d X_robot_base = pomhi_X_robot_base();
};

class PhantomSimModel {
 public:
  /// Throws std::invalid_argument for a non-positive / non-finite setting.
  explicit PhantomSimModel(const PhantomSimConfig& config);

  /// X_W_P: the device frame in the world for a planar base pose (world -> base -> robot ->
  /// lift -> phantom); the lift raises the arm `lift_m` along the robot's z (kinematics/rig.h).
  [[nodiscard]] Eigen::Isometry3d X_W_phantom(const BasePose& base, double lift_m = 0.0) const;
  /// A world point in P.
  [[nodiscard]] Eigen::Vector3d p_P_from_W(const BasePose& base, const Eigen::Vector3d& p_W,
                                           double lift_m = 0.0) const;

  /// Time origin at t_s; forgets commands, keeps the angles (initially those of the
  /// workspace centre).
  void start(double t_s);
  /// Joint torques received at host time t_received_s. Throws std::invalid_argument
  /// "device command has a non-finite value" for NaN / inf.
  void command(const Eigen::Vector3d& tau_Nm, double t_received_s);
  /// Evaluates the device at host time t_s with the base at `base` and the user meaning the
  /// hand to be at hand_W_m, the base's lift at `lift_m`. A t_s before the current time is
  /// ignored. Precondition: started; throws std::logic_error otherwise.
  void simulate_until(double t_s, const BasePose& base, const Eigen::Vector3d& hand_W_m, double lift_m = 0.0);
  /// The same with the base at the origin (BasePose{}) and the hand given in P.
  void simulate_until(double t_s, const Eigen::Vector3d& hand_P_m);

  [[nodiscard]] const PhantomSimConfig& config() const { return config_; }
  [[nodiscard]] double time_s() const { return time_s_; }
  [[nodiscard]] const Eigen::Vector3d& joint_angles_rad() const { return q_reported_; }
  /// Forward kinematics of joint_angles_rad().
  [[nodiscard]] const Eigen::Vector3d& p_P_hip_m() const { return p_hip_P_; }
  /// The torques in effect at time_s() (zero when none or stale) and the tool force they made.
  [[nodiscard]] const Eigen::Vector3d& applied_torques_Nm() const { return tau_applied_; }
  [[nodiscard]] const Eigen::Vector3d& force_P_N() const { return force_P_; }
  /// The impedance hand; nullptr with the kinematic hand.
  [[nodiscard]] const simulation::HandImpedance* hand() const { return hand_ ? &*hand_ : nullptr; }
  [[nodiscard]] bool watchdog_stopped() const { return watchdog_stopped_; }
  /// Host time of the latest command (0 before the first).
  [[nodiscard]] double command_time_s() const { return command_time_s_; }
  /// Evaluations where the hand (or the pushed tool point) lay outside the workspace box.
  [[nodiscard]] std::uint64_t workspace_clamps() const { return workspace_clamps_; }
  /// Evaluations where the inverse kinematics failed and the last angles were held.
  [[nodiscard]] std::uint64_t unreachable_count() const { return unreachable_count_; }

  /// Per-joint torque limits: 8.5 N in any direction at the nominal configuration (the
  /// workspace centre) needs |tau_j| <= max_force_N * |J_P column j|.
  [[nodiscard]] Eigen::Vector3d max_joint_torques_Nm() const;
  /// The angles at the workspace centre.
  [[nodiscard]] const Eigen::Vector3d& nominal_angles_rad() const { return q_nominal_; }

 private:
  [[nodiscard]] Eigen::Vector3d clamp(const Eigen::Vector3d& p_P, bool& clamped) const;
  /// IK; on failure the last reachable angles (counted).
  [[nodiscard]] Eigen::Vector3d solve(const Eigen::Vector3d& p_P, bool& failed) const;
  [[nodiscard]] Eigen::Vector3d quantise(const Eigen::Vector3d& q) const;
  /// The tool force the torques in effect make with the tool at p_P (zero if singular).
  [[nodiscard]] Eigen::Vector3d tool_force_P(const Eigen::Vector3d& p_P) const;
  void evaluate(double t_s, const BasePose& base, const Eigen::Vector3d& hand_W_m, const Eigen::Vector3d& hand_P_m);
  /// The tool point in P after the hand model acted; `clamped` when the box cut it.
  [[nodiscard]] Eigen::Vector3d kinematic_tool_P(const Eigen::Vector3d& hand_P_m, bool& clamped);
  [[nodiscard]] Eigen::Vector3d impedance_tool_P(double dt_s, const BasePose& base, const Eigen::Vector3d& hand_W_m,
                                                 bool& clamped);

  PhantomSimConfig config_;
  Eigen::Isometry3d X_base_robot_ = Eigen::Isometry3d::Identity();
  double lift_m_ = 0.0;  ///< the lift's height at the last evaluation
  Eigen::Vector3d q_nominal_ = Eigen::Vector3d::Zero();
  double angle_step_rad_ = 0.0;

  bool started_ = false;
  double time_s_ = 0.0;
  std::optional<Eigen::Vector3d> tau_command_;
  double command_time_s_ = 0.0;
  bool watchdog_stopped_ = true;

  Eigen::Vector3d q_reachable_ = Eigen::Vector3d::Zero();  ///< last IK solution
  Eigen::Vector3d q_reported_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_hip_P_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d tau_applied_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_P_ = Eigen::Vector3d::Zero();
  std::optional<simulation::HandImpedance> hand_;  ///< the impedance hand
  bool hand_placed_ = false;  ///< the impedance hand was put at the intended hand since start()
  std::uint64_t workspace_clamps_ = 0;
  std::uint64_t unreachable_count_ = 0;
};

}  // namespace mhd::sim_phantom
