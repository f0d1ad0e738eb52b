#pragma once
// `mhd run`: runs a scene on the haptic device (run_command.cpp).

#include <CLI/CLI.hpp>

void add_run_command(CLI::App& app);
