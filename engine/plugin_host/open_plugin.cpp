#include "plugin_host/open_plugin.h"

#include "plugin_host/plugin_kind.h"

#include <fmt/core.h>

#include <utility>

namespace mhd {

PluginResult<PluginInstance> open_plugin(const PluginSearchPath& search, const PluginDescription& description,
                                         const mhd_host& host) {
  PluginResult<std::shared_ptr<const PluginLibrary>> library = search.load(description.name);
  if (!library) return library.error();
  const PluginLibrary& loaded = *library.value();
  if (loaded.kind() != description.kind) {
    return PluginError{PluginErrorKind::WrongKind, loaded.name(), loaded.path(),
                       fmt::format("is a {} plugin, the scene asks for a {}", to_string(loaded.kind()),
                                   to_string(description.kind))};
  }
  PluginInstance instance(std::move(library).value());
  if (PluginStatus opened = instance.open(description.params, host); !opened) return opened.error();
  return instance;
}

}  // namespace mhd
