#include "viewer/display_check.h"

#include <X11/Xlib.h>

#include <fmt/core.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <cstdlib>
#include <string>

namespace mhd::viewer {
namespace {

constexpr int kConnectAttempts = 5;
std::atomic<int> g_shm_major_opcode{-1};
XErrorHandler g_previous_handler = nullptr;

int quiet_handler(Display* display, XErrorEvent* event) {
  if (event->request_code == g_shm_major_opcode.load() && event->error_code == BadMatch) return 0;
  return g_previous_handler != nullptr ? g_previous_handler(display, event) : 0;
}

}  // namespace

void quiet_mit_shm_errors() {
  static std::atomic<bool> installed{false};
  if (installed.exchange(true)) return;
  const char* name = std::getenv("DISPLAY");
  Display* display = XOpenDisplay(name);
  if (display == nullptr) return;
  int major = 0, event = 0, error = 0;
  if (XQueryExtension(display, "MIT-SHM", &major, &event, &error) != 0) g_shm_major_opcode.store(major);
  XCloseDisplay(display);
  g_previous_handler = XSetErrorHandler(quiet_handler);
}

std::string check_display() {
  const char* name = std::getenv("DISPLAY");
  if (name == nullptr || *name == '\0') {
    return "no display: DISPLAY is not set (for offscreen rendering run under "
           "`xvfb-run -a -s '-screen 0 1920x1080x24'`)";
  }
  // Connections to a busy local X server (seen with Xvfb: ~2% of XOpenDisplay calls)
  // sometimes fail once and work on the next try.
  Display* display = nullptr;
  for (int attempt = 0; attempt < kConnectAttempts && display == nullptr; ++attempt) {
    if (attempt > 0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    display = XOpenDisplay(name);
  }
  if (display == nullptr) {
    return fmt::format("no display: cannot open X display '{}' (is the X server or Xvfb running?)", name);
  }
  XCloseDisplay(display);
  return {};
}

}  // namespace mhd::viewer
