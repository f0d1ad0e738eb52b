#pragma once
// Where the test plugins (tests/plugin_host/plugins, built by CMake) are.

#include <filesystem>
#include <string>
#include <string_view>

namespace mhd::test {

inline std::filesystem::path test_plugin_dir() { return MHD_TEST_PLUGIN_DIR; }

/// The test folder's libmhd_NAME.so.
inline std::filesystem::path test_plugin(std::string_view name) {
  return test_plugin_dir() / ("libmhd_" + std::string(name) + ".so");
}

/// The example display plugin in the build tree's plugin folder.
inline std::filesystem::path null_display_plugin() { return MHD_NULL_DISPLAY_PLUGIN; }

}  // namespace mhd::test
