#include "plugin_host/plugin_file_trust.h"

#include <fmt/core.h>

#include <sys/stat.h>

#include <cstdlib>
#include <cstring>
#include <system_error>
#include <vector>

namespace mhd {
namespace {

namespace fs = std::filesystem;

bool opted_in() {
  const char* value = std::getenv(kAllowWritablePluginsVariable);
  return value != nullptr && std::strcmp(value, "1") == 0;
}

/// "the file P is writable by other users (mode 0757)" when others may write `path`.
std::optional<std::string> writable_by_others(const fs::path& path, const char* what) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return std::nullopt;  // a missing file fails later, with its own error
  if ((info.st_mode & S_IWOTH) == 0) return std::nullopt;
  return fmt::format("the {} {} is writable by other users (mode {:04o})", what, path.string(), info.st_mode & 07777);
}

}  // namespace

std::optional<std::string> untrusted_plugin_file_reason(const fs::path& plugin_file) {
  if (opted_in()) return std::nullopt;
  std::error_code ec;
  const fs::path named = fs::absolute(plugin_file, ec).lexically_normal();
  std::vector<fs::path> files{named};
  const fs::path resolved = fs::canonical(named, ec);
  if (!ec && resolved != named) files.push_back(resolved);
  for (const fs::path& file : files) {
    std::optional<std::string> reason = writable_by_others(file, "file");
    // The sticky bit does not help: others may still add a plugin of a new name.
    if (!reason) reason = writable_by_others(file.parent_path(), "folder");
    if (reason) {
      return fmt::format("{}, so they could run code as you: remove their write permission (chmod o-w), or set "
                         "{}=1 to load it anyway",
                         *reason, kAllowWritablePluginsVariable);
    }
  }
  return std::nullopt;
}

}  // namespace mhd
