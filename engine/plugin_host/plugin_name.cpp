#include "plugin_host/plugin_name.h"

#include <algorithm>

namespace mhd {
namespace {

constexpr std::string_view kPrefix = "libmhd_";
constexpr std::string_view kSuffix = ".so";

bool is_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

}  // namespace

bool is_valid_plugin_name(std::string_view name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), is_name_char);
}

std::string plugin_file_name(std::string_view name) {
  std::string out(kPrefix);
  out += name;
  out += kSuffix;
  return out;
}

std::string plugin_name_from_file(const std::filesystem::path& path) {
  const std::string file = path.filename().string();
  if (file.size() <= kPrefix.size() + kSuffix.size()) return {};
  if (file.compare(0, kPrefix.size(), kPrefix) != 0) return {};
  if (file.compare(file.size() - kSuffix.size(), kSuffix.size(), kSuffix) != 0) return {};
  return file.substr(kPrefix.size(), file.size() - kPrefix.size() - kSuffix.size());
}

}  // namespace mhd
