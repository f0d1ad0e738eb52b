#pragma once
// `mhd devices [--plugin-path DIR]...`: for every device plugin mhd can find, whether its
// device answers: each is opened with its defaults, in a child process (a vendor runtime
// that crashes or hangs cannot end or stall the command), and either reports what the
// device can do or says why not (a missing vendor runtime names the library and how to
// install it). Then the scene snippet to use it. Exits 0; 1 when no device plugin is found.

#include <CLI/CLI.hpp>

void add_devices_command(CLI::App& app);
