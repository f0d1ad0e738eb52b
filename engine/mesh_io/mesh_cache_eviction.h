#pragma once
// Keeps the on-disk mesh cache (mesh_cache.h) bounded: its entries are listed, the least
// recently used (oldest modification time; a cache hit touches its file) are removed until
// the folder fits a size limit, and the whole cache can be cleared. Only "*.mhdbvh" files,
// the remembered keys ("*.mhdkey", mesh_key_memo.h: one small file per mesh file, scale and
// build, evicted once its entry is gone) and their leftover temp files are ever removed,
// never anything else in the folder.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace mhd {

/// Default size limit of the cache folder, overridden by $MHD_CACHE_MAX_MB.
inline constexpr std::uint64_t kDefaultMeshCacheLimit_bytes = 512ull * 1024 * 1024;

/// $MHD_CACHE_MAX_MB (a positive whole number of MiB) in bytes, else the default. A bad
/// value falls back to the default (mesh_cache_limit_problem() says why).
[[nodiscard]] std::uint64_t mesh_cache_limit_bytes();
/// Why $MHD_CACHE_MAX_MB was not used, empty when it is unset or fine.
[[nodiscard]] std::string mesh_cache_limit_problem();

struct MeshCacheEntry {
  std::filesystem::path file;
  std::uint64_t size_bytes = 0;
  std::filesystem::file_time_type last_used;  ///< modification time: written or last hit
};

/// The folder's cache entries, most recently used first; empty if it does not exist.
[[nodiscard]] std::vector<MeshCacheEntry> list_mesh_cache(const std::filesystem::path& dir);

struct MeshCacheRemoval {
  std::size_t removed = 0;
  std::uint64_t freed_bytes = 0;
  std::uint64_t kept_bytes = 0;  ///< what the entries left take
  std::size_t keys_removed = 0;  ///< remembered keys, not in `removed`
};

/// Removes least recently used entries until the entries take at most `limit_bytes`, then
/// the remembered keys that name an entry no longer there (those this build can read).
/// `keep` (e.g. the entry just written) is never removed, even if it alone is over.
MeshCacheRemoval evict_mesh_cache(const std::filesystem::path& dir, std::uint64_t limit_bytes,
                                  const std::optional<std::filesystem::path>& keep = std::nullopt);

/// Removes every entry and remembered key, and temp files a killed writer left.
MeshCacheRemoval clear_mesh_cache(const std::filesystem::path& dir);

}  // namespace mhd
