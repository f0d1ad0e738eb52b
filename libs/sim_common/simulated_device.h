#pragma once
// What the simulated Cartesian devices (sim_phantom, sim_delta) share: the simulated hand
// that holds them (its declared parameters and how they fill a model's config), and a
// device_info with one workspace box. Header-only, plugin side.

#include <mhd/plugin_abi.h>
#include <mhd/plugin_sdk.hpp>

#include <Eigen/Core>

#include <array>
#include <string>

namespace mhd::plugin_support {

/// The simulated hand's parameters; a device joins them to its own (sdk::join).
inline constexpr std::array kSimulatedHandParams{
    sdk::choice("hand_model", "kinematic|impedance", "kinematic",
                "how the simulated hand moves: a stiff spring to the intended path, or a mass-spring-damper arm"),
    sdk::number("hand_mass_kg", "kg", "0.55", "impedance hand: the arm's apparent mass", sdk::above_up_to(0, 100)),
    sdk::number("hand_stiffness_N_per_m", "N/m", nullptr,
                "the hand's spring to the intended path (default 2000 kinematic, 135 impedance)",
                sdk::above_up_to(0, 1e6)),
    sdk::number("hand_damping_Ns_per_m", "N s/m", "6.5", "impedance hand: the arm's damping", sdk::above_up_to(0, 1e4)),
};

/// Fills a device model's hand fields (hand_model, hand_impedance, hand_stiffness_N_per_m)
/// from kSimulatedHandParams' values. Throws sdk::ParamError for an impedance-only
/// parameter given with the kinematic hand.
template <class Config>
void read_simulated_hand(const sdk::Params& params, Config& m) {
  using Model = decltype(m.hand_model);
  if (params.text("hand_model") == "impedance") {
    m.hand_model = Model::Impedance;
    auto& h = m.hand_impedance;
    h.mass_kg = params.number("hand_mass_kg");
    // Declared without a default: each hand model has its own (its config's).
    h.stiffness_N_per_m = params.optional_number("hand_stiffness_N_per_m").value_or(h.stiffness_N_per_m);
    h.damping_Ns_per_m = params.number("hand_damping_Ns_per_m");
    return;
  }
  for (const char* impedance_only : {"hand_mass_kg", "hand_damping_Ns_per_m"}) {
    if (params.given(impedance_only)) {
      throw sdk::ParamError("parameter '" + std::string(impedance_only) + "' applies only to hand_model 'impedance'");
    }
  }
  m.hand_stiffness_N_per_m = params.optional_number("hand_stiffness_N_per_m").value_or(m.hand_stiffness_N_per_m);
}

/// A 3-in, 3-out device's info with one workspace box [min_D_m, max_D_m] in its frame.
inline mhd_device_info one_box_device_info(double max_force_N, double max_stiffness_N_per_m,
                                           const Eigen::Vector3d& min_D_m, const Eigen::Vector3d& max_D_m) {
  mhd_device_info out{};
  out.max_force_N = max_force_N;
  out.max_stiffness_N_per_m = max_stiffness_N_per_m;
  out.dof_in = 3;
  out.dof_out = 3;
  out.workspace_box_count = 1;
  for (int i = 0; i < 3; ++i) {
    out.workspace[0].min_m[i] = min_D_m[i];
    out.workspace[0].max_m[i] = max_D_m[i];
  }
  return out;
}

}  // namespace mhd::plugin_support
