#include "plugin_host/plugin_search_path.h"

#include <mhd/plugin_abi.h>

#include "plugin_host/isolated_load.h"
#include "plugin_host/plugin_name.h"

#include <fmt/core.h>

#include <algorithm>
#include <cstdlib>
#include <set>
#include <string>
#include <system_error>
#include <utility>

#if !defined(MHD_BUILD_PLUGIN_DIR) || !defined(MHD_INSTALLED_PLUGIN_DIR_FROM_BINDIR) || !defined(MHD_BUILD_ROOT_DIR)
#error "MHD_BUILD_PLUGIN_DIR, MHD_BUILD_ROOT_DIR and MHD_INSTALLED_PLUGIN_DIR_FROM_BINDIR must be defined by CMake"
#endif

namespace mhd {
namespace {

namespace fs = std::filesystem;

/// The same folder written two ways compares equal (symlinks resolved where they exist).
fs::path identity_of(const fs::path& dir) {
  std::error_code ec;
  fs::path resolved = fs::weakly_canonical(dir, ec);
  if (ec) resolved = fs::absolute(dir, ec).lexically_normal();
  if (!resolved.has_filename()) resolved = resolved.parent_path();  // "/x/a/" is "/x/a"
  return resolved;
}

bool is_plugin_file(const fs::directory_entry& entry) {
  std::error_code ec;
  if (entry.is_directory(ec)) return false;
  return !plugin_name_from_file(entry.path()).empty();
}

}  // namespace

std::string_view to_string(PluginFolderSource source) {
  switch (source) {
    case PluginFolderSource::CommandLine: return "--plugin-path";
    case PluginFolderSource::Environment: return "MHD_PLUGIN_PATH";
    case PluginFolderSource::Executable: return "installed";
    case PluginFolderSource::BuildTree: return "build tree";
    case PluginFolderSource::Given: return "given";
  }
  return "unknown";
}

fs::path versioned_plugin_subdir() { return fs::path("mhd") / fmt::format("plugins-abi{}", MHD_PLUGIN_ABI_VERSION); }

fs::path build_tree_plugin_dir() { return fs::path(MHD_BUILD_PLUGIN_DIR); }

fs::path build_tree_root() { return fs::path(MHD_BUILD_ROOT_DIR); }

fs::path installed_plugin_dir_from_bindir() { return fs::path(MHD_INSTALLED_PLUGIN_DIR_FROM_BINDIR); }

std::vector<PluginFolder> plugin_folders(const std::vector<fs::path>& command_line, std::string_view env_value,
                                         const fs::path& executable) {
  std::vector<PluginFolder> folders;
  std::set<fs::path> seen;
  auto add = [&](const fs::path& dir, PluginFolderSource source) {
    if (dir.empty()) return;
    if (seen.insert(identity_of(dir)).second) folders.push_back(PluginFolder{dir, source});
  };
  for (const fs::path& dir : command_line) add(dir, PluginFolderSource::CommandLine);
  while (!env_value.empty()) {
    const std::size_t colon = env_value.find(':');
    add(fs::path(env_value.substr(0, colon)), PluginFolderSource::Environment);
    env_value = colon == std::string_view::npos ? std::string_view() : env_value.substr(colon + 1);
  }
  bool installed = false;
  // A program in its own build tree has no installed folder: "<build>/tools/lib/..." would
  // be searched, and listed as missing, for nothing.
  const fs::path root = build_tree_root().lexically_normal();
  const fs::path relative = executable.lexically_normal().lexically_relative(root);
  const bool in_build_tree = !executable.empty() && !relative.empty() && *relative.begin() != "..";
  if (!executable.empty() && !in_build_tree) {
    const fs::path dir = (executable.parent_path() / installed_plugin_dir_from_bindir()).lexically_normal();
    add(dir, PluginFolderSource::Executable);
    std::error_code ec;
    installed = fs::is_directory(dir, ec);
  }
  // An installed mhd must not pick up plugins from whatever build tree it was made in.
  if (!installed) add(build_tree_plugin_dir(), PluginFolderSource::BuildTree);
  return folders;
}

PluginSearchPath::PluginSearchPath(std::vector<PluginFolder> folders) : folders_(std::move(folders)) {}

PluginSearchPath PluginSearchPath::standard(const std::vector<fs::path>& command_line) {
  const char* env = std::getenv("MHD_PLUGIN_PATH");
  std::error_code ec;
  const fs::path executable = fs::read_symlink("/proc/self/exe", ec);
  return PluginSearchPath(plugin_folders(command_line, env != nullptr ? env : "", ec ? fs::path() : executable));
}

Result<fs::path, PluginError> PluginSearchPath::find(std::string_view name) const {
  if (!is_valid_plugin_name(name)) {
    return PluginError{PluginErrorKind::NotFound, std::string(name), {},
                       fmt::format("not a valid plugin name ({})", kValidPluginNameRule)};
  }
  const std::string file = plugin_file_name(name);
  std::string searched;
  for (const PluginFolder& folder : folders_) {
    const fs::path candidate = folder.dir / file;
    std::error_code ec;
    const fs::file_status status = fs::symlink_status(candidate, ec);
    if (fs::exists(status) && !fs::is_directory(status)) return candidate;
    if (!searched.empty()) searched += ", ";
    searched += folder.dir.string();
  }
  if (searched.empty()) {
    return PluginError{PluginErrorKind::NotFound, std::string(name), {}, "not found (no plugin folders to search)"};
  }
  return PluginError{PluginErrorKind::NotFound, std::string(name), {},
                     fmt::format("not found (looked for {} in {})", file, searched)};
}

Result<std::shared_ptr<const PluginLibrary>, PluginError> PluginSearchPath::load(std::string_view name) const {
  Result<fs::path, PluginError> path = find(name);
  if (!path) return path.error();
  return PluginLibrary::load(path.value());
}

std::vector<PluginListing> PluginSearchPath::list() const {
  std::vector<PluginListing> listings;
  std::set<std::string> names_seen;
  for (const PluginFolder& folder : folders_) {
    std::error_code ec;
    std::vector<fs::path> files;
    for (fs::directory_iterator it(folder.dir, ec), end; !ec && it != end; it.increment(ec)) {
      if (is_plugin_file(*it)) files.push_back(it->path());
    }
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
      const bool shadowed = !names_seen.insert(plugin_name_from_file(file)).second;
      listings.push_back(PluginListing{file, probe_plugin_isolated(file), shadowed});
    }
  }
  return listings;
}

}  // namespace mhd
