#pragma once
// What the host can say about a scene's <plugin> without opening it (no hardware moves):
// the file is found and loads, it is the kind the scene asks for, and the scene's
// parameters pass the plugin's declarations (ABI 3, mhd/plugin_params.hpp). `mhd
// validate` reports these; `mhd run` refuses the same things before open().

#include "plugin_host/plugin_library.h"
#include "diagnostics/result.h"
#include "plugin_host/plugin_error.h"
#include "plugin_host/plugin_search_path.h"
#include "scene/scene_description.h"

#include <map>
#include <memory>
#include <optional>
#include <string>

namespace mhd {

/// Every problem of `params` against the declarations of `library`, joined by "; "
/// ("unknown parameter 'x' (known: a, b)", "parameter 'rate_hz' must be a number > 0
/// (Hz), got 'abc'"), or nothing when open() may be called.
[[nodiscard]] std::optional<std::string> declared_param_problems(const PluginLibrary& library,
                                                                 const std::map<std::string, std::string>& params);

/// Loads the plugin the scene names and checks it is the kind the scene asks for: the
/// library, or the first error (NotFound ... WrongKind). open_plugin and
/// check_scene_plugin both start here.
[[nodiscard]] Result<std::shared_ptr<const PluginLibrary>, PluginError> load_scene_plugin(
    const PluginSearchPath& search, const PluginDescription& description);

/// Loads the plugin the scene names (and unloads it again), checks its kind and the
/// scene's parameters: the first error (NotFound ... WrongKind, BadParameter), else ok.
[[nodiscard]] Status<PluginError> check_scene_plugin(const PluginSearchPath& search, const PluginDescription& description);

}  // namespace mhd
