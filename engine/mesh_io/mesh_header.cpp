#include "mesh_io/mesh_header.h"

#include "mesh_io/ply_header.h"
#include "mesh_io/stl_header.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace mhd {

MeshHeaderCheck check_mesh_header(std::string_view head, std::uint64_t file_size, std::string_view extension) {
  if (has_ply_magic(head)) return check_ply_header(head, file_size);
  std::string ext(extension);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".stl") return check_stl_header(head, file_size);
  return MeshHeaderClaims{};
}

}  // namespace mhd
