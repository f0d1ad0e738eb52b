#pragma once
// Whether an X display can be opened, asked before OSG is: OSG prints and goes on
// with a null window when there is none.

#include <string>

namespace mhd::viewer {

/// Empty when $DISPLAY names a display that opens, else a message saying what to do
/// ("no display: DISPLAY is not set; run under xvfb-run -a ... or give a display").
[[nodiscard]] std::string check_display();

}  // namespace mhd::viewer

namespace mhd::viewer {

/// Mesa's software renderer first tries MIT-SHM to show a pbuffer, which the X server
/// refuses (BadMatch), then falls back; OSG's X error handler prints every refusal.
/// Installs a handler that drops exactly those and passes every other error on to the
/// handler that was there before. Call after the OpenGL context exists.
void quiet_mit_shm_errors();

}  // namespace mhd::viewer
