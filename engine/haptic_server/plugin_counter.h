#pragma once
// A counter a plugin keeps and hands the host through the ABI's counters call (e.g. the
// `dds` tracker's samples dropped per reason), and its one-line text for status lines.

#include <cstdint>
#include <string>
#include <vector>

namespace mhd {

struct PluginCounter {
  std::string name;
  std::uint64_t value = 0;
};

/// The non-zero counters named "dropped_<reason>", as "<reason> N, <reason> M"; empty
/// when nothing was dropped.
[[nodiscard]] std::string dropped_counts_text(const std::vector<PluginCounter>& counters);

}  // namespace mhd
