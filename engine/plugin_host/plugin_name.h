#pragma once
// Plugin names and their files: plugin N lives in "libmhd_N.so". A name is what a scene
// writes in <plugin name="..."> and what find() looks up, so it may not hold a path.

#include <filesystem>
#include <string>
#include <string_view>

namespace mhd {

inline constexpr std::string_view kValidPluginNameRule = "letters, digits, '_' and '-' only";

/// Non-empty and only [A-Za-z0-9_-].
[[nodiscard]] bool is_valid_plugin_name(std::string_view name);

/// "libmhd_N.so" for N.
[[nodiscard]] std::string plugin_file_name(std::string_view name);

/// N for a file "libmhd_N.so" (any folder); empty for a file not named that way.
[[nodiscard]] std::string plugin_name_from_file(const std::filesystem::path& path);

}  // namespace mhd
