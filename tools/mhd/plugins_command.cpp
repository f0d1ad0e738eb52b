#include "plugins_command.h"

#include "command_exit.h"
#include "plugin_host/plugin_kind.h"
#include "plugin_host/plugin_search_path.h"

#include <mhd/plugin_params.hpp>

#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct PluginsOptions {
  std::vector<std::string> plugin_paths;
  std::string describe;  ///< a plugin name: print its declarations instead of the list
};

using Row = std::array<std::string, 4>;  // kind, name, version, path

Row row_of(const mhd::PluginListing& listing) {
  std::string path = listing.path.string();
  if (listing.shadowed) path += " (shadowed by an earlier folder)";
  if (!listing.loaded) return {"broken", listing.loaded.error().plugin, "-", path};
  const mhd::PluginInfo& info = listing.loaded.value();
  return {std::string(mhd::to_string(info.kind)), info.name, info.version.empty() ? "-" : info.version, path};
}

void print_table(const std::vector<Row>& rows) {
  std::array<std::size_t, 3> width{};
  for (const Row& row : rows) {
    for (std::size_t c = 0; c < width.size(); ++c) width[c] = std::max(width[c], row[c].size());
  }
  for (const Row& row : rows) {
    fmt::print("{:<{}}  {:<{}}  {:<{}}  {}\n", row[0], width[0], row[1], width[1], row[2], width[2], row[3]);
  }
}

int list_plugins(const PluginsOptions& options) {
  std::vector<fs::path> command_line(options.plugin_paths.begin(), options.plugin_paths.end());
  const mhd::PluginSearchPath search = mhd::PluginSearchPath::standard(command_line);

  fmt::print("plugin folders, in search order:\n");
  for (const mhd::PluginFolder& folder : search.folders()) {
    std::error_code ec;
    const bool present = fs::is_directory(folder.dir, ec);
    fmt::print("  {} ({}{})\n", folder.dir.string(), mhd::to_string(folder.source), present ? "" : ", missing");
  }

  const std::vector<mhd::PluginListing> listings = search.list();
  if (listings.empty()) {
    fmt::print("no plugin files found\n");
    return 0;
  }
  std::vector<Row> rows{{"KIND", "NAME", "VERSION", "PATH"}};
  std::size_t broken = 0;
  for (const mhd::PluginListing& listing : listings) {
    rows.push_back(row_of(listing));
    if (!listing.loaded) ++broken;
  }
  print_table(rows);
  fmt::print("{} plugin files: {} loaded, {} broken\n", listings.size(), listings.size() - broken, broken);
  for (const mhd::PluginListing& listing : listings) {
    if (!listing.loaded) fmt::print(stderr, "mhd plugins: error: {}\n", listing.loaded.error().to_string());
  }
  return broken == 0 ? 0 : 1;
}

/// NAME's kind, version, description and declared parameters (mhd/plugin_params.hpp).
int describe_plugin(const PluginsOptions& options) {
  std::vector<fs::path> command_line(options.plugin_paths.begin(), options.plugin_paths.end());
  const mhd::PluginSearchPath search = mhd::PluginSearchPath::standard(command_line);
  const auto library = search.load(options.describe);
  if (!library) {
    fmt::print(stderr, "mhd plugins: error: {}\n", library.error().to_string());
    return 1;
  }
  const mhd::PluginLibrary& l = *library.value();
  const mhd::PluginInfo& info = l.info();
  fmt::print("{} ({} plugin, version {}): {}\n{}\n", info.name, mhd::to_string(info.kind),
             info.version.empty() ? "-" : info.version, info.description, l.path().string());
  const mhd_plugin_api& api = l.api();
  if (api.param_count == 0) {
    fmt::print("parameters: none\n");
    return 0;
  }
  fmt::print("parameters:\n");
  for (std::size_t i = 0; i < api.param_count; ++i) fmt::print("  {}\n", mhd::sdk::describe(api.params[i]));
  return 0;
}

}  // namespace

void add_plugins_command(CLI::App& app) {
  auto options = std::make_shared<PluginsOptions>();
  CLI::App* plugins = app.add_subcommand("plugins", "List the plugins mhd can find and check that each one loads");
  plugins->add_option("--plugin-path", options->plugin_paths, "Search this folder first (repeatable, in order)")
      ->type_name("DIR")
      ->allow_extra_args(false);
  plugins->add_option("--describe", options->describe,
                      "Print plugin NAME's description and declared parameters (name, type, range, unit, default, doc)")
      ->type_name("NAME");
  const std::string versioned = mhd::versioned_plugin_subdir().string();
  plugins->footer(
      "Folders are searched in this order: --plugin-path, $MHD_PLUGIN_PATH (colon-separated),\n"
      "<mhd's folder>/" + mhd::installed_plugin_dir_from_bindir().string() + ", then (only if that folder\n"
      "does not exist) the build tree's lib/" + versioned + ".\n"
      "Plugin NAME is the file libmhd_NAME.so; the first folder holding it wins.\n"
      "Exit status 0 if every plugin file loads, 1 if any is broken (errors on stderr).");
  plugins->callback([options] {
    spdlog::debug("listing plugins");
    mhd::cli::exit_with(options->describe.empty() ? list_plugins(*options) : describe_plugin(*options));
  });
}
