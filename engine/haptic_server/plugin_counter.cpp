#include "haptic_server/plugin_counter.h"

#include <string_view>

namespace mhd {

std::vector<PluginCounter> PluginCounterFrame::to_vector() const {
  std::vector<PluginCounter> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count && i < kMax; ++i) out.push_back({names[i], values[i]});
  return out;
}

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
