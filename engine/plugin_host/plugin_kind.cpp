#include "plugin_host/plugin_kind.h"

#include <mhd/plugin_abi.h>

namespace mhd {

std::optional<PluginKind> plugin_kind_from_abi(std::uint32_t raw_kind) {
  switch (raw_kind) {
    case MHD_KIND_DEVICE: return PluginKind::Device;
    case MHD_KIND_TRACKER: return PluginKind::Tracker;
    case MHD_KIND_BASE: return PluginKind::Base;
    case MHD_KIND_DISPLAY: return PluginKind::Display;
    case MHD_KIND_LINK: return PluginKind::Link;
    default: return std::nullopt;
  }
}

std::string_view to_string(PluginKind kind) {
  switch (kind) {
    case PluginKind::Device: return "device";
    case PluginKind::Tracker: return "tracker";
    case PluginKind::Base: return "base";
    case PluginKind::Display: return "display";
    case PluginKind::Link: return "link";
  }
  return "unknown";
}

}  // namespace mhd
