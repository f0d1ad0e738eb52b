#pragma once
// mhd-popthrough-stress's pushed-body options (--pushed, --body-mass-kg, --body-friction)
// and what it prints of a pushed run beyond the moving-object table: the body speeds the
// throws and the hand reached. Kept apart from popthrough_stress_main.cpp.

#include "stress/moving_stress_run.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>
#include <string_view>

namespace mhd::stress {

struct PushedCli {
  bool pushed = false;
  PushedBodyParams body;
};

/// Adds the options to `app`, writing into `cli`.
void add_pushed_options(CLI::App& app, PushedCli& cli);
/// --pushed makes the moving stress's mover a pushed body with cli's parameters.
void apply_pushed_options(const PushedCli& cli, MovingStressSettings& settings);
/// The options as a command line's tail (" --pushed ..."; empty without --pushed).
[[nodiscard]] std::string pushed_reproducer_flags(const PushedCli& cli);
/// One line on what a pushed body reached: origin speed, rotation rate, surface speed,
/// travel, and the ticks the proxy pressed on it.
void print_pushed_reached(std::FILE* out, std::string_view source, std::string_view object,
                          const MovingStressReport& r);

}  // namespace mhd::stress
