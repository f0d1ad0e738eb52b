#include "devices_command.h"

#include "command_exit.h"
#include "plugin_host/host_services.h"
#include "plugin_host/isolated_load.h"
#include "plugin_host/open_plugin.h"
#include "plugin_host/plugin_kind.h"
#include "plugin_host/plugin_search_path.h"

#include <fmt/core.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct DevicesOptions {
  std::vector<std::string> plugin_paths;
  double timeout_s = mhd::kIsolatedLoadTimeout_s;
  bool trackers = false;
};

/// "found: 3.3 N, 1260 N/m, 6 in / 3 out DOF, workspace x [-0.08, 0.08] y [...] z [...] m".
std::string what_it_can_do(const mhd::DeviceInfo& info) {
  std::string out = fmt::format("found: {:g} N, {:g} N/m, {} in / {} out DOF, workspace", info.max_force_N,
                                info.max_stiffness_N_per_m, info.dof_in, info.dof_out);
  const mhd::WorkspaceBoxD& box = info.workspace[0];
  for (int i = 0; i < 3; ++i) out += fmt::format(" {} [{:g}, {:g}]", "xyz"[i], box.min_m[i], box.max_m[i]);
  return out + " m";
}

/// Opens plugin `name` with its defaults in this (child) process; what its device can
/// do, or why it would not open.
std::string ask_device(const mhd::PluginSearchPath& search, const std::string& name) {
  const mhd::HostServices host;
  const auto opened = mhd::open_plugin(search, mhd::PluginDescription{mhd::PluginKind::Device, name, {}, {}},
                                       host.abi());
  if (!opened) return "no device: " + opened.error().message;
  const auto info = opened.value().device_info();
  if (!info) return "no device: " + info.error().message;
  return what_it_can_do(info.value());
}

/// Opens tracker plugin `name` with its defaults in this (child) process, never starting
/// it: whether its runtime and its tracker answer, or why not.
std::string ask_tracker(const mhd::PluginSearchPath& search, const std::string& name) {
  const mhd::HostServices host;
  const auto opened = mhd::open_plugin(search, mhd::PluginDescription{mhd::PluginKind::Tracker, name, {}, {}},
                                       host.abi());
  if (!opened) return "no tracker: " + opened.error().message;
  return "found: it opened with its default parameters";
}

/// Asks every plugin of `kind` in a child process each; how many there were.
std::size_t list_kind(const mhd::PluginSearchPath& search, mhd::PluginKind kind, const DevicesOptions& options) {
  std::size_t count = 0;
  for (const mhd::PluginListing& listing : search.list()) {
    if (!listing.loaded || listing.shadowed || listing.loaded.value().kind != kind) continue;
    const mhd::PluginInfo& info = listing.loaded.value();
    ++count;
    const bool device = kind == mhd::PluginKind::Device;
    const auto answer = mhd::run_isolated(
        [&] { return device ? ask_device(search, info.name) : ask_tracker(search, info.name); }, info.name,
        listing.path, options.timeout_s);
    fmt::print("{}: {}\n  {}\n  {}\n  <plugin kind=\"{}\" name=\"{}\"/>\n", info.name, info.description,
               listing.path.string(),
               answer ? answer.value() : std::string(device ? "no device: " : "no tracker: ") + answer.error().message,
               device ? "device" : "tracker", info.name);
  }
  return count;
}

int list_devices(const DevicesOptions& options) {
  std::vector<fs::path> command_line(options.plugin_paths.begin(), options.plugin_paths.end());
  const mhd::PluginSearchPath search = mhd::PluginSearchPath::standard(command_line);
  const std::size_t devices = list_kind(search, mhd::PluginKind::Device, options);
  if (options.trackers) list_kind(search, mhd::PluginKind::Tracker, options);
  if (devices == 0) {
    fmt::print(stderr, "mhd devices: no device plugin found (mhd plugins lists the folders searched)\n");
    return 1;
  }
  return 0;
}

}  // namespace

void add_devices_command(CLI::App& app) {
  auto options = std::make_shared<DevicesOptions>();
  CLI::App* devices =
      app.add_subcommand("devices", "Say which force-feedback devices answer, and the scene snippet for each");
  devices->add_option("--plugin-path", options->plugin_paths, "Search this folder first (repeatable, in order)")
      ->type_name("DIR")
      ->allow_extra_args(false);
  devices->add_option("--timeout", options->timeout_s, "Seconds one plugin may take to open before it is killed")
      ->check(CLI::Range(0.1, 600.0))
      ->type_name("S");
  devices->add_flag("--trackers", options->trackers,
                    "Ask the tracker plugins too (opening one may configure its tracker's output format)");
  devices->footer(
      "Each device plugin is opened with its default parameters in a child process, so a\n"
      "vendor runtime that crashes or hangs cannot end or stall this command. A missing\n"
      "runtime is named with how to install it (docs/hardware.md). Nothing is driven: the\n"
      "plugin is never started, so no force is output. With --trackers, each tracker\n"
      "plugin is opened the same way after the devices.\n"
      "Exit status 0; 1 when no device plugin is found.");
  devices->callback([options] { mhd::cli::exit_with(list_devices(*options)); });
}
