#pragma once
// A simulated PHANToM Premium 1.5 held by the simulated user (docs/sim_phantom.md).
//
// The tool point (HIP) follows the user's hand. Each simulate_until(t) takes the hand in
// the device frame P (the plugin shell transforms the world's hand with the base pose and
// the rig's fixed transforms, see X_W_phantom()), clamps it to the device's workspace box,
// and models the hand as a stiff spring: the commanded joint torques make a tool force
// F_P = J_P^-T tau (J_P at the hand's configuration), which pushes the tool by
// F_P / hand_stiffness. The pushed point is clamped to the workspace again and solved by
// the closed-form inverse kinematics; when it has no solution within the joint limits the
// last reachable angles are held (counted). Joint angles are quantised to the encoder
// resolution and the reported HIP is the forward kinematics of the quantised angles.
// Torques received more than command_timeout_s before t count as zero (the device's own
// command watchdog): a stalled host must not leave force applied. Not thread-safe; nothing here is random.

#include "kinematics/base_pose.h"
#include "kinematics/phantom_kinematics.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <optional>

namespace mhd::sim_phantom {

/// scenes/rigs/pomhi.xml: the phantom frame in the robot frame (eq. 4.4).
[[nodiscard]] Eigen::Isometry3d pomhi_X_robot_phantom();
/// scenes/rigs/pomhi.xml: the floor frame "base" in the robot frame.
[[nodiscard]] Eigen::Isometry3d pomhi_X_robot_base();

struct PhantomSimConfig {
  PhantomModel device = phantom_premium_1_5();
  double max_force_N = 8.5;
  double hand_stiffness_N_per_m = 2000.0;
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

  /// X_W_P: the device frame in the world for a planar base pose (world -> base -> robot -> phantom).
  [[nodiscard]] Eigen::Isometry3d X_W_phantom(const BasePose& base) const;
  /// A world point in P.
  [[nodiscard]] Eigen::Vector3d p_P_from_W(const BasePose& base, const Eigen::Vector3d& p_W) const;

  /// Time origin at t_s; forgets commands, keeps the angles (initially those of the
  /// workspace centre).
  void start(double t_s);
  /// Joint torques received at host time t_received_s. Throws std::invalid_argument
  /// "device command has a non-finite value" for NaN / inf.
  void command(const Eigen::Vector3d& tau_Nm, double t_received_s);
  /// Evaluates the device at host time t_s with the hand at hand_P_m (in P). A t_s before
  /// the current time is ignored. Precondition: started; throws std::logic_error otherwise.
  void simulate_until(double t_s, const Eigen::Vector3d& hand_P_m);

  [[nodiscard]] const PhantomSimConfig& config() const { return config_; }
  [[nodiscard]] double time_s() const { return time_s_; }
  [[nodiscard]] const Eigen::Vector3d& joint_angles_rad() const { return q_reported_; }
  /// Forward kinematics of joint_angles_rad().
  [[nodiscard]] const Eigen::Vector3d& p_P_hip_m() const { return p_hip_P_; }
  /// The torques in effect at time_s() (zero when none or stale) and the tool force they made.
  [[nodiscard]] const Eigen::Vector3d& applied_torques_Nm() const { return tau_applied_; }
  [[nodiscard]] const Eigen::Vector3d& force_P_N() const { return force_P_; }
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

  PhantomSimConfig config_;
  Eigen::Isometry3d X_base_phantom_ = Eigen::Isometry3d::Identity();
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
  std::uint64_t workspace_clamps_ = 0;
  std::uint64_t unreachable_count_ = 0;
};

}  // namespace mhd::sim_phantom
