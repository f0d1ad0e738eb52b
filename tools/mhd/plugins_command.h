#pragma once
// `mhd plugins [--plugin-path DIR]...`: lists the plugin folders in search order and
// every plugin file in them (kind, name, version, path), loading each to read what it
// says. Broken files are listed as "broken" and their errors go to stderr. Exits 0 when
// every file loads, 1 when any is broken (so scripts can check an installation).

#include <CLI/CLI.hpp>

void add_plugins_command(CLI::App& app);
