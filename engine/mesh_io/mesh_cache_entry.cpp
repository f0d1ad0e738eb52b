#include "mesh_io/mesh_cache_entry.h"

#include "mesh_io/content_hash.h"

#include <xxhash.h>

#include <cstring>

namespace mhd::mesh_cache_entry {

std::optional<Layout> layout_for(std::uint64_t vertices, std::uint64_t triangles, std::uint64_t normals,
                                 std::uint64_t bvh_bytes, std::uint64_t source_bytes, std::uint64_t limit) {
  if (vertices > limit / sizeof(Eigen::Vector3d) || triangles > limit / sizeof(Eigen::Vector3d) ||
      normals > limit / sizeof(Eigen::Vector3f) || bvh_bytes > limit || source_bytes > kMaxSourceBytes) {
    return std::nullopt;
  }
  Layout l{};
  l.vertices = sizeof(FileHeader);
  l.triangles = align_up(l.vertices + static_cast<std::size_t>(vertices) * sizeof(Eigen::Vector3d));
  l.normals = align_up(l.triangles + static_cast<std::size_t>(triangles) * sizeof(TriangleIndices));
  l.face_normals = align_up(l.normals + static_cast<std::size_t>(normals) * sizeof(Eigen::Vector3f));
  l.bvh = align_up(l.face_normals + static_cast<std::size_t>(triangles) * sizeof(Eigen::Vector3d));
  l.source = l.bvh + static_cast<std::size_t>(bvh_bytes);
  l.end = l.source + static_cast<std::size_t>(source_bytes);
  if (l.end > limit) return std::nullopt;
  return l;
}

std::uint64_t header_hash(FileHeader h) {
  h.header_hash = 0;
  return XXH3_64bits(&h, sizeof h);
}

void seal(std::span<std::byte> image) {
  if (image.size() < sizeof(FileHeader)) return;
  FileHeader h;
  std::memcpy(&h, image.data(), sizeof h);
  ContentHash hash;
  hash.update(image.subspan(sizeof h));
  const ContentHash::Digest payload = hash.digest();
  h.payload_hash_low = payload.low64;
  h.payload_hash_high = payload.high64;
  h.header_hash = header_hash(h);
  std::memcpy(image.data(), &h, sizeof h);
}

}  // namespace mhd::mesh_cache_entry
