#include "tracker_server_command.h"

#include "command_exit.h"
#include "tracker_server/tracker_server.h"

#include <fmt/core.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

std::atomic<bool> g_stop{false};

extern "C" void request_stop(int /*signal*/) { g_stop.store(true); }

struct TrackerServerCli {
  std::string scene;
  std::optional<double> rate_hz;
  std::optional<double> duration_s;
  std::uint32_t rig_id = 0;
  std::optional<std::uint32_t> domain_id;
  std::vector<std::string> plugin_paths;
  std::uint64_t seed = 0;
  std::optional<std::string> identity_dir;
  std::int32_t ownership_strength = mhd::dds::kDefaultOwnershipStrength;
  bool shared_world = false;
};

int run(const TrackerServerCli& cli) {
  mhd::dds::TrackerServerOptions options;
  options.scene_file = cli.scene;
  options.rate_hz = cli.rate_hz;
  options.duration_s = cli.duration_s;
  options.rig_id = cli.rig_id;
  if (cli.domain_id) options.domain_id = *cli.domain_id;
  options.plugin_paths.assign(cli.plugin_paths.begin(), cli.plugin_paths.end());
  options.user_seed = cli.seed;
  if (cli.identity_dir) options.identity_dir = *cli.identity_dir;
  options.ownership_strength = cli.ownership_strength;
  options.shared_world = cli.shared_world;
  g_stop.store(false);
  std::signal(SIGINT, request_stop);
  std::signal(SIGTERM, request_stop);
  try {
    const mhd::dds::TrackerServerReport report = mhd::dds::run_tracker_server(
        options, g_stop, [](const std::string& line) {
          fmt::print("mhd tracker-server: {}\n", line);
          std::fflush(stdout);
        });
    fmt::print("mhd tracker-server: published {} samples of '{}' in {:.2f} s\n", report.published, report.plugin,
               report.elapsed_s);
    if (cli.shared_world) {
      fmt::print("mhd tracker-server: shared world: {} states measured, {} refused{}\n", report.world_states,
                 report.world_states_rejected,
                 report.world_states == 0 ? " (none arrived: does the rig's dds tracker set publish_sim_world?)" : "");
    }
    return 0;
  } catch (const mhd::dds::TrackerServerSceneError& e) {
    fmt::print(stderr, "{}\n", e.what());  // "FILE:LINE: error: ..." as `mhd validate` prints them
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "mhd tracker-server: error: {}\n", e.what());
    return 1;
  }
}

}  // namespace

void add_tracker_server_command(CLI::App& app) {
  auto cli = std::make_shared<TrackerServerCli>();
  CLI::App* cmd = app.add_subcommand("tracker-server", "Publish a scene's tracker plugin over DDS (Cyclone)");
  cmd->add_option("scene", cli->scene, "Scene XML naming one tracker plugin (sim_is900, replay, ...)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--rate-hz", cli->rate_hz, "sim_is900's update rate (default: the scene's, else 190)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--duration", cli->duration_s, "Stop after this many seconds (default: until SIGINT/SIGTERM)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--rig-id", cli->rig_id, "Rig id the samples carry (the dds tracker's rig_id)");
  cmd->add_option("--domain-id", cli->domain_id, "DDS domain (default: the Cyclone configuration's)")
      ->check(CLI::Range(0, 232));
  cmd->add_option("--plugin-path", cli->plugin_paths, "Search this folder first (repeatable)")
      ->type_name("DIR")
      ->allow_extra_args(false);
  cmd->add_option("--seed", cli->seed, "Seed of the simulated user's random walk");
  cmd->add_option("--dds-identity", cli->identity_dir,
                  "DDS Security identity folder (tools/dds_security/make_rig_security.sh; default: "
                  "$MHD_DDS_IDENTITY, else unsecured)")
      ->type_name("DIR");
  cmd->add_option("--ownership-strength", cli->ownership_strength,
                  "Writer strength under exclusive ownership; readers hear only the strongest live writer of a "
                  "sensor (default 10)")
      ->check(CLI::Range(0, 1000000));
  cmd->add_flag("--shared-world", cli->shared_world,
               "Simulation: measure the world the rig's haptic server publishes (its dds tracker's "
               "publish_sim_world: its user and the base it moves) instead of a user simulated here; "
               "starts on the first world received");
  cmd->footer(
      "Set CYCLONEDDS_URI to a Cyclone configuration, e.g.\n"
      "  CYCLONEDDS_URI=file://$PWD/config/cyclonedds-secure.xml, and an identity with --dds-identity\n"
      "  or MHD_DDS_IDENTITY (see docs/networking.md, \"Security\")");
  cmd->callback([cli] { mhd::cli::exit_with(run(*cli)); });
}
