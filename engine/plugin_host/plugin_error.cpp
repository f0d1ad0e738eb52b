#include "plugin_host/plugin_error.h"

namespace mhd {

std::string_view to_string(PluginErrorKind kind) {
  switch (kind) {
    case PluginErrorKind::NotFound: return "not-found";
    case PluginErrorKind::Untrusted: return "untrusted";
    case PluginErrorKind::NotALibrary: return "not-a-library";
    case PluginErrorKind::CrashedWhileLoading: return "crashed-while-loading";
    case PluginErrorKind::NoEntryPoint: return "no-entry-point";
    case PluginErrorKind::EntryReturnedNull: return "entry-returned-null";
    case PluginErrorKind::AbiVersionMismatch: return "abi-version-mismatch";
    case PluginErrorKind::StructSizeMismatch: return "struct-size-mismatch";
    case PluginErrorKind::WrongKind: return "wrong-kind";
    case PluginErrorKind::BadTable: return "bad-table";
    case PluginErrorKind::BadParameter: return "bad-parameter";
    case PluginErrorKind::OpenFailed: return "open-failed";
    case PluginErrorKind::StartFailed: return "start-failed";
    case PluginErrorKind::StopFailed: return "stop-failed";
    case PluginErrorKind::CallFailed: return "call-failed";
    case PluginErrorKind::InvalidData: return "invalid-data";
    case PluginErrorKind::WrongState: return "wrong-state";
  }
  return "unknown";
}

std::string PluginError::to_string() const {
  std::string out = "plugin '" + plugin + "'";
  if (!path.empty()) out += " (" + path.string() + ")";
  out += ": ";
  out += message;
  return out;
}

}  // namespace mhd
