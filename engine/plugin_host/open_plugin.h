#pragma once
// A scene's plugin, from <plugin kind="..." name="..."> to an open instance: find the
// file, load and check it, check that it is the kind the scene asks for, and open it
// with the scene's parameters.

#include "plugin_host/plugin_instance.h"
#include "diagnostics/result.h"
#include "plugin_host/plugin_error.h"
#include "plugin_host/plugin_search_path.h"
#include "scene/scene_description.h"

namespace mhd {

/// An Open instance, or the first error (NotFound ... WrongKind ... OpenFailed).
/// `host` must outlive the instance.
[[nodiscard]] Result<PluginInstance, PluginError> open_plugin(const PluginSearchPath& search,
                                                       const PluginDescription& description, const mhd_host& host);

}  // namespace mhd
