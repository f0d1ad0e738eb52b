#pragma once
// Why the host refused or lost a plugin. Every failure of loading, checking or driving
// a plugin is one of these kinds, with a message that names the plugin (and its file,
// while loading); tests compare the messages exactly.

#include <filesystem>
#include <string>
#include <string_view>

namespace mhd {

enum class PluginErrorKind {
  NotFound,            ///< no file of that name in any plugin folder (or an invalid name)
  Untrusted,           ///< the file or its folder is writable by other users (plugin_file_trust.h)
  NotALibrary,         ///< dlopen failed (not ELF, wrong architecture, missing dependency)
  CrashedWhileLoading, ///< loading it in a child process crashed, ended or hung it (isolated_load.h)
  NoEntryPoint,        ///< the library exports no mhd_plugin_entry
  EntryReturnedNull,   ///< the plugin refused this host's ABI version
  AbiVersionMismatch,  ///< the table's abi_version is not MHD_PLUGIN_ABI_VERSION
  StructSizeMismatch,  ///< the table's struct_size is not sizeof(mhd_plugin_api)
  WrongKind,           ///< unknown kind, or not the kind the caller asked for
  BadTable,            ///< missing name or mandatory function pointers
  BadParameter,        ///< a scene parameter the plugin's declarations refuse (checked before open)
  OpenFailed,          ///< open() returned NULL
  StartFailed,         ///< start() returned MHD_ERROR
  StopFailed,          ///< stop() returned MHD_ERROR
  CallFailed,          ///< a read/write call returned MHD_ERROR
  InvalidData,         ///< the plugin returned a value the host rejects (NaN, range, status)
  WrongState,          ///< a call out of lifecycle order (host bug, refused before the plugin sees it)
};

/// "not-found", "abi-version-mismatch", ...: stable names for logs and tests.
[[nodiscard]] std::string_view to_string(PluginErrorKind kind);

struct PluginError {
  PluginErrorKind kind = PluginErrorKind::NotFound;
  std::string plugin;           ///< plugin name (from the table, else from the file name)
  std::filesystem::path path;   ///< the file; empty for errors of a running plugin
  std::string message;          ///< what went wrong, without the plugin and path

  /// "plugin 'NAME' (PATH): MESSAGE", or "plugin 'NAME': MESSAGE" when path is empty.
  [[nodiscard]] std::string to_string() const;
};

}  // namespace mhd
