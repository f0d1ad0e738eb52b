// `mhd try` alone: tools/mhd/try_command.cpp under a main() that registers only it, the way tools/mhd/main.cpp does, so ctest checks the command's output and exit
// status without the rest of mhd.

#include "command_exit.h"
#include "try_command.h"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"mhd try alone", "mhd"};
  app.require_subcommand(1);
  add_try_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::RuntimeError& e) {
    return e.get_exit_code();
  } catch (const CLI::ParseError& e) {
    const int status = app.exit(e);
    return status == 0 ? 0 : mhd::cli::kUsageError;
  }
  return 0;
}
