#include "mesh_io/triangle_budget.h"

#include <fmt/format.h>

#include <limits>

namespace mhd {
namespace {

std::string bytes_text(std::uint64_t bytes) {
  if (bytes < (std::uint64_t{1} << 20)) return fmt::format("{} bytes", bytes);
  if (bytes < (std::uint64_t{1} << 30)) return fmt::format("{:.1f} MiB", static_cast<double>(bytes) / (1 << 20));
  return fmt::format("{:.1f} GiB", static_cast<double>(bytes) / (1 << 30));
}

}  // namespace

std::string TriangleBudget::refusal(std::string_view what, std::uint64_t count, std::string_view noun) const {
  if (count <= left()) return {};
  const std::string subject = what.empty() ? fmt::format("{} {}", count, noun) : fmt::format("{} {} {}", what, count, noun);
  if (used == 0) return fmt::format("{}, more than max_triangles ({})", subject, max_triangles);
  return fmt::format("{}, more than the {} left of max_triangles ({}) after the scene's other {} triangles", subject,
                     left(), max_triangles, used);
}

std::string TriangleBudget::memory_refusal(std::string_view what, std::uint64_t count, std::string_view noun) const {
  if (memory_bytes == 0 || count <= memory_bytes / kLoadBytesPerTriangle) return {};
  constexpr std::uint64_t kNever = std::numeric_limits<std::uint64_t>::max();
  const std::string subject = what.empty() ? fmt::format("{} {}", count, noun) : fmt::format("{} {} {}", what, count, noun);
  return fmt::format("{}, about {} to load, more than the {} of memory available", subject,
                     bytes_text(count > kNever / kLoadBytesPerTriangle ? kNever : count * kLoadBytesPerTriangle),
                     bytes_text(memory_bytes));
}

}  // namespace mhd
