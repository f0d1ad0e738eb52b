#pragma once
// On-disk cache of loaded meshes with their BVHs, so a second load of a large mesh
// skips both assimp and the BVH build.
//
// Key: XXH3-128 of the mesh file's bytes, the scale, the cache format version and the
// Bullet version, remembered per file while it is unchanged (mesh_key_memo.h). One file
// per key, "<32 hex digits>.mhdbvh" in the cache folder, laid out as mesh_cache_entry.h
// says. Files are written to a temp file and renamed into place; a file that fails any
// check (size, counts, checksums, key, index ranges, BVH leaves) is ignored and rebuilt,
// never trusted. The folder is kept under a size limit (mesh_cache_eviction.h): a hit
// touches its file, and each write removes the least recently used entries beyond it.

#include "collision/mesh_bvh.h"
#include "geometry/triangle_mesh.h"
#include "mesh_io/mesh_loader.h"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace mhd {

/// Version of the cache file layout; part of every key. Bump it whenever the file
/// layout, the loader's processing (load_mesh_file) or MeshBvh's tree convention
/// changes, so that old entries are never used.
/// 2: the loader welds unshared files itself instead of assimp's JoinIdenticalVertices.
/// 3: a mesh past 2^21 triangles is split into Bullet parts (MeshBvh::kPartTriangles).
/// 4: an entry ends with the absolute path of the mesh file that wrote it.
/// 5: an entry holds its face normals, adopted where they lie.
/// 6: vertex normals are single precision.
/// 7: a mesh built in pieces is stored in its tree's leaf order (MeshBvh::MeshOrder).
/// 8: the loader winds each surface one way (orient_coherently).
inline constexpr std::uint32_t kMeshCacheFormatVersion = 8;

/// Meshes with at least this many triangles report progress.
inline constexpr std::size_t kProgressMinTriangles = 100'000;

/// $MHD_CACHE_DIR, else $XDG_CACHE_HOME/mhd, else $HOME/.cache/mhd (empty or, for
/// XDG_CACHE_HOME, relative values are skipped); nullopt when none is set.
[[nodiscard]] std::optional<std::filesystem::path> default_mesh_cache_dir();

struct MeshCacheKey {
  std::uint64_t low = 0, high = 0;
  [[nodiscard]] std::string hex() const;  ///< 32 lowercase hex digits
  friend bool operator==(const MeshCacheKey&, const MeshCacheKey&) = default;
};

/// Key of a mesh file at a scale; nullopt if the file cannot be read.
[[nodiscard]] std::optional<MeshCacheKey> mesh_cache_key(const std::filesystem::path& file,
                                                         const Eigen::Vector3d& scale_to_m);

enum class CacheOutcome {
  Disabled,  ///< no cache folder: loaded and built from scratch
  Hit,       ///< mesh and BVH came from the cache file
  Miss,      ///< no cache file: loaded, built and (if writable) written
  Rejected,  ///< a cache file existed but failed validation: rebuilt and overwritten
};

/// A mesh with its BVH, and how the cache served it.
struct CachedMesh {
  std::shared_ptr<const MeshBvh> bvh;  ///< never null; bvh->mesh_ptr() is the mesh
  CacheOutcome outcome = CacheOutcome::Disabled;
  bool written = false;         ///< a new cache file was written
  std::string rejected_reason;  ///< why the existing cache file was rejected
  std::filesystem::path cache_file;
  std::size_t dropped_triangles = 0;  ///< by the loader (0 on a hit)
  std::size_t flipped_triangles = 0;  ///< turned by the loader to their surface's winding (0 on a hit)
  std::string unisolated_read;        ///< LoadedMesh::unisolated_read (empty on a hit)
  /// Set when the entry written is larger than the cache's size limit: what it takes, the
  /// limit and the variable that sets it (also logged as a warning). Such an entry is
  /// kept until another mesh is cached, which evicts it.
  std::string over_limit;
  [[nodiscard]] const TriangleMesh& mesh() const { return bvh->mesh(); }
};

/// The absolute path of the mesh file an entry was written from ("" if it did not fit
/// the entry); nullopt for a file that is not an entry of this format whose header holds.
[[nodiscard]] std::optional<std::string> mesh_cache_entry_source(const std::filesystem::path& entry);

struct MeshCacheStats {
  std::size_t hits = 0, misses = 0, rejected = 0, writes = 0, write_failures = 0;
  /// Loads whose key came from the file's memo (mesh_key_memo.h), the file not hashed.
  std::size_t keys_remembered = 0;
  /// Loads whose key was hashed from the file's bytes.
  std::size_t keys_hashed = 0;
};

/// Not thread-safe; use one instance per thread (files are safe to share between
/// processes: writers rename complete files into place).
class MeshCache {
 public:
  /// `dir` nullopt disables caching. The folder is created if missing; if it cannot be
  /// created or written, the cache works read-only (logged once per folder).
  explicit MeshCache(std::optional<std::filesystem::path> dir);

  /// Loads `file` at `scale_to_m` (see load_mesh_file()) with its BVH, from the cache
  /// if a valid entry exists, else from the file, then stores it.
  /// `progress` is called for meshes of kProgressMinTriangles or more (for the read
  /// step, estimated from the file size): reading the file, building the tree and writing
  /// the entry, or reading the entry. `budget` as for load_mesh_file(), and applied
  /// to a cache hit too: the header is checked before the file is hashed for its key,
  /// against memory at what a cached mesh takes (kCachedBytesPerTriangle), and a build
  /// is checked again at what it takes. The error is the loader's, or the budget's
  /// refusal of a hit.
  [[nodiscard]] Result<CachedMesh, MeshLoadError> load(const std::filesystem::path& file, const Eigen::Vector3d& scale_to_m,
                                const MeshProgress& progress = {},
                                std::optional<TriangleBudget> budget = std::nullopt);

  [[nodiscard]] const std::optional<std::filesystem::path>& dir() const { return dir_; }
  [[nodiscard]] bool writable() const { return writable_; }
  [[nodiscard]] const MeshCacheStats& stats() const { return stats_; }
  /// Size limit of the folder (default mesh_cache_limit_bytes()), applied after each write.
  void set_limit_bytes(std::uint64_t limit_bytes) { limit_bytes_ = limit_bytes; }
  /// Where the entry for `key` lives (requires dir()).
  [[nodiscard]] std::filesystem::path file_for(const MeshCacheKey& key) const;

 private:
  // Writes the entry; `progress`, when set, follows the bytes written.
  void store(const std::filesystem::path& mesh_file, const std::filesystem::path& target, const MeshCacheKey& key,
             const MeshBvh& bvh, const MeshProgress& progress, CachedMesh& result);

  std::optional<std::filesystem::path> dir_;
  bool writable_ = false;
  std::uint64_t limit_bytes_;
  MeshCacheStats stats_;
};

}  // namespace mhd
