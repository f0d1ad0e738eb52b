#pragma once
// A byte count as a person reads it in a message: "350 bytes", "12.5 MiB", "16.3 GiB".

#include <fmt/format.h>

#include <cstdint>
#include <string>

namespace mhd {

[[nodiscard]] inline std::string byte_count_text(std::uint64_t bytes) {
  if (bytes < (std::uint64_t{1} << 20)) return fmt::format("{} bytes", bytes);
  if (bytes < (std::uint64_t{1} << 30)) return fmt::format("{:.1f} MiB", static_cast<double>(bytes) / (1 << 20));
  return fmt::format("{:.1f} GiB", static_cast<double>(bytes) / (1 << 30));
}

}  // namespace mhd
