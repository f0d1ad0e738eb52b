#pragma once
// Loading a plugin library runs its code: static constructors, then its entry point.
// Commands that only look at plugins (`mhd validate`, `mhd plugins`, Python's
// mhd.validate) do that in a child process, so a library that crashes, exits or hangs
// while it loads is reported as broken and cannot end, stall or change the caller.
// `mhd run` loads in-process: it is about to drive the plugin anyway.

#include "diagnostics/result.h"
#include "plugin_host/plugin_error.h"
#include "plugin_host/plugin_library.h"
#include "plugin_host/plugin_search_path.h"
#include "scene/scene_description.h"

#include <filesystem>
#include <functional>
#include <string>

namespace mhd {

/// How long a child may take to load one plugin before it is killed.
inline constexpr double kIsolatedLoadTimeout_s = 10.0;

/// Runs `work` in a child process and returns the bytes it returned, or a
/// PluginError{CrashedWhileLoading} for `plugin` and `path` saying how the child ended
/// (a signal, an exit before it answered, or no answer within `timeout_s`).
[[nodiscard]] Result<std::string, PluginError> run_isolated(const std::function<std::string()>& work,
                                                           const std::string& plugin, const std::filesystem::path& path,
                                                           double timeout_s = kIsolatedLoadTimeout_s);

/// check_scene_plugin() in a child process.
[[nodiscard]] Status<PluginError> check_scene_plugin_isolated(const PluginSearchPath& search,
                                                              const PluginDescription& description,
                                                              double timeout_s = kIsolatedLoadTimeout_s);

/// PluginLibrary::load(path) in a child process: what the plugin says about itself.
[[nodiscard]] Result<PluginInfo, PluginError> probe_plugin_isolated(const std::filesystem::path& path,
                                                                    double timeout_s = kIsolatedLoadTimeout_s);

}  // namespace mhd
