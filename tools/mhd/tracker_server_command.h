#pragma once
// `mhd tracker-server SCENE.xml [--rate-hz 190] [--duration S] [--rig-id ID]
// [--domain-id D] [--plugin-path DIR]... [--seed N]`: runs the scene's tracker plugin
// and publishes its samples over Cyclone DDS (tools/tracker_server/tracker_server.h)
// until --duration passes or SIGINT/SIGTERM. Exit status 0, or 1 with
// "mhd tracker-server: error: ..." on stderr.

#include <CLI/CLI.hpp>

void add_tracker_server_command(CLI::App& app);
