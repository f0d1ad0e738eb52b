#include "stress/pushed_stress_cli.h"

#include <fmt/core.h>

#include <numbers>

namespace mhd::stress {

void add_pushed_options(CLI::App& app, PushedCli& cli) {
  app.add_flag("--pushed", cli.pushed,
               "With --moving: the stressed object is a rigid body pushed by the proxy's force as the haptic server "
               "pushes it, thrown at each proxy reset with a random twist (up to --max-object-speed-mps and "
               "--max-object-rate-deg-s); other objects are its still colliders; gravity only if its scene makes "
               "it pushable");
  app.add_option("--body-mass-kg", cli.body.mass_kg,
                 "--pushed: the body's mass when its scene gives it no <dynamics>")
      ->check(CLI::Range(1e-3, 1000.0));
  app.add_option("--body-friction", cli.body.friction,
                 "--pushed: the body's friction with still objects when its scene gives it no <dynamics>")
      ->check(CLI::Range(0.0, 10.0));
}

void apply_pushed_options(const PushedCli& cli, MovingStressSettings& settings) {
  if (!cli.pushed) return;
  settings.mover = MoverKind::Pushed;
  settings.pushed = cli.body;
}

std::string pushed_reproducer_flags(const PushedCli& cli) {
  if (!cli.pushed) return {};
  return fmt::format(" --pushed --body-mass-kg {} --body-friction {}", cli.body.mass_kg, cli.body.friction);
}

void print_pushed_reached(std::FILE* out, std::string_view source, std::string_view object,
                          const MovingStressReport& r) {
  fmt::print(out,
             "  {} / {}: pushed body reached {:.3f} m/s, {:.0f} deg/s, surface up to {:.3f} m/s, {:.3f} m from its "
             "start; thrown at up to {:.3f} m/s, {:.0f} deg/s; the proxy pressed on it on {} ticks\n",
             source, object, r.max_reached_speed_mps, r.max_reached_rate_radps * 180.0 / std::numbers::pi,
             r.max_reached_surface_speed_mps, r.max_travel_m, r.max_object_speed_mps,
             r.max_object_rate_radps * 180.0 / std::numbers::pi, r.object_force_ticks);
}

}  // namespace mhd::stress
