#pragma once
// A plugin runs with the user's rights, so a plugin file that other users may change, or
// a folder where they may put or replace one, lets them run code as this user. Such a
// file is refused before dlopen, unless MHD_ALLOW_WRITABLE_PLUGINS=1 opts in. The file
// and its folder are checked both as named and with links resolved; a group-writable
// file or folder is the user's own choice (Debian's private groups) and is accepted.

#include <filesystem>
#include <optional>
#include <string>

namespace mhd {

/// The name of the variable that opts in, and the value that does.
inline constexpr const char* kAllowWritablePluginsVariable = "MHD_ALLOW_WRITABLE_PLUGINS";

/// Why `plugin_file` must not be loaded, or nothing when it may be (or the user opted in).
[[nodiscard]] std::optional<std::string> untrusted_plugin_file_reason(const std::filesystem::path& plugin_file);

}  // namespace mhd
