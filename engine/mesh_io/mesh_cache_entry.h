#pragma once
// The layout of one mesh cache entry (mesh_cache.h): a 128-byte header, then vertices
// (double), triangles (uint32), vertex normals (double), face normals (double, one per
// triangle) and Bullet's serialized BVH, each section 16-byte aligned, then the path of
// the mesh file that wrote it. MeshCache reads
// and writes it; tests and the cache fuzzer craft entries with seal().

#include "geometry/triangle_mesh.h"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <type_traits>

namespace mhd::mesh_cache_entry {

inline constexpr std::array<char, 8> kMagic = {'M', 'H', 'D', 'B', 'V', 'H', '\0', '\0'};
inline constexpr std::uint32_t kEndianTag = 0x01020304u;
inline constexpr std::size_t kAlign = 16;
inline constexpr const char* kExtension = ".mhdbvh";
/// Longest mesh file path an entry records (Linux's PATH_MAX).
inline constexpr std::uint64_t kMaxSourceBytes = 4096;

/// The first 128 bytes of a cache file (native byte order; the endian tag, scalar and
/// pointer sizes and Bullet version make a file from another platform a mismatch).
struct FileHeader {
  std::array<char, 8> magic;
  std::uint32_t format_version;
  std::uint32_t header_bytes;
  std::uint32_t endian_tag;
  std::uint32_t scalar_bytes;
  std::uint32_t pointer_bytes;
  std::uint32_t bullet_version;
  std::uint64_t key_low, key_high;
  std::uint64_t vertex_count;
  std::uint64_t triangle_count;
  std::uint64_t normal_count;
  std::uint64_t bvh_bytes;
  std::uint64_t payload_bytes;
  std::uint64_t payload_hash_low, payload_hash_high;  ///< XXH3-128 of everything after the header
  std::uint64_t source_bytes;  ///< length of the mesh file's path, the last section
  std::uint64_t reserved;
  std::uint64_t header_hash;  ///< XXH3-64 of this header with header_hash = 0
};
static_assert(sizeof(FileHeader) == 128);
static_assert(std::is_trivially_copyable_v<FileHeader>);
static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double), "vertices are stored as packed doubles");
static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "vertex normals are stored as packed floats");
static_assert(sizeof(TriangleIndices) == 3 * sizeof(std::uint32_t));
static_assert(std::is_trivially_copyable_v<TriangleIndices>);

[[nodiscard]] constexpr std::size_t align_up(std::size_t n) { return (n + kAlign - 1) / kAlign * kAlign; }

/// Byte offsets of the payload sections, relative to the file start.
struct Layout {
  std::size_t vertices, triangles, normals, face_normals, bvh, source, end;
};

/// Layout for the given counts; nullopt if it would not fit in `limit` bytes (checked
/// before multiplying, so hostile counts cannot overflow).
[[nodiscard]] std::optional<Layout> layout_for(std::uint64_t vertices, std::uint64_t triangles, std::uint64_t normals,
                                               std::uint64_t bvh_bytes, std::uint64_t source_bytes, std::uint64_t limit);

/// XXH3-64 of `h` with its header_hash field zero.
[[nodiscard]] std::uint64_t header_hash(FileHeader h);

/// Writes both checksums of a whole entry image (at least a header long) in place: what
/// a test or fuzzer that edits an entry does so that the reader checks what lies behind
/// them.
void seal(std::span<std::byte> image);

}  // namespace mhd::mesh_cache_entry
