#include "mesh_io/mesh_cache_eviction.h"

#include "mesh_io/mesh_key_memo.h"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <string_view>
#include <system_error>

namespace mhd {

namespace {

constexpr std::string_view kEntryExtension = ".mhdbvh";

bool is_entry(const std::filesystem::path& p) { return p.extension() == kEntryExtension; }

// "<key>.mhdbvh.tmp.<pid>.<n>": what MeshCache::store leaves if killed mid-write.
bool is_temp(const std::filesystem::path& p) {
  return p.filename().string().find(std::string(kEntryExtension) + ".tmp.") != std::string::npos;
}

// A file's remembered key (mesh_key_memo.h), or what its writer left if killed mid-write.
bool is_key_memo(const std::filesystem::path& p) {
  return p.extension() == kMeshKeyMemoExtension ||
         p.filename().string().find(std::string(kMeshKeyMemoExtension) + ".tmp.") != std::string::npos;
}

// Removes the remembered keys whose entry is not in `dir`: such a memo only spares hashing
// a file that must then be read and built anyway. A memo this build cannot read (another
// build's format, a writer's temp file) is left. Returns how many went.
std::size_t remove_memos_without_entry(const std::filesystem::path& dir) {
  std::error_code ec;
  std::vector<std::filesystem::path> orphans;
  for (const auto& item : std::filesystem::directory_iterator(dir, ec)) {
    if (item.path().extension() != kMeshKeyMemoExtension) continue;
    const std::optional<MeshCacheKey> key = mesh_key_memo_key(item.path());
    std::error_code exists_ec;
    if (key && !std::filesystem::exists(dir / (key->hex() + std::string(kEntryExtension)), exists_ec) && !exists_ec) {
      orphans.push_back(item.path());
    }
  }
  std::size_t removed = 0;
  for (const auto& memo : orphans) {
    std::error_code remove_ec;
    if (std::filesystem::remove(memo, remove_ec)) ++removed;
  }
  return removed;
}

std::optional<std::uint64_t> parse_limit_mb(std::string& problem) {
  const char* text = std::getenv("MHD_CACHE_MAX_MB");
  if (text == nullptr || *text == '\0') return std::nullopt;
  const std::string_view s(text);
  std::uint64_t mb = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), mb);
  if (ec != std::errc() || end != s.data() + s.size() || mb == 0 || mb > (1ull << 40)) {
    problem = "MHD_CACHE_MAX_MB='" + std::string(s) + "' is not a whole number of MiB from 1 to 2^40; using " +
              std::to_string(kDefaultMeshCacheLimit_bytes >> 20) + " MiB";
    return std::nullopt;
  }
  return mb * 1024 * 1024;
}

}  // namespace

std::uint64_t mesh_cache_limit_bytes() {
  std::string problem;
  return parse_limit_mb(problem).value_or(kDefaultMeshCacheLimit_bytes);
}

std::string mesh_cache_limit_problem() {
  std::string problem;
  (void)parse_limit_mb(problem);
  return problem;
}

std::vector<MeshCacheEntry> list_mesh_cache(const std::filesystem::path& dir) {
  std::vector<MeshCacheEntry> entries;
  std::error_code ec;
  for (const auto& item : std::filesystem::directory_iterator(dir, ec)) {
    if (!is_entry(item.path()) || !item.is_regular_file(ec)) continue;
    MeshCacheEntry e;
    e.file = item.path();
    e.size_bytes = item.file_size(ec);
    if (ec) continue;  // removed by another process meanwhile
    e.last_used = item.last_write_time(ec);
    if (ec) continue;
    entries.push_back(std::move(e));
  }
  std::sort(entries.begin(), entries.end(), [](const MeshCacheEntry& a, const MeshCacheEntry& b) {
    return a.last_used != b.last_used ? a.last_used > b.last_used : a.file < b.file;
  });
  return entries;
}

MeshCacheRemoval evict_mesh_cache(const std::filesystem::path& dir, std::uint64_t limit_bytes,
                                  const std::optional<std::filesystem::path>& keep) {
  const std::vector<MeshCacheEntry> entries = list_mesh_cache(dir);
  MeshCacheRemoval r;
  for (const MeshCacheEntry& e : entries) r.kept_bytes += e.size_bytes;
  // Oldest first, from the back of the most-recent-first list.
  for (auto it = entries.rbegin(); it != entries.rend() && r.kept_bytes > limit_bytes; ++it) {
    if (keep && it->file == *keep) continue;
    std::error_code ec;
    if (std::filesystem::remove(it->file, ec) || !ec) {
      ++r.removed;
      r.freed_bytes += it->size_bytes;
      r.kept_bytes -= it->size_bytes;
    }
  }
  r.keys_removed = remove_memos_without_entry(dir);
  return r;
}

MeshCacheRemoval clear_mesh_cache(const std::filesystem::path& dir) {
  MeshCacheRemoval r = evict_mesh_cache(dir, 0);
  std::error_code ec;
  std::vector<std::filesystem::path> temps, keys;
  for (const auto& item : std::filesystem::directory_iterator(dir, ec)) {
    if (is_temp(item.path())) temps.push_back(item.path());
    if (is_key_memo(item.path())) keys.push_back(item.path());
  }
  for (const auto& k : keys) {
    std::error_code remove_ec;
    if (std::filesystem::remove(k, remove_ec)) ++r.keys_removed;
  }
  for (const auto& t : temps) {
    std::error_code remove_ec;
    const auto size = std::filesystem::file_size(t, remove_ec);
    if (std::filesystem::remove(t, remove_ec)) {
      ++r.removed;
      r.freed_bytes += remove_ec ? 0 : size;
    }
  }
  return r;
}

}  // namespace mhd
