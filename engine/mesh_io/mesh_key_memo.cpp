#include "mesh_io/mesh_key_memo.h"

#include "mesh_io/content_hash.h"

#include <LinearMath/btScalar.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <ctime>
#include <system_error>

namespace mhd {

namespace {

/// What identifies a file's bytes without reading them (see the header: ctime is the
/// kernel's, set on every write).
struct FileStamp {
  std::uint64_t dev = 0, ino = 0, size = 0;
  std::int64_t mtime_ns = 0, ctime_ns = 0;
  friend bool operator==(const FileStamp&, const FileStamp&) = default;
};

std::int64_t ns_of(const timespec& t) { return static_cast<std::int64_t>(t.tv_sec) * 1'000'000'000 + t.tv_nsec; }

std::optional<FileStamp> stamp_of(const std::filesystem::path& file) {
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
  return FileStamp{static_cast<std::uint64_t>(st.st_dev), static_cast<std::uint64_t>(st.st_ino),
                   static_cast<std::uint64_t>(st.st_size), ns_of(st.st_mtim), ns_of(st.st_ctim)};
}

std::int64_t realtime_now_ns() {
  timespec t{};
  ::clock_gettime(CLOCK_REALTIME, &t);
  return ns_of(t);
}

/// A memo file as written: no padding, every field fixed-width.
struct MemoFile {
  std::array<char, 8> magic{};
  FileStamp stamp;
  std::array<double, 3> scale_to_m{};
  std::uint32_t format_version = 0, bullet_version = 0;
  std::uint64_t key_low = 0, key_high = 0;
  std::uint64_t check = 0;  ///< low half of XXH3-128 of every byte before it
};
static_assert(sizeof(MemoFile) == 104, "MemoFile has padding");

constexpr std::array<char, 8> kMagic{'M', 'H', 'D', 'K', 'E', 'Y', '1', '\0'};

/// nullopt when no hash state could be had: no memo is then read or written.
std::optional<std::uint64_t> check_of(const MemoFile& m) {
  ContentHash state;
  if (!state.ok()) return std::nullopt;
  state.update(&m, offsetof(MemoFile, check));
  return state.digest().low64;
}

/// The memo as this file, at this scale, with this build, would have it (key left zero).
MemoFile memo_for(const FileStamp& stamp, const Eigen::Vector3d& scale_to_m) {
  MemoFile m;
  m.magic = kMagic;
  m.stamp = stamp;
  // +0.0 folds -0.0, as the key does.
  m.scale_to_m = {scale_to_m.x() + 0.0, scale_to_m.y() + 0.0, scale_to_m.z() + 0.0};
  m.format_version = kMeshCacheFormatVersion;
  m.bullet_version = static_cast<std::uint32_t>(BT_BULLET_VERSION);
  return m;
}

/// One memo per file, scale and build: named by what stays when the file is rewritten in
/// place, and by the versions that keep builds' entries apart.
std::filesystem::path memo_path(const std::filesystem::path& dir, const MemoFile& m) {
  ContentHash state;
  state.update(&m.stamp.dev, sizeof m.stamp.dev);
  state.update(&m.stamp.ino, sizeof m.stamp.ino);
  state.update(m.scale_to_m.data(), sizeof m.scale_to_m);
  state.update(&m.format_version, sizeof m.format_version);
  state.update(&m.bullet_version, sizeof m.bullet_version);
  const ContentHash::Digest name = state.digest();
  return dir / (MeshCacheKey{name.low64, name.high64}.hex() + std::string(kMeshKeyMemoExtension));
}

/// The memo at `path` if it is whole, of this memo format, and passes its checksum.
std::optional<MemoFile> read_whole_memo(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  MemoFile m;
  struct stat st {};
  const bool whole = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size == sizeof m &&
                     ::pread(fd, &m, sizeof m, 0) == static_cast<ssize_t>(sizeof m);
  ::close(fd);
  if (!whole || m.check != check_of(m).value_or(~m.check) || m.magic != kMagic) return std::nullopt;
  return m;
}

std::optional<MeshCacheKey> read_memo(const std::filesystem::path& path, const MemoFile& expected) {
  const std::optional<MemoFile> m = read_whole_memo(path);
  if (!m || !(m->stamp == expected.stamp) || m->scale_to_m != expected.scale_to_m ||
      m->format_version != expected.format_version || m->bullet_version != expected.bullet_version) {
    return std::nullopt;
  }
  return MeshCacheKey{m->key_low, m->key_high};
}

/// Best effort: a folder that cannot take it only means the file is hashed next time.
void write_memo(const std::filesystem::path& path, MemoFile m, const MeshCacheKey& key) {
  m.key_low = key.low;
  m.key_high = key.high;
  const std::optional<std::uint64_t> check = check_of(m);
  if (!check) return;
  m.check = *check;
  static std::atomic<unsigned> counter{0};
  std::filesystem::path temp = path;
  temp += fmt::format(".tmp.{}.{}", ::getpid(), counter.fetch_add(1));
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) return;
  const bool written = ::write(fd, &m, sizeof m) == static_cast<ssize_t>(sizeof m);
  const bool closed = ::close(fd) == 0;
  std::error_code ec;
  if (written && closed) std::filesystem::rename(temp, path, ec);
  if (!written || !closed || ec) std::filesystem::remove(temp, ec);
}

}  // namespace

std::optional<std::filesystem::path> mesh_key_memo_file(const std::filesystem::path& dir,
                                                        const std::filesystem::path& file,
                                                        const Eigen::Vector3d& scale_to_m,
                                                        std::uint32_t format_version) {
  const std::optional<FileStamp> stamp = stamp_of(file);
  if (!stamp) return std::nullopt;
  MemoFile memo = memo_for(*stamp, scale_to_m);
  memo.format_version = format_version;
  return memo_path(dir, memo);
}

std::optional<MeshCacheKey> mesh_key_memo_key(const std::filesystem::path& memo) {
  const std::optional<MemoFile> m = read_whole_memo(memo);
  if (!m) return std::nullopt;
  return MeshCacheKey{m->key_low, m->key_high};
}

std::optional<MeshCacheKey> mesh_key_remembered_or_hashed(const std::filesystem::path& dir,
                                                          const std::filesystem::path& file,
                                                          const Eigen::Vector3d& scale_to_m, bool writable,
                                                          bool& remembered) {
  remembered = false;
  const std::optional<FileStamp> before = stamp_of(file);
  if (!before) return mesh_cache_key(file, scale_to_m);  // the loader then says what it is
  const MemoFile memo = memo_for(*before, scale_to_m);
  const std::filesystem::path path = memo_path(dir, memo);
  if (const std::optional<MeshCacheKey> key = read_memo(path, memo)) {
    remembered = true;
    return key;
  }
  const std::int64_t hashing_began_ns = realtime_now_ns();
  const std::optional<MeshCacheKey> key = mesh_cache_key(file, scale_to_m);
  if (!key || !writable) return key;
  const bool settled = before->ctime_ns <= hashing_began_ns - static_cast<std::int64_t>(kMeshKeySettle_s * 1e9);
  if (settled && stamp_of(file) == before) write_memo(path, memo, *key);
  return key;
}

}  // namespace mhd
