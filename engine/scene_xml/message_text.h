#pragma once
// Builds diagnostic messages without pulling a formatting library into the layer:
// concat("attribute '", name, "' needs ", 3, " numbers") and format_g(1e-9) == "1e-09".

#include <concepts>
#include <cstdio>
#include <string>
#include <string_view>

namespace mhd::scene_xml {

namespace message_detail {
inline void append(std::string& out, std::string_view s) { out += s; }
inline void append(std::string& out, const char* s) { out += s; }
inline void append(std::string& out, const std::string& s) { out += s; }
inline void append(std::string& out, char c) { out += c; }
template <std::integral T>
  requires(!std::same_as<T, char> && !std::same_as<T, bool>)
void append(std::string& out, T value) {
  out += std::to_string(value);
}
}  // namespace message_detail

template <typename... Parts>
[[nodiscard]] std::string concat(const Parts&... parts) {
  std::string out;
  (message_detail::append(out, parts), ...);
  return out;
}

/// printf's %g: six significant digits, e.g. 0.002, 1e-09, 1e+06.
[[nodiscard]] inline std::string format_g(double value) {
  char buffer[32];
  const int n = std::snprintf(buffer, sizeof buffer, "%g", value);
  return n > 0 ? std::string(buffer, static_cast<std::size_t>(n)) : std::string();
}

}  // namespace mhd::scene_xml
