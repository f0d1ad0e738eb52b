#pragma once
// A scene's triangle limit (max_triangles) as one mesh load sees it: the limit and how
// many triangles the scene has already loaded.

#include <cstdint>
#include <string>
#include <string_view>

namespace mhd {

struct TriangleBudget {
  std::uint64_t max_triangles = 0;
  std::uint64_t used = 0;  ///< triangles loaded before this mesh

  [[nodiscard]] std::uint64_t left() const { return used >= max_triangles ? 0 : max_triangles - used; }

  /// "" when `count` fits, else why not, e.g. "the header claims 100000000 faces, more
  /// than max_triangles (50000000)" for what = "the header claims", noun = "faces".
  [[nodiscard]] std::string refusal(std::string_view what, std::uint64_t count, std::string_view noun) const;
};

}  // namespace mhd
