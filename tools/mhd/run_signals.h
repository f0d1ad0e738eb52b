#pragma once
// How `mhd run` ends on a signal or a dying process (docs/haptic_server.md, "How a run
// ends"). Every end leaves zero torque and a stopped base:
//   SIGINT, SIGTERM, SIGHUP, SIGQUIT  a safe stop through the server's normal path
//   SIGPIPE, SIGUSR1, SIGUSR2         ignored (a closed stdout never ends a run)
//   SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, std::terminate (an uncaught exception),
//   exit() or quick_exit() while the server runs
//                                     the last gasp: zero torque and a base stop straight
//                                     through the plugins, a message naming the plugin
//                                     whose call was in progress and the cause, exit 4.

#include "haptic_server/haptic_server.h"

namespace mhd::cli {

/// The status of a run ended by the last gasp.
inline constexpr int kRunLastGasp = 4;

/// Installs the process-wide handlers above (once; call before opening plugins).
void install_run_signal_handlers();
/// The server the handlers act on while it runs; null after run() returns. A stop signal
/// that came before is passed on at once.
void guard_server(HapticServer* server) noexcept;
/// The first stop signal received (SIGINT, ...), 0 when none.
[[nodiscard]] int stop_signal() noexcept;

}  // namespace mhd::cli
