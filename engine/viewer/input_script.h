#pragma once
// Timed input for `mhd try --script FILE`: the mouse and key events a user would make,
// each at a frame number, so a run (and its screenshot) is deterministic. One event a
// line, '#' starts a comment:
//
//   FRAME press X Y        left button down at window pixel (X, Y), origin bottom left
//   FRAME drag X Y         pointer moved to (X, Y) with the button held
//   FRAME release X Y
//   FRAME scroll N         N wheel notches, + away from the user
//   FRAME key K            a key: one character (w, s, r, ...) or PageUp, PageDown, Home
//
// Frames count from 0 and never decrease; an event at frame F is handled while frame F
// is drawn, and its effect is seen from frame F + 1 on.

#include "diagnostics/result.h"
#include "viewer/input_event.h"

#include <filesystem>
#include <string>
#include <vector>

namespace mhd::viewer {

struct ScriptedEvent {
  int frame = 0;
  InputEvent event;
};

/// The events, or the first mistake at its file:line.
[[nodiscard]] Result<std::vector<ScriptedEvent>> parse_input_script(const std::string& text, const std::string& file_name);
[[nodiscard]] Result<std::vector<ScriptedEvent>> read_input_script(const std::filesystem::path& file);

}  // namespace mhd::viewer
