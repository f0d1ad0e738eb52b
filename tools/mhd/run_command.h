#pragma once
// `mhd run SCENE`: the haptic server on the scene's plugins (run_command.cpp).

#include <CLI/CLI.hpp>

void add_run_command(CLI::App& app);
