#pragma once
// `mhd replay RECORDING.csv`: re-runs a recording through the engine (replay_command.cpp).

#include <CLI/CLI.hpp>

void add_replay_command(CLI::App& app);
