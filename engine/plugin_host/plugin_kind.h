#pragma once
// The plugin kinds (scene/plugin_kind.h) as the ABI numbers them and as the scene names them.

#include "scene/plugin_kind.h"

#include <cstdint>
#include <optional>
#include <string_view>

namespace mhd {

/// The kind a table's raw kind field names; nullopt outside 1..5. Takes the raw number
/// because a plugin may put any value there (reading it as the enum would be UB).
[[nodiscard]] std::optional<PluginKind> plugin_kind_from_abi(std::uint32_t raw_kind);

/// "device", "tracker", "base", "display", "link" (the scene's <plugin kind="...">).
[[nodiscard]] std::string_view to_string(PluginKind kind);

}  // namespace mhd
