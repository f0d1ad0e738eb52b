#include "mesh_io/mesh_cache.h"

#include "collision/huge_pages.h"
#include "collision/split_tree_build.h"
#include "mesh_io/byte_count_text.h"
#include "mesh_io/content_hash.h"
#include "mesh_io/mesh_cache_entry.h"
#include "mesh_io/mesh_cache_eviction.h"
#include "mesh_io/mesh_key_memo.h"
#include "mesh_io/regular_file.h"
#include "mesh_io/whole_fd_io.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <future>
#include <limits>
#include <mutex>
#include <set>
#include <span>
#include <system_error>
#include <type_traits>
#include <vector>

namespace mhd {
namespace {

using namespace mesh_cache_entry;  // NOLINT(google-build-using-namespace): the format this file reads and writes


/// Closes a file descriptor on scope exit.
struct Fd {
  int fd = -1;
  explicit Fd(int f) : fd(f) {}
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
};

// What a cache entry is written in, between reports of its progress.
constexpr std::size_t kWriteChunkBytes = std::size_t{64} << 20;

/// Warns once per folder and process that the cache cannot be written there.
void warn_unwritable_once(const std::filesystem::path& dir, const std::string& why) {
  static std::mutex mutex;
  static std::set<std::string> warned;
  std::lock_guard lock(mutex);
  if (warned.insert(dir.string()).second) {
    spdlog::warn("mesh cache: cannot write to '{}' ({}); meshes load without the cache", dir.string(), why);
  }
}

struct HashInput {
  std::uint32_t format_version;
  std::uint32_t bullet_version;
  double scale[3];
};

std::string short_name(const std::filesystem::path& file) { return file.filename().string(); }

/// Validates a cache file's header against the expected key and the file's size;
/// returns the payload layout or the reason for rejecting the file.
std::optional<Layout> check_header(const FileHeader& h, const MeshCacheKey& key, std::size_t file_size,
                                   std::string& why) {
  if (h.magic != kMagic) {
    why = "bad magic";
    return std::nullopt;
  }
  if (h.format_version != kMeshCacheFormatVersion || h.header_bytes != sizeof(FileHeader) ||
      h.endian_tag != kEndianTag || h.scalar_bytes != sizeof(btScalar) || h.pointer_bytes != sizeof(void*) ||
      h.bullet_version != BT_BULLET_VERSION) {
    why = "format or platform mismatch";
    return std::nullopt;
  }
  if (h.header_hash != header_hash(h)) {
    why = "header checksum mismatch";
    return std::nullopt;
  }
  if (h.key_low != key.low || h.key_high != key.high) {
    why = "key mismatch";
    return std::nullopt;
  }
  if (h.triangle_count == 0 || h.vertex_count < 3 || h.vertex_count > std::numeric_limits<std::uint32_t>::max() ||
      h.normal_count != h.vertex_count || h.bvh_bytes == 0 ||
      h.triangle_count > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
    why = "implausible counts";
    return std::nullopt;
  }
  const auto layout =
      layout_for(h.vertex_count, h.triangle_count, h.normal_count, h.bvh_bytes, h.source_bytes, file_size);
  if (!layout || layout->end != file_size || h.payload_bytes != file_size - sizeof(FileHeader)) {
    why = fmt::format("size mismatch ({} bytes)", file_size);
    return std::nullopt;
  }
  return layout;
}

/// XXH3-128 of `bytes`, a window at a time: each window's pages are mapped in one call
/// (not a fault each), and those from `release_from` on are let go once hashed, so a large
/// entry is never resident at once (the tree's check maps its pages again). The bytes at
/// `head_at` are read from `head`, a copy taken before the tree's adoption writes there.
ContentHash::Digest hash_mapped(std::span<const std::byte> bytes, const std::byte* release_from, std::size_t head_at,
                          std::span<const std::byte> head) {
  constexpr std::size_t kWindow = std::size_t{64} << 20;
  ContentHash state;
  if (!state.ok()) return {};
  const auto hash_range = [&](std::span<const std::byte> range) {
    for (std::size_t at = 0; at < range.size(); at += kWindow) {
      const std::span<const std::byte> window = range.subspan(at, std::min(kWindow, range.size() - at));
      populate_for_reading(window.data(), window.size());
      state.update(window);
      if (window.data() + window.size() > release_from) {
        const std::byte* from = std::max(window.data(), release_from);
        release_file_pages(from, static_cast<std::size_t>(window.data() + window.size() - from));
      }
    }
  };
  hash_range(bytes.first(head_at));
  state.update(head);
  hash_range(bytes.subspan(head_at + head.size()));
  return state.digest();
}

/// The n elements of a section at `offset` of an entry's image. The layout puts each
/// section on a 16-byte boundary and a mapping starts on a page, so they lie aligned.
template <class T>
std::span<T> section_of(std::span<std::byte> image, std::size_t offset, std::size_t n) {
  return {reinterpret_cast<T*>(image.data() + offset), n};
}

/// Adopts the sections before the tree as `mesh`'s arrays where they lie in the image
/// (kept alive by `image_owner`). MeshBvh::adopt_serialized() checks them there, in the
/// passes that read them anyway: every index in range and every corner distinct, every
/// vertex and normal finite. A matching checksum makes accidental corruption vanishingly
/// unlikely; the checks keep a hand-made file from breaking the mesh's invariants.
void adopt_mesh_sections(const FileHeader& h, const Layout& layout, std::span<std::byte> image,
                         const std::shared_ptr<void>& image_owner, TriangleMesh& mesh) {
  const auto nv = static_cast<std::size_t>(h.vertex_count);
  const auto nt = static_cast<std::size_t>(h.triangle_count);
  mesh.vertices_m = adopt_mesh_array(section_of<Eigen::Vector3d>(image, layout.vertices, nv), image_owner);
  mesh.triangles = adopt_mesh_array(section_of<TriangleIndices>(image, layout.triangles, nt), image_owner);
  mesh.vertex_normals = adopt_mesh_array(section_of<Eigen::Vector3f>(image, layout.normals, nv), image_owner);
}

/// Builds the mesh and BVH from a whole cache file image whose header passed
/// check_header(), adopting the tree in place in the image (a private mapping of the
/// file, which `image_owner` keeps alive); returns null with the reason if the payload
/// fails validation.
std::unique_ptr<MeshBvh> parse_payload(const FileHeader& h, const Layout& layout, std::span<std::byte> image,
                                       const std::shared_ptr<void>& image_owner, std::string& why) {
  // The checksum is read on a helper thread while this one (and another) check the mesh,
  // its face normals and the tree where they lie in the entry; the tree is adopted only
  // once the checksum holds too.
  const std::span<const std::byte> payload = std::span<const std::byte>(image).subspan(sizeof(FileHeader));
  // The tree's head as the file has it: adopting the tree rebuilds Bullet's object there
  // while the checksum is still being read. Its page is never let go (that would drop
  // what the adoption wrote); the tree's other pages are.
  std::array<std::byte, MeshBvh::kSerializedHeadBytes> head_copy{};
  const std::span<const std::byte> head(head_copy.data(), std::min<std::size_t>(head_copy.size(), h.bvh_bytes));
  std::memcpy(head_copy.data(), image.data() + layout.bvh, head.size());
  const std::size_t head_at = layout.bvh - sizeof(FileHeader);
  const std::byte* const release_from = image.data() + layout.bvh + head.size();
  std::future<ContentHash::Digest> hashed;
  try {
    hashed = std::async(std::launch::async, hash_mapped, payload, release_from, head_at, head);
  } catch (const std::system_error&) {
    hashed = std::async(std::launch::deferred, hash_mapped, payload, release_from, head_at, head);
  }
  const auto checksum_holds = [&] {
    const ContentHash::Digest sum = hashed.get();
    return sum.low64 == h.payload_hash_low && sum.high64 == h.payload_hash_high;
  };
  auto mesh = std::make_shared<TriangleMesh>();
  adopt_mesh_sections(h, layout, image, image_owner, *mesh);
  bool checksum_held = true;
  const std::span<std::byte> tree = image.subspan(layout.bvh, static_cast<std::size_t>(h.bvh_bytes));
  // The face normals are the entry's too, checked against the triangles' own as they
  // are taken.
  auto face_normals_O = adopt_mesh_array(section_of<Eigen::Vector3d>(image, layout.face_normals, mesh->triangles.size()),
                                         std::shared_ptr<const void>(image_owner));
  auto bvh = MeshBvh::adopt_serialized(std::move(mesh), tree, image_owner, MeshBvh::TreePages::Release, [&] {
    checksum_held = checksum_holds();
    // From here on the tree's pages are read where walks go: a fault maps its own page,
    // not its neighbours. The mesh's pages, just checked, stay mapped: sweeps read its
    // triangles without a fault.
    if (checksum_held) ::madvise(image.data(), image.size(), MADV_RANDOM);
    return checksum_held;
  }, std::move(face_normals_O));
  if (!checksum_held) {
    why = "payload checksum mismatch";
    return nullptr;
  }
  // Its check holds every leaf's box to its triangle and every box to its children's, so
  // a query by a triangle's own box finds that triangle: a tree built to another
  // convention fails it as a hand-made one does.
  if (!bvh) why = "invalid serialized BVH";
  return bvh;
}

/// Reads and validates the cache file for `key`: nullptr with `why` set if it is
/// unusable, nullptr with `why` empty if there is none.
std::unique_ptr<MeshBvh> read_cache_file(const std::filesystem::path& path, const MeshCacheKey& key,
                                         const std::string& name, const MeshProgress& progress, std::string& why) {
  // O_NONBLOCK: a FIFO in the cache folder must not block the open (refused below).
  Fd fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
  if (fd.fd < 0) {
    if (errno != ENOENT && errno != ENOTDIR) why = fmt::format("cannot open: {}", std::strerror(errno));
    return nullptr;
  }
  struct stat st {};
  if (::fstat(fd.fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    why = "not a regular file";
    return nullptr;
  }
  const auto size = static_cast<std::size_t>(st.st_size);
  FileHeader h;
  if (size < sizeof(FileHeader) || !read_all(fd.fd, reinterpret_cast<std::byte*>(&h), sizeof h)) {
    why = "truncated header";
    return nullptr;
  }
  const auto layout = check_header(h, key, size, why);
  if (!layout) return nullptr;
  const bool report = progress && h.triangle_count >= kProgressMinTriangles;
  const std::string what = fmt::format("reading cached BVH of {}", name);
  if (report) progress(what, 0.0);
  // The file mapped, private and writable: Bullet writes the tree's header where it lies
  // (a copy of that page), and the nodes stay the file's pages. Our writers replace an
  // entry by renaming a new file over it, so a mapped file is never truncated under it.
  void* mapped = ::mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE, fd.fd, 0);
  if (mapped == MAP_FAILED) {
    why = fmt::format("cannot map: {}", std::strerror(errno));
    return nullptr;
  }
  const std::shared_ptr<void> image_owner(mapped, [size](void* p) { ::munmap(p, size); });
  const std::span<std::byte> image(static_cast<std::byte*>(mapped), size);
  if (std::memcmp(image.data(), &h, sizeof h) != 0) {
    why = "file changed while read";
    return nullptr;
  }
  auto bvh = parse_payload(h, *layout, image, image_owner, why);
  if (report) progress(what, 1.0);
  return bvh;
}

}  // namespace

std::optional<std::filesystem::path> default_mesh_cache_dir() {
  auto env = [](const char* name) -> std::string {
    const char* v = std::getenv(name);
    return v != nullptr ? std::string(v) : std::string();
  };
  if (auto d = env("MHD_CACHE_DIR"); !d.empty()) return std::filesystem::path(d);
  if (auto d = env("XDG_CACHE_HOME"); !d.empty() && std::filesystem::path(d).is_absolute()) {
    return std::filesystem::path(d) / "mhd";
  }
  if (auto d = env("HOME"); !d.empty()) return std::filesystem::path(d) / ".cache" / "mhd";
  return std::nullopt;
}

std::string MeshCacheKey::hex() const { return fmt::format("{:016x}{:016x}", high, low); }

std::optional<MeshCacheKey> mesh_cache_key(const std::filesystem::path& file, const Eigen::Vector3d& scale_to_m) {
  RegularFile opened(file);  // never blocks on a FIFO; the loader then says what it is
  if (!opened.ok()) return std::nullopt;
  Fd fd(opened.release());
  ::posix_fadvise(fd.fd, 0, 0, POSIX_FADV_SEQUENTIAL);
  ContentHash state;
  if (!state.ok()) return std::nullopt;
  // A chunk that stays in the core's cache between its copy and its hash (4 MiB: 14-26 %
  // slower on a 1.9 GB file).
  constexpr std::size_t kChunk = std::size_t{256} << 10;
  const auto buffer = std::make_unique_for_overwrite<std::byte[]>(kChunk);
  for (;;) {
    const ssize_t n = ::read(fd.fd, buffer.get(), kChunk);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return std::nullopt;
    if (n == 0) break;
    state.update(buffer.get(), static_cast<std::size_t>(n));
  }
  // +0.0 folds -0.0 so equal scales give equal keys.
  const HashInput extra{kMeshCacheFormatVersion, BT_BULLET_VERSION,
                        {scale_to_m.x() + 0.0, scale_to_m.y() + 0.0, scale_to_m.z() + 0.0}};
  state.update(&extra, sizeof extra);
  const ContentHash::Digest h = state.digest();
  return MeshCacheKey{h.low64, h.high64};
}

std::optional<std::string> mesh_cache_entry_source(const std::filesystem::path& entry) {
  Fd fd(::open(entry.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
  if (fd.fd < 0) return std::nullopt;
  struct stat st {};
  if (::fstat(fd.fd, &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
  FileHeader h;
  if (::pread(fd.fd, &h, sizeof h, 0) != static_cast<ssize_t>(sizeof h)) return std::nullopt;
  std::string why;
  const auto layout = check_header(h, MeshCacheKey{h.key_low, h.key_high}, static_cast<std::size_t>(st.st_size), why);
  if (!layout) return std::nullopt;
  std::string source(static_cast<std::size_t>(h.source_bytes), '\0');
  if (!source.empty() && ::pread(fd.fd, source.data(), source.size(), static_cast<off_t>(layout->source)) !=
                             static_cast<ssize_t>(source.size())) {
    return std::nullopt;
  }
  return source;
}

MeshCache::MeshCache(std::optional<std::filesystem::path> dir)
    : dir_(std::move(dir)), limit_bytes_(mesh_cache_limit_bytes()) {
  if (!dir_) return;
  std::error_code ec;
  std::filesystem::create_directories(*dir_, ec);
  if (ec) {
    warn_unwritable_once(*dir_, ec.message());
  } else if (::access(dir_->c_str(), W_OK | X_OK) != 0) {
    warn_unwritable_once(*dir_, std::strerror(errno));
  } else {
    writable_ = true;
  }
}

std::filesystem::path MeshCache::file_for(const MeshCacheKey& key) const {
  return dir_.value_or(std::filesystem::path()) / (key.hex() + kExtension);
}

Result<CachedMesh, MeshLoadError> MeshCache::load(const std::filesystem::path& file, const Eigen::Vector3d& scale_to_m,
                                                  const MeshProgress& progress, std::optional<TriangleBudget> budget) {
  CachedMesh result;
  const std::string name = short_name(file);
  std::optional<MeshCacheKey> key;
  if (dir_) {
    // The key reads the whole file: what its header alone refuses is refused first.
    if (std::optional<MeshLoadError> refused =
            refusal_from_header(file, budget, TriangleBudget::kCachedBytesPerTriangle)) {
      return *std::move(refused);
    }
    bool remembered = false;
    key = mesh_key_remembered_or_hashed(*dir_, file, scale_to_m, writable_, remembered);
    if (remembered) ++stats_.keys_remembered;
    if (key && !remembered) ++stats_.keys_hashed;
  }

  // 1. Try the cache file.
  if (key) {
    result.cache_file = file_for(*key);
    std::string why;
    auto bvh = read_cache_file(result.cache_file, *key, name, progress, why);
    if (bvh && budget) {
      if (std::string refused = budget->refusal("", bvh->mesh().triangle_count(), "triangles"); !refused.empty()) {
        return MeshLoadError{file, std::move(refused)};
      }
    }
    if (bvh) {
      ++stats_.hits;
      result.outcome = CacheOutcome::Hit;
      result.bvh = std::shared_ptr<const MeshBvh>(std::move(bvh));
      spdlog::debug("mesh cache: hit for '{}' ({})", file.string(), result.cache_file.string());
      // Recently used: eviction goes by modification time. Best effort (read-only folder).
      std::error_code touch_ec;
      std::filesystem::last_write_time(result.cache_file, std::filesystem::file_time_type::clock::now(), touch_ec);
      return result;
    }
    if (why.empty()) {
      ++stats_.misses;
      result.outcome = CacheOutcome::Miss;
    } else {
      ++stats_.rejected;
      result.outcome = CacheOutcome::Rejected;
      result.rejected_reason = why;
      spdlog::info("mesh cache: ignoring '{}' for '{}': {}; rebuilding", result.cache_file.string(), file.string(),
                   why);
    }
  }

  // 2. Load the file and build the BVH.
  MeshProgress read_progress;
  std::error_code ec;
  const auto file_bytes = std::filesystem::file_size(file, ec);
  // Roughly 16+ bytes per triangle in binary formats; text formats are larger, so this
  // errs towards reporting.
  if (progress && !ec && file_bytes >= kProgressMinTriangles * 16) read_progress = progress;
  Result<LoadedMesh, MeshLoadError> loaded = load_mesh_file(file, scale_to_m, read_progress, budget);
  if (!loaded.ok()) return loaded.error();
  result.dropped_triangles = loaded->dropped_triangles;
  result.flipped_triangles = loaded->flipped_triangles;
  result.unisolated_read = loaded->unisolated_read;
  if (!MeshBvh::holds(loaded->mesh.triangle_count())) {
    return MeshLoadError{file, fmt::format("{} triangles, more than the {} one collision tree holds",
                                           loaded->mesh.triangle_count(), MeshBvh::kMaxTriangles)};
  }
  auto mesh = std::make_shared<const TriangleMesh>(std::move(loaded->mesh));
  const bool big = mesh->triangle_count() >= kProgressMinTriangles;
  const std::string what = fmt::format("building BVH of {} ({} triangles)", name, mesh->triangle_count());
  if (big && progress) progress(what, 0.0);
  // A mesh large enough to be built in pieces is kept in its leaves' order: its file's
  // order would scatter a tick's triangles, and the cached tree's check, over gigabytes.
  const auto order = mesh->triangle_count() >= kSplitBuildMinTriangles ? MeshBvh::MeshOrder::Leaves
                                                                       : MeshBvh::MeshOrder::AsGiven;
  BuildProgress build_progress;
  if (big && progress) build_progress = [&](double fraction) { progress(what, fraction); };
  auto bvh = std::make_shared<const MeshBvh>(std::move(mesh), order, build_progress);
  if (big && progress) progress(what, 1.0);
  result.bvh = bvh;

  // 3. Store it.
  if (key && writable_) store(file, result.cache_file, *key, *bvh, big ? progress : MeshProgress{}, result);
  return result;
}

void MeshCache::store(const std::filesystem::path& mesh_file, const std::filesystem::path& target,
                      const MeshCacheKey& key, const MeshBvh& bvh, const MeshProgress& progress,
                      CachedMesh& result) {
  const TriangleMesh& mesh = bvh.mesh();
  MeshBvh::SerializedTree serialized;
  try {
    serialized = bvh.serialize_tree();
  } catch (const std::exception& e) {
    ++stats_.write_failures;
    spdlog::warn("mesh cache: not caching '{}': {}", mesh_file.string(), e.what());
    return;
  }
  // The mesh file it came from, for `mhd cache list` (the key is its content, not its name).
  std::error_code absolute_ec;
  std::string source = std::filesystem::absolute(mesh_file, absolute_ec).lexically_normal().string();
  if (absolute_ec || source.size() > kMaxSourceBytes) source.clear();
  const std::size_t limit = std::numeric_limits<std::size_t>::max() / 2;
  const auto layout = layout_for(mesh.vertices_m.size(), mesh.triangles.size(), mesh.vertex_normals.size(),
                                 serialized.size, source.size(), limit);
  if (!layout || mesh.vertex_normals.size() != mesh.vertices_m.size()) {
    ++stats_.write_failures;
    return;
  }

  // Sections with the zero padding between them, in file order.
  static constexpr std::array<std::byte, kAlign> kZeros{};
  std::vector<std::span<const std::byte>> parts;
  std::size_t at = sizeof(FileHeader);
  auto add = [&](std::size_t offset, const void* data, std::size_t bytes) {
    if (offset > at) parts.emplace_back(kZeros.data(), offset - at);
    parts.emplace_back(static_cast<const std::byte*>(data), bytes);
    at = offset + bytes;
  };
  add(layout->vertices, mesh.vertices_m.data(), mesh.vertices_m.size() * sizeof(Eigen::Vector3d));
  add(layout->triangles, mesh.triangles.data(), mesh.triangles.size() * sizeof(TriangleIndices));
  add(layout->normals, mesh.vertex_normals.data(), mesh.vertex_normals.size() * sizeof(Eigen::Vector3f));
  add(layout->face_normals, bvh.face_normals_O().data(), bvh.face_normals_O().size_bytes());
  add(layout->bvh, serialized.bytes.get(), serialized.size);
  add(layout->source, source.data(), source.size());

  ContentHash state;
  if (!state.ok()) {
    ++stats_.write_failures;
    return;
  }
  // The step starts with the checksum, which reads every byte once before the write.
  const std::string what = fmt::format("writing cached BVH of {}", short_name(mesh_file));
  if (progress) progress(what, 0.0);
  for (const auto& p : parts) state.update(p);
  const ContentHash::Digest payload = state.digest();

  FileHeader h{};
  h.magic = kMagic;
  h.format_version = kMeshCacheFormatVersion;
  h.header_bytes = sizeof(FileHeader);
  h.endian_tag = kEndianTag;
  h.scalar_bytes = sizeof(btScalar);
  h.pointer_bytes = sizeof(void*);
  h.bullet_version = BT_BULLET_VERSION;
  h.key_low = key.low;
  h.key_high = key.high;
  h.vertex_count = mesh.vertices_m.size();
  h.triangle_count = mesh.triangles.size();
  h.normal_count = mesh.vertex_normals.size();
  h.bvh_bytes = serialized.size;
  h.source_bytes = source.size();
  h.payload_bytes = layout->end - sizeof(FileHeader);
  h.payload_hash_low = payload.low64;
  h.payload_hash_high = payload.high64;
  h.header_hash = header_hash(h);

  // Unique temp name in the same folder, then an atomic rename over the target.
  static std::atomic<unsigned> counter{0};
  std::filesystem::path temp = target;
  temp += fmt::format(".tmp.{}.{}", ::getpid(), counter.fetch_add(1));
  bool ok = false;
  std::string why;
  {
    Fd fd(::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644));
    if (fd.fd < 0) {
      why = std::strerror(errno);
    } else {
      ok = write_all(fd.fd, reinterpret_cast<const std::byte*>(&h), sizeof h);
      // In chunks, so that the step's progress moves while gigabytes are written.
      std::size_t written = sizeof h;
      for (const auto& p : parts) {
        for (std::size_t from = 0; ok && from < p.size(); from += kWriteChunkBytes) {
          const std::size_t n = std::min(kWriteChunkBytes, p.size() - from);
          ok = write_all(fd.fd, p.data() + from, n);
          written += n;
          if (progress && written < layout->end) {  // the end is reported once, below
            progress(what, static_cast<double>(written) / static_cast<double>(layout->end));
          }
        }
      }
      if (!ok) why = std::strerror(errno);
      if (::close(fd.fd) != 0 && ok) {
        ok = false;
        why = std::strerror(errno);
      }
      fd.fd = -1;
    }
  }
  if (progress) progress(what, 1.0);  // the step ends, written or not (a failure warns)
  std::error_code ec;
  if (ok) {
    std::filesystem::rename(temp, target, ec);
    if (ec) {
      ok = false;
      why = ec.message();
    }
  }
  if (!ok) {
    std::filesystem::remove(temp, ec);
    ++stats_.write_failures;
    writable_ = false;
    warn_unwritable_once(*dir_, why);
    return;
  }
  ++stats_.writes;
  result.written = true;
  spdlog::debug("mesh cache: wrote '{}'", target.string());
  if (const std::uint64_t entry_bytes = layout->end; entry_bytes > limit_bytes_) {
    result.over_limit = fmt::format(
        "the cache entry of '{}' takes {}, more than the cache's limit of {} (set by MHD_CACHE_MAX_MB); "
        "it is kept until another mesh is cached",
        mesh_file.string(), byte_count_text(entry_bytes), byte_count_text(limit_bytes_));
    spdlog::warn("mesh cache: {}", result.over_limit);
  }
  const MeshCacheRemoval evicted = evict_mesh_cache(*dir_, limit_bytes_, target);
  if (evicted.removed > 0)
    spdlog::info("mesh cache: removed {} least recently used entries ({:.1f} MiB) to stay within {:.0f} MiB",
                 evicted.removed, static_cast<double>(evicted.freed_bytes) / 1048576.0,
                 static_cast<double>(limit_bytes_) / 1048576.0);
}

}  // namespace mhd
