#include "simulation/hand_impedance.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace mhd::simulation {
namespace {

void require_positive(double value, const char* name) {
  if (!(value > 0.0) || !std::isfinite(value)) throw std::invalid_argument(std::string(name) + " must be a positive number");
}

}  // namespace

HandImpedance::HandImpedance(const HandImpedanceParams& params) : params_(params) {
  require_positive(params.mass_kg, "hand mass_kg");
  require_positive(params.stiffness_N_per_m, "hand stiffness_N_per_m");
  require_positive(params.damping_Ns_per_m, "hand damping_Ns_per_m");
  require_positive(params.max_substep_s, "hand max_substep_s");
  require_positive(params.intent_velocity_time_constant_s, "hand intent_velocity_time_constant_s");
  require_positive(params.max_step_s, "hand max_step_s");
  require_positive(params.max_intent_jump_m, "hand max_intent_jump_m");
}

void HandImpedance::reset(const Eigen::Vector3d& p_W_m) noexcept {
  p_W_m_ = p_W_m;
  p_W_intended_m_ = p_W_m;
  v_W_mps_.setZero();
  v_W_intended_mps_.setZero();
}

Eigen::Vector3d HandImpedance::equilibrium_W_m(const Eigen::Vector3d& F_W_N) const noexcept {
  return p_W_intended_m_ + F_W_N / params_.stiffness_N_per_m;
}

void HandImpedance::advance(double dt_s, const Eigen::Vector3d& p_W_intended_m, const Eigen::Vector3d& F_W_N) noexcept {
  if (!(dt_s > 0.0)) return;
  const Eigen::Vector3d p_start = p_W_intended_m_;
  if ((p_W_intended_m - p_start).norm() > params_.max_intent_jump_m) {
    reset(p_W_intended_m);
    return;
  }
  if (dt_s > params_.max_step_s) {
    // Too long to integrate step by step; by then a damped hand has settled.
    reset(p_W_intended_m);
    p_W_m_ = equilibrium_W_m(F_W_N);
    return;
  }
  const double alpha = 1.0 - std::exp(-dt_s / params_.intent_velocity_time_constant_s);
  v_W_intended_mps_ += alpha * ((p_W_intended_m - p_start) / dt_s - v_W_intended_mps_);
  p_W_intended_m_ = p_W_intended_m;

  const double m = params_.mass_kg;
  const double k = params_.stiffness_N_per_m;
  const double b = params_.damping_Ns_per_m;
  const int n = static_cast<int>(std::ceil(dt_s / params_.max_substep_s - 1e-9));
  const double h = dt_s / n;
  // Trapezoidal rule, solved in closed form (the model is linear): second order and
  // symmetric in time. Semi-implicit Euler would place the position h/2 early, a phase
  // lead that hides part of the sampled wall's delay and overstates its stable stiffness.
  const double c = h / (2.0 * m);
  const double g = k * h / 2.0 + b;
  for (int i = 0; i < n; ++i) {
    const double mid = (static_cast<double>(i) + 0.5) / n;
    const Eigen::Vector3d u = F_W_N + k * (p_start + mid * (p_W_intended_m - p_start)) + b * v_W_intended_mps_;
    const Eigen::Vector3d v_next = (v_W_mps_ + c * (2.0 * u - 2.0 * k * p_W_m_ - g * v_W_mps_)) / (1.0 + c * g);
    p_W_m_ += 0.5 * h * (v_W_mps_ + v_next);
    v_W_mps_ = v_next;
  }
}

}  // namespace mhd::simulation
