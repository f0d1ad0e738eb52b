// One `mhd` command alone: its file from tools/mhd under a main() that registers only it,
// the way tools/mhd/main.cpp does, so ctest checks the command's output and exit status
// without the rest of mhd. CMake names the command: MHD_COMMAND_NAME ("viewer"),
// MHD_COMMAND_HEADER ("viewer_command.h") and MHD_ADD_COMMAND (add_viewer_command).

#include "command_exit.h"
#include MHD_COMMAND_HEADER

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"mhd " MHD_COMMAND_NAME " alone", "mhd"};
  app.require_subcommand(1);
  MHD_ADD_COMMAND(app);
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
