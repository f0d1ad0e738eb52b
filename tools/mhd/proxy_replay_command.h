#pragma once
// `mhd proxy-replay`: a HIP path through the scene's proxy, a row per tick
// (proxy_replay_command.cpp).

#include <CLI/CLI.hpp>

void add_proxy_replay_command(CLI::App& app);
