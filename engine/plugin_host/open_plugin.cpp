#include "plugin_host/open_plugin.h"

#include <mhd/plugin_abi.h>

#include "plugin_host/scene_plugin_check.h"

#include <utility>

namespace mhd {

Result<PluginInstance, PluginError> open_plugin(const PluginSearchPath& search, const PluginDescription& description,
                                         const mhd_host& host) {
  Result<std::shared_ptr<const PluginLibrary>, PluginError> library = load_scene_plugin(search, description);
  if (!library) return library.error();
  PluginInstance instance(std::move(library).value());
  if (Status<PluginError> opened = instance.open(description.params, host); !opened) return opened.error();
  return instance;
}

}  // namespace mhd
