#include "cache_command.h"

#include "command_exit.h"
#include "mesh_io/mesh_cache.h"
#include "mesh_io/mesh_cache_eviction.h"

#include <fmt/chrono.h>
#include <fmt/core.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

namespace {

std::string mib(std::uint64_t bytes) { return fmt::format("{:.1f} MiB", static_cast<double>(bytes) / 1048576.0); }

std::optional<std::filesystem::path> cache_dir_or_say_why(const char* command) {
  std::optional<std::filesystem::path> dir = mhd::default_mesh_cache_dir();
  if (!dir) fmt::print(stderr, "mhd cache {}: error: no cache folder: set MHD_CACHE_DIR or HOME\n", command);
  return dir;
}

int list() {
  const auto dir = cache_dir_or_say_why("list");
  if (!dir) return 1;
  if (const std::string problem = mhd::mesh_cache_limit_problem(); !problem.empty())
    fmt::print(stderr, "mhd cache list: warning: {}\n", problem);
  const auto entries = mhd::list_mesh_cache(*dir);
  std::uint64_t total = 0;
  fmt::print("BVH cache {}: most recently used first\n", dir->string());
  for (const mhd::MeshCacheEntry& e : entries) {
    total += e.size_bytes;
    const auto when = std::chrono::time_point_cast<std::chrono::seconds>(
        std::chrono::file_clock::to_sys(e.last_used));
    const std::optional<std::string> source = mhd::mesh_cache_entry_source(e.file);
    fmt::print("  {}  {:>10}  last used {:%Y-%m-%d %H:%M:%S} UTC  {}\n", e.file.filename().string(), mib(e.size_bytes),
               when,
               !source ? std::string("(not an entry of this version: rebuilt when its mesh is loaded)")
                       : source->empty() ? std::string("(mesh file not recorded)") : *source);
  }
  fmt::print("{} {}, {} of {} (limit: MHD_CACHE_MAX_MB; least recently used go first)\n", entries.size(),
             entries.size() == 1 ? "entry" : "entries", mib(total), mib(mhd::mesh_cache_limit_bytes()));
  return 0;
}

int clear() {
  const auto dir = cache_dir_or_say_why("clear");
  if (!dir) return 1;
  const mhd::MeshCacheRemoval r = mhd::clear_mesh_cache(*dir);
  fmt::print("BVH cache {}: removed {} files, {}{}\n", dir->string(), r.removed, mib(r.freed_bytes),
             r.keys_removed > 0 ? fmt::format(", and {} remembered keys", r.keys_removed) : "");
  if (!mhd::list_mesh_cache(*dir).empty()) {
    fmt::print(stderr, "mhd cache clear: error: some entries in {} could not be removed\n", dir->string());
    return 1;
  }
  return 0;
}

}  // namespace

void add_cache_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("cache", "The BVH cache of loaded meshes: list or clear it");
  cmd->require_subcommand(1);
  cmd->footer(
      "The cache keeps each mesh with its BVH so a second load skips assimp and the BVH\n"
      "build. Folder: $MHD_CACHE_DIR, else $XDG_CACHE_HOME/mhd, else ~/.cache/mhd. Size\n"
      "limit: $MHD_CACHE_MAX_MB (default 512); each write removes the least recently used\n"
      "entries beyond it. Entries are rebuilt when missing, so clearing is always safe.");
  CLI::App* list_cmd = cmd->add_subcommand("list", "Each entry with its size, last use and mesh file, the total and the limit");
  list_cmd->callback([] { mhd::cli::exit_with(list()); });
  CLI::App* clear_cmd =
      cmd->add_subcommand("clear", "Remove every entry and remembered key (they are rebuilt on the next load)");
  clear_cmd->callback([] { mhd::cli::exit_with(clear()); });
}
