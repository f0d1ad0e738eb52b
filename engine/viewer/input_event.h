#pragma once
// A mouse or key event in the viewer's window, free of OSG: what the interactive mode
// (`mhd try`, docs/viewer.md "Try it by hand") reacts to, and what a script or a test
// injects into the viewer's event queue to drive it as a user would.

#include <string>

namespace mhd::viewer {

/// X11 keysyms (OSG uses the same values) of the non-printing keys the viewer knows.
inline constexpr int kKeyHome = 0xFF50;
inline constexpr int kKeyPageUp = 0xFF55;
inline constexpr int kKeyPageDown = 0xFF56;

struct InputEvent {
  enum class Kind { Press, Drag, Release, Scroll, Key };
  Kind kind = Kind::Key;
  /// Press, Drag, Release: the pointer in window pixels, origin at the bottom left, y up.
  double x_px = 0.0;
  double y_px = 0.0;
  int button = 1;        ///< Press, Release: 1 left, 2 middle, 3 right
  int scroll_steps = 0;  ///< Scroll: +1 per wheel notch up (away from the user), -1 down
  int key = 0;           ///< Key (pressed): a printable character, or kKeyHome etc.

  static InputEvent press(double x_px, double y_px, int button = 1) { return {Kind::Press, x_px, y_px, button, 0, 0}; }
  static InputEvent drag(double x_px, double y_px) { return {Kind::Drag, x_px, y_px, 1, 0, 0}; }
  static InputEvent release(double x_px, double y_px, int button = 1) {
    return {Kind::Release, x_px, y_px, button, 0, 0};
  }
  static InputEvent scroll(int steps) { return {Kind::Scroll, 0.0, 0.0, 1, steps, 0}; }
  static InputEvent key_press(int key) { return {Kind::Key, 0.0, 0.0, 1, 0, key}; }
};

}  // namespace mhd::viewer
