#include "plugin_host/plugin_kind.h"

namespace mhd {

mhd_plugin_kind to_abi_kind(PluginKind kind) {
  switch (kind) {
    case PluginKind::Device: return MHD_KIND_DEVICE;
    case PluginKind::Tracker: return MHD_KIND_TRACKER;
    case PluginKind::Base: return MHD_KIND_BASE;
    case PluginKind::Display: return MHD_KIND_DISPLAY;
  }
  return MHD_KIND_DEVICE;
}

std::optional<PluginKind> plugin_kind_from_abi(std::uint32_t raw_kind) {
  switch (raw_kind) {
    case MHD_KIND_DEVICE: return PluginKind::Device;
    case MHD_KIND_TRACKER: return PluginKind::Tracker;
    case MHD_KIND_BASE: return PluginKind::Base;
    case MHD_KIND_DISPLAY: return PluginKind::Display;
    default: return std::nullopt;
  }
}

std::string_view to_string(PluginKind kind) {
  switch (kind) {
    case PluginKind::Device: return "device";
    case PluginKind::Tracker: return "tracker";
    case PluginKind::Base: return "base";
    case PluginKind::Display: return "display";
  }
  return "unknown";
}

}  // namespace mhd
