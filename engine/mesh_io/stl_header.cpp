#include "mesh_io/stl_header.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>

namespace mhd {
namespace {

constexpr std::uint64_t kHeaderBytes = 84;
constexpr std::uint64_t kTriangleBytes = 50;

/// ASCII STL as assimp sees it: "solid" after leading white space. Binary STLs often
/// start with "solid" too, so control characters (other than white space) in the head
/// mark the file as binary.
bool looks_ascii(std::string_view head) {
  const std::size_t start = head.find_first_not_of(" \t\r\n\f\v");
  if (start == std::string_view::npos || !head.substr(start).starts_with("solid")) return false;
  const std::string_view sample = head.substr(0, 512);
  return std::none_of(sample.begin(), sample.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 0x20 && std::strchr("\t\r\n\f\v", c) == nullptr;
  });
}

}  // namespace

MeshHeaderCheck check_stl_header(std::string_view head, std::uint64_t file_size) {
  MeshHeaderClaims check;
  if (head.size() >= kHeaderBytes) {
    std::uint32_t count = 0;  // little-endian
    for (int i = 3; i >= 0; --i) count = (count << 8) | static_cast<unsigned char>(head[80 + static_cast<std::size_t>(i)]);
    const std::uint64_t expected = kHeaderBytes + kTriangleBytes * count;
    if (expected == file_size) {
      check.claimed_faces = count;
      return check;
    }
    if (looks_ascii(head)) return check;
    return fmt::format("binary STL header claims {} triangle{} ({} bytes), but the file has {} bytes", count,
                       count == 1 ? "" : "s", expected, file_size);
  }
  if (looks_ascii(head)) return check;
  return fmt::format("binary STL is {} bytes, shorter than its {}-byte header", file_size, kHeaderBytes);
}

}  // namespace mhd
