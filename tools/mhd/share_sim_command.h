#pragma once
// `mhd share-sim [--sessions N] [--first-seed S] [--duration-s D] [--out DIR]`: two rigs
// sharing one pushable box over a simulated link (tools/share_sim/shared_object_sim.h):
// drawn sessions of both users pushing, holding and stroking it. Prints pop-throughs,
// how far each rig's box is from the authority's, and how long a push takes to be felt,
// and writes DIR/share_sim.csv (one row per session).
// Exit status 0; 1 on a bad option or a file that cannot be written; 3 on a pop-through.

#include <CLI/CLI.hpp>

void add_share_sim_command(CLI::App& app);
