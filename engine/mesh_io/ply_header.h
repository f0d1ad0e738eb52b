#pragma once
// PLY header check: the element counts must fit in the bytes after end_header
// (binary: at least the fixed size of each element; ASCII: about 2 bytes per number).

#include "mesh_io/mesh_header.h"

#include <cstdint>
#include <string_view>

namespace mhd {

/// True when `head` starts with the PLY magic line.
[[nodiscard]] bool has_ply_magic(std::string_view head);

[[nodiscard]] MeshHeaderCheck check_ply_header(std::string_view head, std::uint64_t file_size);

}  // namespace mhd
