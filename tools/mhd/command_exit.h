#pragma once
// How a subcommand sets mhd's exit status. CLI11 callbacks return void, so a callback
// that fails ends with exit_with(status); main() turns that into the process status
// without printing anything more. Usage errors (bad options) exit with kUsageError.

#include <CLI/CLI.hpp>

namespace mhd::cli {

inline constexpr int kUsageError = 2;

/// Ends the running subcommand with `status` (0: success, nothing happens).
inline void exit_with(int status) {
  if (status != 0) throw CLI::RuntimeError(status);
}

}  // namespace mhd::cli
