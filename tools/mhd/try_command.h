#pragma once

#include <CLI/CLI.hpp>

/// `mhd try SCENE.xml`: the scene in a desktop window, the hand point moved by the mouse
/// and keys, the engine's proxy and force drawn as they would be felt (engine/viewer
/// hand_session.h, docs/viewer.md "Try it by hand").
void add_try_command(CLI::App& app);
