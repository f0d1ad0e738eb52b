// mhd-hand-stability: the highest virtual-wall stiffness that the impedance hand can
// press stably at 1 kHz and 10 kHz, next to Colgate and Schenkel's passivity bound
// K < 2 (b - |B|) / T (docs/simulated_hand.md, "Stability"). Also a sweep in multiples
// of the bound. Simulation only; a few seconds.
#include "wall_press.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <vector>

int main(int argc, char** argv) {
  CLI::App app{"Highest stable wall stiffness with the impedance hand, next to the passivity bound"};
  mhd::stability::WallPressSettings base;
  std::vector<double> rates_hz{1000.0, 10000.0};
  std::vector<double> wall_dampings_Ns_per_m{0.0, 1.0};
  app.add_option("--rates-hz", rates_hz, "haptic rates");
  app.add_option("--wall-damping", wall_dampings_Ns_per_m, "virtual damping B of the wall (N s/m)");
  app.add_option("--resolution-m", base.position_resolution_m, "encoder resolution at the tool (0: exact)");
  app.add_option("--hand-damping", base.hand.damping_Ns_per_m, "hand damping b (N s/m)");
  app.add_option("--hand-mass", base.hand.mass_kg, "hand mass (kg)");
  app.add_option("--hand-stiffness", base.hand.stiffness_N_per_m, "hand stiffness (N/m)");
  CLI11_PARSE(app, argc, argv);

  const double b = base.hand.damping_Ns_per_m;
  fmt::print("impedance hand m {} kg, k {} N/m, b {} N s/m; encoder resolution {} m; press {} mm behind the wall\n",
             base.hand.mass_kg, base.hand.stiffness_N_per_m, b, base.position_resolution_m, base.press_depth_m * 1e3);
  fmt::print("{:>8} {:>8} {:>16} {:>16} {:>8}\n", "rate_Hz", "B_Ns/m", "bound_N/m", "highest_N/m", "ratio");
  for (const double rate_hz : rates_hz) {
    for (const double B : wall_dampings_Ns_per_m) {
      mhd::stability::WallPressSettings s = base;
      s.rate_hz = rate_hz;
      s.wall_damping_Ns_per_m = B;
      const double bound = mhd::stability::passivity_bound_N_per_m(b, B, 1.0 / rate_hz);
      const double highest = mhd::stability::highest_stable_stiffness_N_per_m(s, 100.0, 50.0 * bound);
      fmt::print("{:>8.0f} {:>8.2f} {:>16.0f} {:>16.0f} {:>8.3f}\n", rate_hz, B, bound, highest, highest / bound);
    }
  }
  fmt::print("\nsweep (B = 0): force peak-to-peak in the last two {} s windows of {} s\n", base.window_s, base.duration_s);
  fmt::print("{:>8} {:>10} {:>12} {:>12} {:>12} {:>10}\n", "rate_Hz", "K/bound", "K_N/m", "ptp_prev_N", "ptp_last_N",
             "verdict");
  for (const double rate_hz : rates_hz) {
    const double bound = mhd::stability::passivity_bound_N_per_m(b, 0.0, 1.0 / rate_hz);
    for (const double ratio : {0.5, 0.9, 0.95, 1.0, 1.05, 1.1, 1.5, 3.0}) {
      mhd::stability::WallPressSettings s = base;
      s.rate_hz = rate_hz;
      s.wall_stiffness_N_per_m = ratio * bound;
      const auto r = mhd::stability::press_wall(s);
      fmt::print("{:>8.0f} {:>10.2f} {:>12.0f} {:>12.4f} {:>12.4f} {:>10}\n", rate_hz, ratio, s.wall_stiffness_N_per_m,
                 r.force_ptp_previous_N, r.force_ptp_last_N, r.stable ? "settles" : "UNSTABLE");
    }
  }
  return 0;
}
