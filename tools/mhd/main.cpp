// mhd: the MHD command line. Each subcommand lives in its own *_command.cpp and is
// registered here by its add_*_command(app); a subcommand's callback does the work
// and reports failure through mhd::cli::exit_with (command_exit.h).

#include "cache_command.h"
#include "calibrate_command.h"
#include "command_exit.h"
#include "devices_command.h"
#include "huge_page_malloc.h"
#include "plan_sim_command.h"
#include "share_sim_command.h"
#include "plugins_command.h"
#include "proxy_replay_command.h"
#include "replay_command.h"
#include "run_command.h"
#include "strokes_command.h"
#include "try_command.h"
#include "viewer_command.h"
#ifdef MHD_HAVE_DDS
#include "tracker_server_command.h"
#endif
#include "validate_command.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <exception>

namespace {

void set_up_logging() {
  auto logger = spdlog::stderr_color_mt("mhd");
  logger->set_pattern("mhd: %^%l%$: %v");
  spdlog::set_default_logger(logger);
  spdlog::set_level(spdlog::level::info);
}

}  // namespace

int main(int argc, char** argv) {
  // First, before anything is allocated that a large mesh's load would grow. The
  // subcommand comes first on mhd's command line (-v and --version aside).
  for (int i = 1; i < argc; ++i) {
    if (argv[i][0] == '-') continue;
    if (mhd::cli::wants_huge_page_malloc(argv[i])) mhd::cli::restart_with_huge_page_malloc("/proc/self/exe", argv);
    break;
  }
  set_up_logging();

  CLI::App app{"MHD: haptic rendering engine", "mhd"};
  app.set_version_flag("--version", "mhd " MHD_VERSION);
  app.require_subcommand(1);
  app.add_flag_callback("-v,--verbose", [] { spdlog::set_level(spdlog::level::debug); },
                        "Log what each command does");

  add_validate_command(app);
  add_run_command(app);
  add_plugins_command(app);
  add_devices_command(app);
  add_plan_sim_command(app);
  add_share_sim_command(app);
  add_cache_command(app);
  add_calibrate_command(app);
  add_replay_command(app);
  add_viewer_command(app);
  add_try_command(app);
#ifdef MHD_HAVE_DDS
  add_tracker_server_command(app);
#endif
  add_strokes_command(app);
  add_proxy_replay_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::RuntimeError& e) {
    return e.get_exit_code();  // a subcommand's exit_with(status)
  } catch (const CLI::ParseError& e) {
    const int status = app.exit(e);  // prints help, version or the usage error
    return status == 0 ? 0 : mhd::cli::kUsageError;
  } catch (const std::exception& e) {
    fmt::print(stderr, "mhd: error: {}\n", e.what());
    return 1;
  }
  return 0;
}
