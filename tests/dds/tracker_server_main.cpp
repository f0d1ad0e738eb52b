// dds_test_tracker_server: `mhd tracker-server` alone (the same command file the mhd
// executable registers), so tests/dds runs the real command as a process.
#include "../../tools/mhd/tracker_server_command.h"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"mhd tracker-server, for tests/dds", "mhd"};
  app.require_subcommand(1);
  add_tracker_server_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::RuntimeError& e) {
    return e.get_exit_code();
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  return 0;
}
