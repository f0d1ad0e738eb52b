#pragma once
// A counter a plugin keeps and hands the host through the ABI's counters call (e.g. the
// `dds` tracker's samples dropped per reason), and its one-line text for status lines.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mhd {

struct PluginCounter {
  std::string name;
  std::uint64_t value = 0;
};

/// Up to kMax of a plugin's counters, as a real-time thread hands them on without
/// allocating: the names are the plugin's own static strings, valid while it is loaded.
struct PluginCounterFrame {
  static constexpr std::size_t kMax = 32;
  std::array<const char*, kMax> names{};
  std::array<std::uint64_t, kMax> values{};
  std::size_t count = 0;

  [[nodiscard]] std::vector<PluginCounter> to_vector() const;
};

/// The non-zero counters named "dropped_<reason>", as "<reason> N, <reason> M"; empty
/// when nothing was dropped.
[[nodiscard]] std::string dropped_counts_text(const std::vector<PluginCounter>& counters);

}  // namespace mhd
