#pragma once
// A mesh file's cache key, remembered beside the cache's entries, so that a cached load of
// an unchanged file reads its header only (hashing the 1.9 GB file of a 100 M-triangle
// mesh took 0.10-0.17 s of a 2.6 s cached load, and longer out of the page cache).
//
// One memo per file (device and inode), scale and build (cache format and Bullet version),
// "<32 hex digits>.mhdkey": the key, with the file's size and its modification and change
// times when it was hashed. The change time (ctime) is set by the kernel on every write
// and cannot be set back by a user, so a file rewritten with its old size and modification
// time is hashed again. A memo is only written for a file that had not changed for
// kMeshKeySettle_s before its hashing began and did not change during it: a write in the
// same clock tick as the one the memo saw, which would keep ctime, cannot then happen. A
// memo that fails its check (magic, file, scale, versions, checksum) is ignored, the file
// hashed, and the memo written again.

#include "mesh_io/mesh_cache.h"

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>

namespace mhd {

/// How long a file must have stood unchanged before its key is remembered.
inline constexpr double kMeshKeySettle_s = 1.0;

inline constexpr std::string_view kMeshKeyMemoExtension = ".mhdkey";

/// The key of `file` at `scale_to_m` for the cache folder `dir`: from the file's memo when
/// it holds for the file as it is now (`remembered` set), else mesh_cache_key(), and then,
/// if `writable`, the memo written for next time. nullopt if the file cannot be read.
[[nodiscard]] std::optional<MeshCacheKey> mesh_key_remembered_or_hashed(const std::filesystem::path& dir,
                                                                        const std::filesystem::path& file,
                                                                        const Eigen::Vector3d& scale_to_m,
                                                                        bool writable, bool& remembered);

/// The memo's path for `file` at `scale_to_m` in `dir`, as a build writing cache format
/// `format_version` names it (builds of different formats keep their own memos, as they
/// keep their own entries); nullopt if `file` is not a regular file.
[[nodiscard]] std::optional<std::filesystem::path> mesh_key_memo_file(
    const std::filesystem::path& dir, const std::filesystem::path& file, const Eigen::Vector3d& scale_to_m,
    std::uint32_t format_version = kMeshCacheFormatVersion);

/// The key the memo file `memo` holds, if it is a whole memo of this memo format that
/// passes its checksum, for whatever file, scale and build it was written; else nullopt
/// (cache eviction removes the memos whose entry is no longer there, of those it can read).
[[nodiscard]] std::optional<MeshCacheKey> mesh_key_memo_key(const std::filesystem::path& memo);

}  // namespace mhd
