#include "mesh_io/mesh_header.h"

#include "mesh_io/ply_header.h"
#include "mesh_io/stl_header.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace mhd {

MeshHeaderCheck check_mesh_header(std::string_view head, std::uint64_t file_size, std::string_view extension) {
  std::string ext(extension);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  // assimp picks its SMD reader by these extensions whatever the file holds, and that
  // reader never returns from a "nodes" section the file ends in: no bound would hold.
  if (ext == ".smd" || ext == ".vta") {
    return std::string("SMD files are not read: assimp 5.2.5's SMD reader can loop for ever on a truncated file "
                       "(convert it to PLY, OBJ or glTF)");
  }
  if (has_ply_magic(head)) return check_ply_header(head, file_size);
  if (ext == ".stl") return check_stl_header(head, file_size);
  // The kind before assimp sees the file: a PLY starts with its magic word, and an OBJ is
  // text, so a NUL in its first bytes means a binary file under the wrong name (assimp
  // would read all of it before saying so).
  if (ext == ".ply") return std::string("not a PLY file: it does not start with 'ply'");
  if (ext == ".obj") {
    if (const std::size_t nul = head.find('\0'); nul != std::string_view::npos) {
      return "not an OBJ file: byte " + std::to_string(nul) + " is a NUL, and an OBJ is text";
    }
  }
  return MeshHeaderClaims{};
}

}  // namespace mhd
