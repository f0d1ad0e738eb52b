#include "plugin_host/plugin_library.h"

#include "plugin_host/plugin_file_trust.h"
#include "plugin_host/plugin_kind.h"
#include "plugin_host/plugin_name.h"

#include <mhd/plugin_abi.h>
#include <mhd/plugin_params.hpp>

#include <fmt/core.h>

#include <dlfcn.h>

#include <cstdint>
#include <cstring>
#include <optional>
#include <system_error>
#include <utility>
#include <vector>

namespace mhd {
namespace {

namespace fs = std::filesystem;

struct DlCloser {
  void operator()(void* handle) const noexcept { dlclose(handle); }
};
using DlHandle = std::unique_ptr<void, DlCloser>;

/// dlerror() text without the leading "PATH: " glibc puts there (the error names the path).
std::string dl_error_text(const fs::path& absolute) {
  const char* raw = dlerror();
  std::string text = raw != nullptr ? raw : "unknown dlopen error";
  const std::string prefix = absolute.string() + ": ";
  if (text.compare(0, prefix.size(), prefix) == 0) text.erase(0, prefix.size());
  return text;
}

/// Names of the null pointers among those every plugin, and its kind, must provide.
std::vector<std::string_view> missing_functions(const mhd_plugin_api& api, PluginKind kind) {
  std::vector<std::string_view> missing;
  auto need = [&missing](bool present, std::string_view what) {
    if (!present) missing.push_back(what);
  };
  need(api.open != nullptr, "open");
  need(api.start != nullptr, "start");
  need(api.stop != nullptr, "stop");
  need(api.close != nullptr, "close");
  switch (kind) {
    case PluginKind::Device:
      need(api.device_info != nullptr, "device_info");
      need(api.device_read != nullptr, "device_read");
      need(api.device_write != nullptr, "device_write");
      break;
    case PluginKind::Tracker: need(api.tracker_read != nullptr, "tracker_read"); break;
    case PluginKind::Base:
      need(api.base_read != nullptr, "base_read");
      need(api.base_write != nullptr, "base_write");
      break;
    case PluginKind::Display: need(api.display_write != nullptr, "display_write"); break;
    case PluginKind::Link:
      need(api.link_send != nullptr, "link_send");
      need(api.link_read != nullptr, "link_read");
      break;
  }
  return missing;
}

std::string join(const std::vector<std::string_view>& items) {
  std::string out;
  for (std::string_view item : items) {
    if (!out.empty()) out += ", ";
    out += item;
  }
  return out;
}

std::string or_empty(const char* text) { return text != nullptr ? std::string(text) : std::string(); }

}  // namespace

PluginLibrary::PluginLibrary(void* handle, const mhd_plugin_api* api, PluginInfo info, fs::path path)
    : handle_(handle), api_(api), info_(std::move(info)), path_(std::move(path)) {}

PluginLibrary::~PluginLibrary() { dlclose(handle_); }

Result<std::shared_ptr<const PluginLibrary>, PluginError> PluginLibrary::load(const fs::path& path) {
  const std::string file_name = plugin_name_from_file(path);
  auto fail = [&](PluginErrorKind kind, std::string message, const std::string& plugin = {}) {
    return PluginError{kind, plugin.empty() ? (file_name.empty() ? path.filename().string() : file_name) : plugin,
                       path, std::move(message)};
  };

  std::error_code ec;
  if (!fs::exists(path, ec)) return fail(PluginErrorKind::NotFound, "no such file");
  const fs::path absolute = fs::absolute(path, ec);
  if (std::optional<std::string> untrusted = untrusted_plugin_file_reason(absolute)) {
    return fail(PluginErrorKind::Untrusted, std::move(*untrusted));
  }

  dlerror();
  DlHandle handle(dlopen(absolute.c_str(), RTLD_NOW | RTLD_LOCAL));
  if (!handle) {
    return fail(PluginErrorKind::NotALibrary, fmt::format("not a loadable library ({})", dl_error_text(absolute)));
  }

  dlerror();
  void* symbol = dlsym(handle.get(), MHD_PLUGIN_ENTRY_SYMBOL);
  if (symbol == nullptr) return fail(PluginErrorKind::NoEntryPoint, "exports no " MHD_PLUGIN_ENTRY_SYMBOL);
  const auto entry = reinterpret_cast<mhd_plugin_entry_fn>(symbol);

  const mhd_plugin_api* api = entry(MHD_PLUGIN_ABI_VERSION);
  if (api == nullptr) {
    // A plugin built for another ABI refuses this host's version. Asking for the older
    // versions (each answer is a static table or NULL) tells the user which it speaks.
    for (std::uint32_t older = MHD_PLUGIN_ABI_VERSION - 1; older >= 1; --older) {
      const mhd_plugin_api* old_api = entry(older);
      if (old_api != nullptr && old_api->abi_version == older) {
        return fail(PluginErrorKind::AbiVersionMismatch,
                    fmt::format("built for plugin ABI {}, this host speaks ABI {}: rebuild it against this MHD's "
                                "mhd/plugin_abi.h (docs/plugins.md, \"Porting a plugin to ABI {}\")",
                                older, MHD_PLUGIN_ABI_VERSION, MHD_PLUGIN_ABI_VERSION));
      }
    }
    return fail(PluginErrorKind::EntryReturnedNull,
                fmt::format("refused this host ({}({}) returned NULL)", MHD_PLUGIN_ENTRY_SYMBOL, MHD_PLUGIN_ABI_VERSION));
  }
  // abi_version and struct_size open every version of the table, so they are safe to read first.
  if (api->abi_version != MHD_PLUGIN_ABI_VERSION) {
    return fail(PluginErrorKind::AbiVersionMismatch,
                fmt::format("ABI version {}, this host speaks {}", api->abi_version, MHD_PLUGIN_ABI_VERSION));
  }
  if (api->struct_size != sizeof(mhd_plugin_api)) {
    return fail(PluginErrorKind::StructSizeMismatch,
                fmt::format("plugin table is {} bytes, this host's is {} (built against another plugin_abi.h)",
                            api->struct_size, sizeof(mhd_plugin_api)));
  }
  std::uint32_t raw_kind = 0;
  static_assert(sizeof(raw_kind) == sizeof(api->kind));
  std::memcpy(&raw_kind, &api->kind, sizeof(raw_kind));  // any number may be there; not read as the enum
  const std::optional<PluginKind> kind = plugin_kind_from_abi(raw_kind);
  if (!kind) return fail(PluginErrorKind::WrongKind, fmt::format("unknown kind {}", raw_kind));

  const std::string name = or_empty(api->name);
  if (name.empty()) return fail(PluginErrorKind::BadTable, "the table gives no name");
  if (!is_valid_plugin_name(name)) {
    return fail(PluginErrorKind::BadTable,
                fmt::format("the table's name '{}' is not a valid plugin name ({})", name, kValidPluginNameRule));
  }
  if (!file_name.empty() && name != file_name) {
    return fail(PluginErrorKind::BadTable,
                fmt::format("the table names the plugin '{}', the file is named for '{}'", name, file_name));
  }
  const std::vector<std::string_view> missing = missing_functions(*api, *kind);
  if (!missing.empty()) {
    return fail(PluginErrorKind::BadTable,
                fmt::format("the table lacks {} (mandatory for a {} plugin)", join(missing), to_string(*kind)), name);
  }

  if (auto problem = sdk::check_declarations(api->params, api->param_count)) {
    return fail(PluginErrorKind::BadTable, *problem, name);
  }

  PluginInfo info{*kind, name, or_empty(api->version), or_empty(api->description)};
  return std::shared_ptr<const PluginLibrary>(new PluginLibrary(handle.release(), api, std::move(info), path));
}

}  // namespace mhd
