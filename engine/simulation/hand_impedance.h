#pragma once
// The simulated user's hand as an impedance (Hogan 1985): a mass held by a spring and a
// damper to where the user means the hand to be (the intended path), pushed by the
// force at the handle it holds:
//   m a = F_handle + k (p_intended - p) + b (v_intended - v).
// It is the equilibrium-point model of the arm; docs/simulated_hand.md cites the
// parameters. Integrated by the trapezoidal rule in sub-steps no longer than
// max_substep_s, the intended position interpolated linearly across a step. The
// intended path arrives as samples (the user thread writes it), so its velocity is their
// finite difference, low-passed with time constant intent_velocity_time_constant_s.
// Allocation-free and lock-free: the simulated device advances it on the haptic thread.

#include <Eigen/Core>

namespace mhd::simulation {

struct HandImpedanceParams {
  /// van Beek et al. 2015, one participant's postural arm at a handle (docs/simulated_hand.md).
  double mass_kg = 0.55;
  double stiffness_N_per_m = 135.0;
  double damping_Ns_per_m = 6.5;
  double max_substep_s = 20e-6;
  double intent_velocity_time_constant_s = 0.02;
  /// A longer step (a stalled host) restarts the hand at rest in equilibrium.
  double max_step_s = 0.1;
  /// An intended hand that leaps further in one step was placed anew (the world's hand is
  /// the origin until the user first writes it), not moved: the hand restarts there at rest.
  double max_intent_jump_m = 0.1;
};

class HandImpedance {
 public:
  /// Throws std::invalid_argument naming the first parameter that is not positive and finite.
  explicit HandImpedance(const HandImpedanceParams& params);

  /// The hand at rest at p_W_m, and the intended path there too.
  void reset(const Eigen::Vector3d& p_W_m) noexcept;
  /// Advances by dt_s (<= 0: nothing) with the force F_W_N held on the hand during the
  /// step and the intended path ending at p_W_intended_m. Inputs must be finite.
  void advance(double dt_s, const Eigen::Vector3d& p_W_intended_m, const Eigen::Vector3d& F_W_N) noexcept;

  [[nodiscard]] const Eigen::Vector3d& p_W_m() const noexcept { return p_W_m_; }
  [[nodiscard]] const Eigen::Vector3d& v_W_mps() const noexcept { return v_W_mps_; }
  [[nodiscard]] const Eigen::Vector3d& p_W_intended_m() const noexcept { return p_W_intended_m_; }
  [[nodiscard]] const Eigen::Vector3d& v_W_intended_mps() const noexcept { return v_W_intended_mps_; }
  /// Where the hand rests under a constant force: p_intended + F / k.
  [[nodiscard]] Eigen::Vector3d equilibrium_W_m(const Eigen::Vector3d& F_W_N) const noexcept;
  [[nodiscard]] const HandImpedanceParams& params() const noexcept { return params_; }

 private:
  HandImpedanceParams params_;
  Eigen::Vector3d p_W_m_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d v_W_mps_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_W_intended_m_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d v_W_intended_mps_ = Eigen::Vector3d::Zero();
};

}  // namespace mhd::simulation
