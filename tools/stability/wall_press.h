#pragma once
// The closed loop of a sampled virtual wall and the impedance hand, without threads: the
// simulated PHANToM (sim_phantom_model, hand_model impedance) held by the hand, read
// every T = 1 / rate_hz, the god-object proxy against a flat wall of stiffness K and
// damping B, the force sent back as tau = J^T F and held for the next T (what the
// haptic thread does each tick). The user means to press 10 mm behind the wall. It says
// whether the contact settles (docs/simulated_hand.md, "Stability").

#include "sim_phantom_model.h"

#include "simulation/hand_impedance.h"

namespace mhd::stability {

struct WallPressSettings {
  double rate_hz = 1000.0;
  double wall_stiffness_N_per_m = 1000.0;
  double wall_damping_Ns_per_m = 0.0;
  simulation::HandImpedanceParams hand;
  /// Encoder resolution at the tool; 0 (exact angles) as in Colgate and Schenkel's analysis.
  double position_resolution_m = 0.0;
  double press_depth_m = 0.01;  ///< where the user means the hand, behind the surface
  double duration_s = 6.0;
  double window_s = 1.0;        ///< the last two windows of this length are compared
};

struct WallPressFigures {
  /// The force's peak-to-peak along the wall normal in the last two windows.
  double force_ptp_previous_N = 0.0;
  double force_ptp_last_N = 0.0;
  double mean_force_last_N = 0.0;
  double max_force_N = 0.0;
  /// Settles: the last window's ripple is below 1 mN or under 0.9 of the one before. Near
  /// the bound the contact mode decays slowly (the sampled wall's negative damping K T / 2
  /// eats the hand's b), so windows of a second are compared; beyond it the oscillation
  /// grows until the hand bounces off the wall each cycle, a limit cycle (ratio ~1).
  bool stable = false;
};

[[nodiscard]] WallPressFigures press_wall(const WallPressSettings& settings);

/// Colgate and Schenkel (1997): a virtual wall K, B sampled with period T on a device of
/// physical damping b is passive when b > K T / 2 + |B|, i.e. K < 2 (b - |B|) / T.
[[nodiscard]] double passivity_bound_N_per_m(double physical_damping_Ns_per_m, double wall_damping_Ns_per_m,
                                             double period_s);

/// The highest wall stiffness that settles, by bisection on log K in [low, high] (low
/// must settle); `iterations` halvings.
[[nodiscard]] double highest_stable_stiffness_N_per_m(WallPressSettings settings, double low_N_per_m,
                                                      double high_N_per_m, int iterations = 24);

}  // namespace mhd::stability
