#pragma once
// `mhd strokes`: the scripted stroke set through the proxy (strokes_command.cpp).

#include <CLI/CLI.hpp>

void add_strokes_command(CLI::App& app);
