#include "sim_delta_model.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace mhd::sim_delta {
namespace {

constexpr double kTimeTolerance_s = 1e-9;

void require_positive(double value, const char* name) {
  if (!(value > 0.0) || !std::isfinite(value)) throw std::invalid_argument(std::string(name) + " must be a positive number");
}

}  // namespace

DeltaSimModel::DeltaSimModel(const DeltaSimConfig& config) : config_(config) {
  const DeltaGeometry& g = config.geometry;
  require_positive(g.base_radius_m, "base_radius_m");
  require_positive(g.effector_radius_m, "effector_radius_m");
  require_positive(g.upper_arm_m, "upper_arm_m");
  require_positive(g.forearm_m, "forearm_m");
  for (const double phi : g.arm_angles_rad) {
    if (!std::isfinite(phi)) throw std::invalid_argument("arm_angles_rad must be finite");
  }
  if (!std::isfinite(config.limits.min_rad) || !std::isfinite(config.limits.max_rad) ||
      !(config.limits.min_rad < config.limits.max_rad)) {
    throw std::invalid_argument("joint limits must be finite with min_rad < max_rad");
  }
  if (!config.workspace.min_D_m.allFinite() || !config.workspace.max_D_m.allFinite() ||
      !(config.workspace.min_D_m.array() < config.workspace.max_D_m.array()).all()) {
    throw std::invalid_argument("the workspace box must be finite with min < max on every axis");
  }
  require_positive(config.max_force_N, "max_force_N");
  if (config.max_motor_torque_Nm) require_positive(*config.max_motor_torque_Nm, "max_motor_torque_Nm");
  if (config.workspace_samples_per_axis < 2) throw std::invalid_argument("workspace_samples_per_axis must be at least 2");
  require_positive(config.max_jacobian_condition, "max_jacobian_condition");
  require_positive(config.hand_stiffness_N_per_m, "hand_stiffness_N_per_m");
  require_positive(config.command_timeout_s, "command_timeout_s");
  if (config.hand_model == HandModel::Impedance) hand_.emplace(config.hand_impedance);

  survey_ = survey_workspace(g, config.limits, config.workspace, config.workspace_samples_per_axis,
                             config.max_jacobian_condition);
  if (!survey_.all_reached()) throw std::invalid_argument("the workspace box is not reachable everywhere");
  max_motor_torque_Nm_ = config.max_motor_torque_Nm.value_or(config.max_force_N * survey_.max_jacobian_column_m);

  // The survey reached the centre's grid neighbours; the centre itself may fall between them.
  const std::optional<Eigen::Vector3d> q = delta_inverse_kinematics(g, config.limits, config.workspace.center_D_m());
  const std::optional<Eigen::Matrix3d> J = q ? delta_jacobian(g, *q) : std::nullopt;
  if (!J) throw std::invalid_argument("the workspace box is not reachable everywhere");
  q_nominal_rad_ = *q;
  q_rad_ = *q;
  J_D_ = *J;
  p_D_tool_m_ = delta_forward_kinematics(g, q_rad_).value_or(config.workspace.center_D_m());
}

void DeltaSimModel::start(double t_s) {
  if (!std::isfinite(t_s)) throw std::invalid_argument("start time must be finite");
  started_ = true;
  velocity_valid_ = false;
  time_s_ = t_s;
  has_command_ = false;
  watchdog_stopped_ = true;
  hand_placed_ = false;
  tau_command_Nm_.setZero();
  tau_applied_Nm_.setZero();
  force_D_N_.setZero();
  v_D_tool_mps_.setZero();
}

void DeltaSimModel::command(const Eigen::Vector3d& F_D_N, double t_received_s) {
  if (!F_D_N.allFinite() || !std::isfinite(t_received_s)) {
    throw std::invalid_argument("device command has a non-finite value");
  }
  // Both limits scale the whole command so the force keeps its direction; clipping one
  // motor alone would turn the force.
  bool limited = false;
  Eigen::Vector3d F = F_D_N;
  const double force_N = F.norm();
  if (force_N > config_.max_force_N) {
    F *= config_.max_force_N / force_N;
    limited = true;
  }
  Eigen::Vector3d tau = delta_motor_torques_Nm(J_D_, F);
  const double largest_Nm = tau.cwiseAbs().maxCoeff();
  if (largest_Nm > max_motor_torque_Nm_) {
    tau *= max_motor_torque_Nm_ / largest_Nm;
    limited = true;
  }
  if (limited) ++limited_commands_;
  tau_command_Nm_ = tau;
  command_time_s_ = t_received_s;
  has_command_ = true;
}

Eigen::Vector3d DeltaSimModel::tool_force_D_N(const Eigen::Vector3d& p_D_m) const {
  if (tau_applied_Nm_.isZero(0.0)) return Eigen::Vector3d::Zero();
  const std::optional<Eigen::Vector3d> q = delta_inverse_kinematics(config_.geometry, config_.limits, p_D_m);
  const std::optional<Eigen::Matrix3d> J = q ? delta_jacobian(config_.geometry, *q) : std::optional<Eigen::Matrix3d>(J_D_);
  if (!J) return Eigen::Vector3d::Zero();
  return delta_tool_force_N(*J, tau_applied_Nm_).value_or(Eigen::Vector3d::Zero());
}

Eigen::Vector3d DeltaSimModel::kinematic_tool_D_m(const Eigen::Vector3d& p_D_hand_m, bool& clamped) {
  const Eigen::Vector3d hand = config_.workspace.clamp(p_D_hand_m, clamped);
  force_D_N_ = tool_force_D_N(hand);
  return config_.workspace.clamp(hand + force_D_N_ / config_.hand_stiffness_N_per_m, clamped);
}

Eigen::Vector3d DeltaSimModel::impedance_tool_D_m(double dt_s, const Eigen::Vector3d& p_D_hand_m, bool& clamped) {
  if (!hand_placed_) {
    hand_->reset(p_D_hand_m);
    hand_placed_ = true;
    dt_s = 0.0;
  }
  // The torques held since the last evaluation push the tool where the hand was then.
  bool ignored = false;
  force_D_N_ = tool_force_D_N(config_.workspace.clamp(hand_->p_W_m(), ignored));
  hand_->advance(dt_s, p_D_hand_m, force_D_N_);
  return config_.workspace.clamp(hand_->p_W_m(), clamped);
}

void DeltaSimModel::simulate_until(double t_s, const Eigen::Vector3d& p_D_hand_m) {
  if (!started_) throw std::logic_error("simulate_until before start");
  if (!std::isfinite(t_s)) throw std::invalid_argument("simulation time must be finite");
  if (!p_D_hand_m.allFinite()) throw std::invalid_argument("hand position must be finite");
  if (t_s < time_s_) return;
  const double dt_s = t_s - time_s_;
  time_s_ = t_s;

  const bool fresh = has_command_ && command_time_s_ <= t_s + kTimeTolerance_s &&
                     t_s - command_time_s_ <= config_.command_timeout_s + kTimeTolerance_s;
  watchdog_stopped_ = !fresh;
  tau_applied_Nm_ = fresh ? tau_command_Nm_ : Eigen::Vector3d::Zero();

  bool clamped = false;
  const Eigen::Vector3d target =
      hand_ ? impedance_tool_D_m(dt_s, p_D_hand_m, clamped) : kinematic_tool_D_m(p_D_hand_m, clamped);
  if (clamped) ++workspace_clamps_;

  const std::optional<Eigen::Vector3d> q = delta_inverse_kinematics(config_.geometry, config_.limits, target);
  const std::optional<Eigen::Matrix3d> J = q ? delta_jacobian(config_.geometry, *q) : std::nullopt;
  const std::optional<Eigen::Vector3d> p = q ? delta_forward_kinematics(config_.geometry, *q) : std::nullopt;
  if (!J || !p) {
    ++unreachable_count_;
    if (dt_s > 0.0) v_D_tool_mps_.setZero();  // held still
    return;
  }
  q_rad_ = *q;
  J_D_ = *J;
  if (velocity_valid_ && dt_s > 0.0) v_D_tool_mps_ = (*p - p_D_tool_m_) / dt_s;
  p_D_tool_m_ = *p;
  velocity_valid_ = true;
}

}  // namespace mhd::sim_delta
