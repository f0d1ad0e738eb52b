#pragma once
// `mhd validate FILE...`: reads each scene (and compiles it unless --no-meshes),
// prints every diagnostic to stderr and "FILE: ok (N objects, M triangles)" to stdout
// for each good file; exits 0 when all files are good, 1 otherwise.

#include <CLI/CLI.hpp>

void add_validate_command(CLI::App& app);
