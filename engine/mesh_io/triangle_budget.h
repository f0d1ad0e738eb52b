#pragma once
// A scene's triangle limit (max_triangles) as one mesh load sees it: the limit and how
// many triangles the scene has already loaded.

#include <cstdint>
#include <string>
#include <string_view>

namespace mhd {

struct TriangleBudget {
  /// Peak bytes a load takes per triangle (assimp's copy, the mesh, normals and tree),
  /// with a twentieth to spare: 7.1 GB at 50 M triangles and 14.2 GB at 100 M, 142 bytes
  /// a triangle, measured with /usr/bin/time on `mhd validate` (docs/benchmarks.md,
  /// "Meshes at size").
  static constexpr std::uint64_t kLoadBytesPerTriangle = 150;
  /// Resident bytes a cached mesh takes per triangle once adopted from its entry: 58 at
  /// 100 M triangles (docs/benchmarks.md, "Meshes at size"), rounded up.
  static constexpr std::uint64_t kCachedBytesPerTriangle = 60;

  std::uint64_t max_triangles = 0;
  std::uint64_t used = 0;  ///< triangles loaded before this mesh
  /// Memory the load may take (available_memory_bytes()); 0: not checked.
  std::uint64_t memory_bytes = 0;

  [[nodiscard]] std::uint64_t left() const { return used >= max_triangles ? 0 : max_triangles - used; }

  /// "" when `count` fits, else why not, e.g. "the header claims 100000000 faces, more
  /// than max_triangles (50000000)" for what = "the header claims", noun = "faces".
  [[nodiscard]] std::string refusal(std::string_view what, std::uint64_t count, std::string_view noun) const;

  /// "" when loading `count` triangles at `bytes_per_triangle` fits memory_bytes (or it is
  /// 0), else why not, e.g. "the header claims 100000000 faces, about 14.0 GiB to load,
  /// more than the 12.0 GiB of memory available".
  [[nodiscard]] std::string memory_refusal(std::string_view what, std::uint64_t count, std::string_view noun,
                                           std::uint64_t bytes_per_triangle = kLoadBytesPerTriangle) const;
};

}  // namespace mhd
