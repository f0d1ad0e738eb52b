#include "sim_phantom_model.h"

#include "geometry/pose.h"

#include <Eigen/LU>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace mhd::sim_phantom {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kTimeTolerance_s = 1e-9;

void require_positive(double value, const char* name) {
  if (!(value > 0.0) || !std::isfinite(value)) throw std::invalid_argument(std::string(name) + " must be a positive number");
}

bool finite_pose(const Eigen::Isometry3d& X) { return X.matrix().allFinite(); }

}  // namespace

Eigen::Isometry3d pomhi_X_robot_phantom() {
  return pose_from_xyz_rpy(Eigen::Vector3d(-1.6, -235.8, 59.2) / 1000.0, Eigen::Vector3d(90.0, 0.0, 0.0) * kDeg);
}

Eigen::Isometry3d pomhi_X_robot_base() {
  return pose_from_xyz_rpy(Eigen::Vector3d(0.0, 0.0, -810.8) / 1000.0, Eigen::Vector3d(90.0, 0.0, 0.0) * kDeg);
}

PhantomSimModel::PhantomSimModel(const PhantomSimConfig& config) : config_(config) {
  require_positive(config.max_force_N, "max_force_N");
  require_positive(config.hand_stiffness_N_per_m, "hand_stiffness_N_per_m");
  require_positive(config.command_timeout_s, "command_timeout_s");
  if (!(config.position_resolution_m >= 0.0) || !std::isfinite(config.position_resolution_m)) {
    throw std::invalid_argument("position_resolution_m must be a non-negative number");
  }
  if (!finite_pose(config.X_robot_phantom) || !finite_pose(config.X_robot_base)) {
    throw std::invalid_argument("rig transforms must be finite");
  }
  if (config.hand_model == HandModel::Impedance) hand_.emplace(config.hand_impedance);
  const PhantomGeometry& g = config.device.geometry;
  require_positive(g.l1_m, "l1_m");
  require_positive(g.l2_m, "l2_m");
  X_base_robot_ = config.X_robot_base.inverse(Eigen::Isometry);
  angle_step_rad_ = config.position_resolution_m / (g.l1_m + g.l2_m);
  const PhantomIkSolution nominal = phantom_inverse_kinematics(config.device, config.device.workspace.center_P_m());
  if (!nominal.ok()) throw std::invalid_argument("the workspace centre is not reachable");
  q_nominal_ = nominal.q_rad;
  q_reachable_ = q_nominal_;
  q_reported_ = quantise(q_nominal_);
  p_hip_P_ = phantom_tool_position(g, q_reported_);
}

Eigen::Isometry3d PhantomSimModel::X_W_phantom(const BasePose& base, double lift_m) const {
  return pose_from_base(base) * X_base_robot_ * Eigen::Translation3d(0.0, 0.0, lift_m) * config_.X_robot_phantom;
}

Eigen::Vector3d PhantomSimModel::p_P_from_W(const BasePose& base, const Eigen::Vector3d& p_W, double lift_m) const {
  return X_W_phantom(base, lift_m).inverse(Eigen::Isometry) * p_W;
}

void PhantomSimModel::start(double t_s) {
  if (!std::isfinite(t_s)) throw std::invalid_argument("start time must be finite");
  started_ = true;
  time_s_ = t_s;
  tau_command_.reset();
  watchdog_stopped_ = true;
  hand_placed_ = false;
  tau_applied_.setZero();
  force_P_.setZero();
}

void PhantomSimModel::command(const Eigen::Vector3d& tau_Nm, double t_received_s) {
  if (!tau_Nm.allFinite() || !std::isfinite(t_received_s)) {
    throw std::invalid_argument("device command has a non-finite value");
  }
  tau_command_ = tau_Nm;
  command_time_s_ = t_received_s;
}

Eigen::Vector3d PhantomSimModel::clamp(const Eigen::Vector3d& p_P, bool& clamped) const {
  const WorkspaceBox& box = config_.device.workspace;
  const Eigen::Vector3d c = p_P.cwiseMax(box.min_P_m).cwiseMin(box.max_P_m);
  if (c != p_P) clamped = true;
  return c;
}

Eigen::Vector3d PhantomSimModel::solve(const Eigen::Vector3d& p_P, bool& failed) const {
  const PhantomIkSolution ik = phantom_inverse_kinematics(config_.device, p_P);
  if (ik.ok()) return ik.q_rad;
  failed = true;
  return q_reachable_;
}

Eigen::Vector3d PhantomSimModel::quantise(const Eigen::Vector3d& q) const {
  if (angle_step_rad_ <= 0.0) return q;
  return (q / angle_step_rad_).array().round().matrix() * angle_step_rad_;
}

Eigen::Vector3d PhantomSimModel::tool_force_P(const Eigen::Vector3d& p_P) const {
  if (tau_applied_.isZero(0.0)) return Eigen::Vector3d::Zero();
  // The force the motors make at the tool: tau = J^T F.
  bool ignored = false;
  const Eigen::Vector3d q = solve(p_P, ignored);
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(phantom_position_jacobian(config_.device.geometry, q).transpose());
  if (!lu.isInvertible()) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d F = lu.solve(tau_applied_);
  return F.allFinite() ? F : Eigen::Vector3d::Zero();
}

Eigen::Vector3d PhantomSimModel::kinematic_tool_P(const Eigen::Vector3d& hand_P_m, bool& clamped) {
  const Eigen::Vector3d hand = clamp(hand_P_m, clamped);
  force_P_ = tool_force_P(hand);
  return clamp(hand + force_P_ / config_.hand_stiffness_N_per_m, clamped);
}

Eigen::Vector3d PhantomSimModel::impedance_tool_P(double dt_s, const BasePose& base, const Eigen::Vector3d& hand_W_m,
                                                  bool& clamped) {
  const Eigen::Isometry3d X_W_P = X_W_phantom(base, lift_m_);
  if (!hand_placed_) {
    hand_->reset(hand_W_m);
    hand_placed_ = true;
    dt_s = 0.0;
  }
  // The torques held since the last evaluation push the tool where the hand was then.
  bool ignored = false;
  force_P_ = tool_force_P(clamp(X_W_P.inverse(Eigen::Isometry) * hand_->p_W_m(), ignored));
  hand_->advance(dt_s, hand_W_m, X_W_P.linear() * force_P_);
  return clamp(X_W_P.inverse(Eigen::Isometry) * hand_->p_W_m(), clamped);
}

void PhantomSimModel::simulate_until(double t_s, const BasePose& base, const Eigen::Vector3d& hand_W_m,
                                     double lift_m) {
  if (!hand_W_m.allFinite()) throw std::invalid_argument("hand position must be finite");
  if (!std::isfinite(lift_m)) throw std::invalid_argument("lift height must be finite");
  lift_m_ = lift_m;
  evaluate(t_s, base, hand_W_m, p_P_from_W(base, hand_W_m, lift_m));
}

void PhantomSimModel::simulate_until(double t_s, const Eigen::Vector3d& hand_P_m) {
  if (!hand_P_m.allFinite()) throw std::invalid_argument("hand position must be finite");
  lift_m_ = 0.0;
  evaluate(t_s, BasePose{}, X_W_phantom(BasePose{}) * hand_P_m, hand_P_m);
}

void PhantomSimModel::evaluate(double t_s, const BasePose& base, const Eigen::Vector3d& hand_W_m,
                               const Eigen::Vector3d& hand_P_m) {
  if (!started_) throw std::logic_error("simulate_until before start");
  if (!std::isfinite(t_s)) throw std::invalid_argument("simulation time must be finite");
  if (t_s < time_s_) return;
  const double dt_s = t_s - time_s_;
  time_s_ = t_s;

  // Torques in effect: the latest command, unless it is older than command_timeout_s.
  const bool fresh = tau_command_ && command_time_s_ <= t_s + kTimeTolerance_s &&
                     t_s - command_time_s_ <= config_.command_timeout_s + kTimeTolerance_s;
  watchdog_stopped_ = !fresh;
  tau_applied_ = fresh ? *tau_command_ : Eigen::Vector3d::Zero();

  bool clamped = false;
  const Eigen::Vector3d target =
      hand_ ? impedance_tool_P(dt_s, base, hand_W_m, clamped) : kinematic_tool_P(hand_P_m, clamped);
  if (clamped) ++workspace_clamps_;

  bool failed = false;
  q_reachable_ = solve(target, failed);
  if (failed) ++unreachable_count_;
  q_reported_ = quantise(q_reachable_);
  p_hip_P_ = phantom_tool_position(config_.device.geometry, q_reported_);
}

Eigen::Vector3d PhantomSimModel::max_joint_torques_Nm() const {
  const Eigen::Matrix3d J = phantom_position_jacobian(config_.device.geometry, q_nominal_);
  return config_.max_force_N * J.colwise().norm().transpose();
}

}  // namespace mhd::sim_phantom
