#include "mesh_io/triangle_budget.h"

#include <fmt/format.h>

namespace mhd {

std::string TriangleBudget::refusal(std::string_view what, std::uint64_t count, std::string_view noun) const {
  if (count <= left()) return {};
  const std::string subject = what.empty() ? fmt::format("{} {}", count, noun) : fmt::format("{} {} {}", what, count, noun);
  if (used == 0) return fmt::format("{}, more than max_triangles ({})", subject, max_triangles);
  return fmt::format("{}, more than the {} left of max_triangles ({}) after the scene's other {} triangles", subject,
                     left(), max_triangles, used);
}

}  // namespace mhd
