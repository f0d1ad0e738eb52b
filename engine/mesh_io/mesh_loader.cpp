#include "mesh_io/mesh_loader.h"

#include "geometry/coherent_winding.h"

#include "mesh_io/isolated_assimp_read.h"
#include "mesh_io/mesh_header.h"
#include "mesh_io/regular_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <system_error>
#include <unordered_map>

#include <unistd.h>

namespace mhd {

std::string MeshLoadError::message() const {
  return fmt::format("mesh file '{}': {}", file.string(), reason);
}

namespace {

/// The first `bytes` bytes of an open file (nullopt on a read error, errno set).
std::optional<std::string> read_head(int fd, std::size_t bytes) {
  std::string head(bytes, '\0');
  std::size_t got = 0;
  while (got < bytes) {
    const ssize_t n = ::pread(fd, head.data() + got, bytes - got, static_cast<off_t>(got));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return std::nullopt;
    if (n == 0) break;
    got += static_cast<std::size_t>(n);
  }
  head.resize(got);
  return head;
}

MeshLoadError fail(const std::filesystem::path& file, std::string reason) {
  return MeshLoadError{file, std::move(reason)};
}

/// Key of a position for welding: the bit patterns, with -0 folded into +0.
struct PositionKey {
  std::uint64_t x, y, z;
  friend bool operator==(const PositionKey&, const PositionKey&) = default;
};
struct PositionKeyHash {
  std::size_t operator()(const PositionKey& k) const noexcept {
    std::uint64_t h = k.x * 0x9E3779B97F4A7C15ull;
    h ^= (h >> 29) ^ (k.y * 0xC2B2AE3D27D4EB4Full);
    h ^= (h >> 31) ^ (k.z * 0x165667B19E3779F9ull);
    return static_cast<std::size_t>(h ^ (h >> 32));
  }
};
PositionKey key_of(const Eigen::Vector3d& p) {
  return {std::bit_cast<std::uint64_t>(p.x() + 0.0), std::bit_cast<std::uint64_t>(p.y() + 0.0),
          std::bit_cast<std::uint64_t>(p.z() + 0.0)};
}

/// Merges vertices at bit-identical positions (seams between the file's meshes).
void weld_identical_positions(TriangleMesh& mesh) {
  std::unordered_map<PositionKey, std::uint32_t, PositionKeyHash> first;
  first.reserve(mesh.vertices_m.size());
  std::vector<std::uint32_t> remap(mesh.vertices_m.size());
  MeshArray<Eigen::Vector3d> kept;
  kept.reserve(mesh.vertices_m.size());
  for (std::size_t i = 0; i < mesh.vertices_m.size(); ++i) {
    auto [it, inserted] = first.try_emplace(key_of(mesh.vertices_m[i]), static_cast<std::uint32_t>(kept.size()));
    if (inserted) kept.push_back(mesh.vertices_m[i]);
    remap[i] = it->second;
  }
  if (kept.size() == mesh.vertices_m.size()) return;
  for (auto& t : mesh.triangles) {
    for (auto& i : t) i = i < remap.size() ? remap[i] : std::numeric_limits<std::uint32_t>::max();
  }
  mesh.vertices_m = std::move(kept);
}

/// Removes vertices no triangle uses, keeping the order of the rest.
void drop_unused_vertices(TriangleMesh& mesh) {
  constexpr auto kUnused = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> remap(mesh.vertices_m.size(), kUnused);
  for (const auto& t : mesh.triangles) {
    for (auto i : t) remap[i] = 0;
  }
  std::uint32_t next = 0;
  for (std::size_t i = 0; i < remap.size(); ++i) {
    if (remap[i] != kUnused) {
      remap[i] = next;
      mesh.vertices_m[next++] = mesh.vertices_m[i];
    }
  }
  if (next == mesh.vertices_m.size()) return;
  mesh.vertices_m.resize(next);
  for (auto& t : mesh.triangles) {
    for (auto& i : t) i = remap[i];
  }
}

}  // namespace

MeshCleanUp finish_loaded_mesh(TriangleMesh& mesh, const Eigen::Vector3d& scale_to_m) {
  for (auto& v : mesh.vertices_m) v = v.cwiseProduct(scale_to_m);
  // A mirroring scale turns counter-clockwise into clockwise; swap two corners back.
  if (scale_to_m.x() * scale_to_m.y() * scale_to_m.z() < 0.0) {
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  }
  MeshCleanUp done;
  done.dropped_triangles = remove_invalid_triangles(mesh);
  // Zero-area triangles (collinear corners) have no surface and no normal.
  const auto before = mesh.triangles.size();
  std::erase_if(mesh.triangles, [&](const TriangleIndices& t) {
    const Eigen::Vector3d& a = mesh.vertices_m[t[0]];
    return (mesh.vertices_m[t[1]] - a).cross(mesh.vertices_m[t[2]] - a).isZero(0.0);
  });
  done.dropped_triangles += before - mesh.triangles.size();
  drop_unused_vertices(mesh);
  done.flipped_triangles = orient_coherently(mesh);
  compute_vertex_normals(mesh);
  return done;
}

std::optional<MeshLoadError> refusal_from_header(const std::filesystem::path& file,
                                                 const std::optional<TriangleBudget>& budget,
                                                 std::uint64_t bytes_per_triangle) {
  const RegularFile opened(file);
  if (!opened.ok()) return fail(file, opened.problem());
  if (opened.size_bytes() == 0) return fail(file, "file is empty");
  const std::optional<std::string> head =
      read_head(opened.fd(), std::min<unsigned long long>(opened.size_bytes(), kMeshHeaderBytes));
  if (!head) return fail(file, fmt::format("cannot read file: {}", std::strerror(errno)));
  const MeshHeaderCheck header = check_mesh_header(*head, opened.size_bytes(), file.extension().string());
  if (!header.ok()) return fail(file, header.error());
  if (budget && header->claimed_faces) {
    if (std::string refused = budget->refusal("the header claims", *header->claimed_faces, "faces"); !refused.empty()) {
      return fail(file, std::move(refused));
    }
    if (std::string refused =
            budget->memory_refusal("the header claims", *header->claimed_faces, "faces", bytes_per_triangle);
        !refused.empty()) {
      return fail(file, std::move(refused));
    }
  }
  return std::nullopt;
}

Result<LoadedMesh, MeshLoadError> load_mesh_file(const std::filesystem::path& file, const Eigen::Vector3d& scale_to_m,
                              const MeshProgress& progress, std::optional<TriangleBudget> budget,
                              const MeshReadLimits& limits) {
  if (!scale_to_m.allFinite() || (scale_to_m.array() == 0.0).any()) {
    return fail(file, fmt::format("invalid scale ({}, {}, {}): every factor must be finite and non-zero",
                                  scale_to_m.x(), scale_to_m.y(), scale_to_m.z()));
  }
  // Header counts are checked against the file size before assimp allocates for them.
  if (std::optional<MeshLoadError> refused = refusal_from_header(file, budget, TriangleBudget::kLoadBytesPerTriangle)) {
    return *std::move(refused);
  }

  std::function<void(double)> read_progress;
  if (progress) {
    read_progress = [&progress, what = fmt::format("reading {}", file.filename().string())](double fraction) {
      progress(what, fraction);
    };
  }
  Result<AssimpRead, std::string> read = read_with_assimp(file, read_progress, limits);
  if (!read.ok()) return fail(file, read.error());
  TriangleMesh mesh = std::move(read->mesh);
  std::size_t dropped = read->dropped;
  if (mesh.triangles.empty()) return fail(file, "mesh has no triangles");
  if (budget) {
    if (std::string refused = budget->refusal("", mesh.triangles.size(), "triangles"); !refused.empty()) {
      return fail(file, std::move(refused));
    }
  }
  // An indexed surface has about half as many vertices as triangles; more vertices than
  // triangles means corners are not shared (STL, per-face OBJ) or the file has several
  // meshes: join identical positions so neighbours share their edges.
  if (read->unshared) weld_identical_positions(mesh);

  const MeshCleanUp done = finish_loaded_mesh(mesh, scale_to_m);
  dropped += done.dropped_triangles;
  if (mesh.triangles.empty()) return fail(file, "mesh has no triangles (all are degenerate)");
  for (const auto& v : mesh.vertices_m) {
    if (!v.allFinite()) return fail(file, "non-finite vertex coordinates");
  }

  return LoadedMesh{std::move(mesh), dropped, done.flipped_triangles, std::move(read->unisolated_read)};
}

}  // namespace mhd
