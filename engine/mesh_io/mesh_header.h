#pragma once
// What a mesh file's header claims, checked against the file's size before anything is
// allocated: a PLY's element counts, a binary STL's triangle count. OBJ and ASCII STL
// carry no counts (their size bounds what they can hold). The file's kind is checked too:
// a .ply without PLY's magic word and a .obj with a NUL byte are refused here, and so is
// any .smd or .vta, whose assimp reader can loop for ever.

#include "diagnostics/result.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace mhd {

/// The bytes at the start of a file that the header checks read (a PLY header must end
/// within them).
inline constexpr std::size_t kMeshHeaderBytes = 65536;

/// What a header that fits its file claims.
struct MeshHeaderClaims {
  /// Faces the header claims (PLY 'face' elements, binary STL triangles); each is at
  /// least one triangle. nullopt when the format carries no count.
  std::optional<std::uint64_t> claimed_faces;
};

/// The header's claims, or why it does not fit the file ("PLY header claims ...").
using MeshHeaderCheck = Result<MeshHeaderClaims, std::string>;

/// Checks a header: `head` is the file's first min(file_size, kMeshHeaderBytes) bytes,
/// `extension` the file's (".stl", any case; binary STL has no magic number).
[[nodiscard]] MeshHeaderCheck check_mesh_header(std::string_view head, std::uint64_t file_size,
                                                std::string_view extension);

}  // namespace mhd
