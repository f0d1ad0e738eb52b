#pragma once
// The role a plugin plays in a scene. The scene names it (<plugin kind="device" ...>), so
// the enum belongs to the scene layer; plugin_host, which sits above the scene and reads
// its descriptions, maps it to the ABI's kinds and to these names
// (plugin_host/plugin_kind.h). Putting it in plugin_host would make the scene depend on
// the layer that loads plugins.

namespace mhd {

enum class PluginKind { Device, Tracker, Base, Display, Link };

}  // namespace mhd
