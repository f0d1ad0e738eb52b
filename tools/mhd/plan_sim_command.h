#pragma once
// `mhd plan-sim [--out DIR] [--planner seed|predictive|both] [--v-mps V...] [--omega-degps W...]
//  [--facing-deg F...] [--cell-mm C] [--half-size-m H] [--set NAME=VALUE]... [--no-maps]`:
// the planner simulator of thesis ch. 3.6-3.7 (tools/plan_sim/plan_sim.h). For every planner,
// facing change, maximum linear and angular speed it maps the next user positions the base
// follows within 1 s, prints the table of followed areas, and writes DIR/plan_sim_areas.csv
// and one CSV per map in DIR/maps (tools/plots/plan_sim_maps.py draws them). --set overrides planner settings by name (docs/planner.md).
// Exit status 0 on success, 1 on a bad setting or a file that cannot be written.

#include <CLI/CLI.hpp>

void add_plan_sim_command(CLI::App& app);
