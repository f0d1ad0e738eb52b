#include "mesh_io/triangle_budget.h"

#include "mesh_io/byte_count_text.h"

#include <fmt/format.h>

#include <limits>

namespace mhd {
std::string TriangleBudget::refusal(std::string_view what, std::uint64_t count, std::string_view noun) const {
  if (count <= left()) return {};
  const std::string subject = what.empty() ? fmt::format("{} {}", count, noun) : fmt::format("{} {} {}", what, count, noun);
  if (used == 0) return fmt::format("{}, more than max_triangles ({})", subject, max_triangles);
  return fmt::format("{}, more than the {} left of max_triangles ({}) after the scene's other {} triangles", subject,
                     left(), max_triangles, used);
}

std::string TriangleBudget::memory_refusal(std::string_view what, std::uint64_t count, std::string_view noun,
                                           std::uint64_t bytes_per_triangle) const {
  if (memory_bytes == 0 || bytes_per_triangle == 0 || count <= memory_bytes / bytes_per_triangle) return {};
  constexpr std::uint64_t kNever = std::numeric_limits<std::uint64_t>::max();
  const std::string subject = what.empty() ? fmt::format("{} {}", count, noun) : fmt::format("{} {} {}", what, count, noun);
  return fmt::format("{}, about {} to load, more than the {} of memory available", subject,
                     byte_count_text(count > kNever / bytes_per_triangle ? kNever : count * bytes_per_triangle),
                     byte_count_text(memory_bytes));
}

}  // namespace mhd
