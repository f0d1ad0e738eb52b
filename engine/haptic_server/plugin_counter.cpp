#include "haptic_server/plugin_counter.h"

#include <string_view>

namespace mhd {

std::string dropped_counts_text(const std::vector<PluginCounter>& counters) {
  constexpr std::string_view kPrefix = "dropped_";
  std::string out;
  for (const PluginCounter& c : counters) {
    if (c.value == 0 || !std::string_view(c.name).starts_with(kPrefix)) continue;
    if (!out.empty()) out += ", ";
    out += c.name.substr(kPrefix.size()) + " " + std::to_string(c.value);
  }
  return out;
}

}  // namespace mhd
