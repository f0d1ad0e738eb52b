#pragma once

#include <CLI/CLI.hpp>

/// `mhd viewer SCENE.xml`: draws the scene (and a rig state) in stereo or mono, in a window
/// or offscreen into a PNG (engine/viewer, docs/viewer.md).
void add_viewer_command(CLI::App& app);
