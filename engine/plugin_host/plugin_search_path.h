#pragma once
// Where plugins are found. Folders are searched in this order:
//   1. --plugin-path folders from the command line, in the order given;
//   2. $MHD_PLUGIN_PATH, colon-separated (empty entries skipped);
//   3. <executable's folder>/../lib/mhd/plugins-abi<N> (an installed mhd; "lib" is the
//      install's libdir, see installed_plugin_dir_from_bindir()), unless the executable
//      lies in the build tree it was built in;
//   4. the build tree's <build>/lib/mhd/plugins-abi<N> (MHD_BUILD_PLUGIN_DIR), only when
//      folder 3 does not exist: an installed mhd never loads plugins from a build tree.
// N is MHD_PLUGIN_ABI_VERSION: a host never even looks at plugins of another ABI.
// Plugin NAME is the file libmhd_NAME.so; the first folder holding it wins, whether or
// not that file loads (a broken file is reported, never silently skipped).

#include "plugin_host/plugin_library.h"
#include "diagnostics/result.h"
#include "plugin_host/plugin_error.h"

#include <filesystem>
#include <memory>
#include <string_view>
#include <vector>

namespace mhd {

enum class PluginFolderSource { CommandLine, Environment, Executable, BuildTree, Given };

/// "--plugin-path", "MHD_PLUGIN_PATH", "installed", "build tree", "given".
[[nodiscard]] std::string_view to_string(PluginFolderSource source);

struct PluginFolder {
  std::filesystem::path dir;
  PluginFolderSource source = PluginFolderSource::Given;
};

/// "mhd/plugins-abi<MHD_PLUGIN_ABI_VERSION>": the versioned folder under a lib folder.
[[nodiscard]] std::filesystem::path versioned_plugin_subdir();

/// The build tree's plugin folder (where mhd_add_plugin puts plugins).
[[nodiscard]] std::filesystem::path build_tree_plugin_dir();

/// The build tree this library was built in (CMake's top binary folder).
[[nodiscard]] std::filesystem::path build_tree_root();

/// Where `cmake --install` puts plugins, relative to the folder it puts mhd in, e.g.
/// "../lib/mhd/plugins-abi6" ("../lib/x86_64-linux-gnu/..." for a /usr prefix on Debian).
/// Ends with versioned_plugin_subdir().
[[nodiscard]] std::filesystem::path installed_plugin_dir_from_bindir();

/// The search order above from its inputs: `env_value` is $MHD_PLUGIN_PATH's value and
/// `executable` the running program (either may be empty). A folder named twice keeps
/// its first place. The build tree's folder is left out when the executable's installed
/// plugin folder exists; the installed one, when the executable lies in the build tree.
[[nodiscard]] std::vector<PluginFolder> plugin_folders(const std::vector<std::filesystem::path>& command_line,
                                                       std::string_view env_value,
                                                       const std::filesystem::path& executable);

/// One plugin file found by list().
struct PluginListing {
  std::filesystem::path path;
  Result<PluginInfo, PluginError> loaded;  ///< what the plugin says, or why it did not load
  bool shadowed = false;            ///< an earlier folder holds the same name; find() never returns this file
};

class PluginSearchPath {
 public:
  explicit PluginSearchPath(std::vector<PluginFolder> folders);

  /// The standard order, reading $MHD_PLUGIN_PATH and /proc/self/exe.
  [[nodiscard]] static PluginSearchPath standard(const std::vector<std::filesystem::path>& command_line);

  [[nodiscard]] const std::vector<PluginFolder>& folders() const noexcept { return folders_; }

  /// The first folder's libmhd_NAME.so; NotFound names every folder searched.
  [[nodiscard]] Result<std::filesystem::path, PluginError> find(std::string_view name) const;

  /// find() and PluginLibrary::load().
  [[nodiscard]] Result<std::shared_ptr<const PluginLibrary>, PluginError> load(std::string_view name) const;

  /// Every libmhd_*.so in every folder, folder by folder in search order and by file
  /// name within a folder; each is loaded in a child process (isolated_load.h) to read
  /// what it says. A file that does not load is listed with its error.
  [[nodiscard]] std::vector<PluginListing> list() const;

 private:
  std::vector<PluginFolder> folders_;
};

}  // namespace mhd
