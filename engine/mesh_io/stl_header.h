#pragma once
// STL header check: a binary STL (84-byte header, then 50 bytes per triangle) must be
// exactly as long as its triangle count says; an ASCII STL ("solid ...") has no count.

#include "mesh_io/mesh_header.h"

#include <cstdint>
#include <string_view>

namespace mhd {

[[nodiscard]] MeshHeaderCheck check_stl_header(std::string_view head, std::uint64_t file_size);

}  // namespace mhd
