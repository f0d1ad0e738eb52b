#include "plugin_host/scene_plugin_check.h"

#include <mhd/plugin_abi.h>

#include "plugin_host/plugin_kind.h"

#include <mhd/plugin_params.hpp>

#include <fmt/core.h>

#include <vector>

namespace mhd {

std::optional<std::string> declared_param_problems(const PluginLibrary& library,
                                                   const std::map<std::string, std::string>& params) {
  std::vector<mhd_param> abi_params;
  abi_params.reserve(params.size());
  for (const auto& [key, value] : params) abi_params.push_back(mhd_param{key.c_str(), value.c_str()});
  const mhd_plugin_api& api = library.api();
  const std::vector<std::string> problems =
      sdk::check_params(api.params, api.param_count, abi_params.data(), abi_params.size());
  if (problems.empty()) return std::nullopt;
  std::string message = problems.front();
  for (std::size_t i = 1; i < problems.size(); ++i) message += "; " + problems[i];
  return message;
}

Result<std::shared_ptr<const PluginLibrary>, PluginError> load_scene_plugin(const PluginSearchPath& search,
                                                                     const PluginDescription& description) {
  Result<std::shared_ptr<const PluginLibrary>, PluginError> library = search.load(description.name);
  if (!library) return library.error();
  const PluginLibrary& loaded = *library.value();
  if (loaded.kind() != description.kind) {
    return PluginError{PluginErrorKind::WrongKind, loaded.name(), loaded.path(),
                       fmt::format("is a {} plugin, the scene asks for a {}", to_string(loaded.kind()),
                                   to_string(description.kind))};
  }
  return library;
}

Status<PluginError> check_scene_plugin(const PluginSearchPath& search, const PluginDescription& description) {
  Result<std::shared_ptr<const PluginLibrary>, PluginError> library = load_scene_plugin(search, description);
  if (!library) return library.error();
  const PluginLibrary& loaded = *library.value();
  if (auto problems = declared_param_problems(loaded, description.params)) {
    return PluginError{PluginErrorKind::BadParameter, loaded.name(), {}, *problems};
  }
  return {};
}

}  // namespace mhd
