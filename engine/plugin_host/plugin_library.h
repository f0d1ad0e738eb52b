#pragma once
// One plugin file, loaded and checked: refused when other users may write it or its
// folder (plugin_file_trust.h), else dlopen (RTLD_NOW | RTLD_LOCAL), then
// mhd_plugin_entry(MHD_PLUGIN_ABI_VERSION), then the table is checked in this order:
// abi_version, struct_size, kind, name (non-empty; equal to N for a file libmhd_N.so),
// lifecycle pointers and the kind's mandatory calls (device: device_info,
// device_read, device_write; tracker: tracker_read; base: base_read, base_write;
// display: display_write). Any failure unloads the file and returns the reason.
// The library stays loaded while a PluginLibrary exists; instances share it.

#include "diagnostics/result.h"
#include "plugin_host/plugin_error.h"
#include "scene/scene_description.h"

#include <filesystem>
#include <memory>
#include <string>

struct mhd_plugin_api;  // the plugin's table (mhd/plugin_abi.h): whoever reads it includes that

namespace mhd {

/// What a plugin says about itself (copied out of the library).
struct PluginInfo {
  PluginKind kind = PluginKind::Device;
  std::string name;
  std::string version;      ///< empty when the plugin gives none
  std::string description;  ///< empty when the plugin gives none
};

class PluginLibrary {
 public:
  /// Loads and checks `path`. Errors name the plugin by its file name (libmhd_N.so: N).
  [[nodiscard]] static Result<std::shared_ptr<const PluginLibrary>, PluginError> load(const std::filesystem::path& path);

  ~PluginLibrary();
  PluginLibrary(const PluginLibrary&) = delete;
  PluginLibrary& operator=(const PluginLibrary&) = delete;
  PluginLibrary(PluginLibrary&&) = delete;
  PluginLibrary& operator=(PluginLibrary&&) = delete;

  /// The checked table; valid while this object lives.
  [[nodiscard]] const mhd_plugin_api& api() const noexcept { return *api_; }
  [[nodiscard]] const PluginInfo& info() const noexcept { return info_; }
  [[nodiscard]] const std::string& name() const noexcept { return info_.name; }
  [[nodiscard]] PluginKind kind() const noexcept { return info_.kind; }
  [[nodiscard]] const std::filesystem::path& path() const noexcept { return path_; }

 private:
  PluginLibrary(void* handle, const mhd_plugin_api* api, PluginInfo info, std::filesystem::path path);

  void* handle_;
  const mhd_plugin_api* api_;
  PluginInfo info_;
  std::filesystem::path path_;
};

}  // namespace mhd
