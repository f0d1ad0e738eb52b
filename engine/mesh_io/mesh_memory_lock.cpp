#include "mesh_io/mesh_memory_lock.h"

#include "mesh_io/available_memory.h"

#include <fmt/core.h>

#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <limits>
#include <set>
#include <utility>

namespace mhd {
namespace {

// Bytes faulted in between progress reports: about 140 reports for a 100 M-triangle
// mesh's 8.7 GB.
constexpr std::size_t kChunkBytes = std::size_t{64} << 20;

template <class T>
void add_block(std::vector<MemoryBlock>& blocks, const T* data, std::size_t count) {
  if (count > 0) blocks.push_back(MemoryBlock{data, count * sizeof(T)});
}

std::string size_text(std::uint64_t bytes) {
  if (bytes >= (std::uint64_t{1} << 30)) return fmt::format("{:.1f} GiB", static_cast<double>(bytes) / (1U << 30));
  if (bytes >= (std::uint64_t{1} << 20)) return fmt::format("{:.1f} MiB", static_cast<double>(bytes) / (1U << 20));
  return fmt::format("{} KiB", bytes / 1024);
}

std::string memlock_limit_text() {
  rlimit limit{};
  if (::getrlimit(RLIMIT_MEMLOCK, &limit) != 0) return "unknown";
  return limit.rlim_cur == RLIM_INFINITY ? std::string("unlimited") : size_text(limit.rlim_cur);
}

std::string how_to_raise() {
  return fmt::format(
      "the limit on locked memory (RLIMIT_MEMLOCK) is {}: raise it (`ulimit -l`, or memlock in "
      "/etc/security/limits.conf) or give the process CAP_IPC_LOCK",
      memlock_limit_text());
}

// Bytes of the pages of [begin, begin + bytes) (whole pages) that are not in memory
// (mincore), a chunk at a time; from a chunk that is not all mapped on, none is.
std::uint64_t bytes_not_in_memory(std::uintptr_t begin, std::size_t bytes, std::uintptr_t page) {
  std::vector<unsigned char> in_memory(kChunkBytes / page);
  std::uint64_t out = 0;
  for (std::size_t offset = 0; offset < bytes; offset += kChunkBytes) {
    const std::size_t n = std::min(kChunkBytes, bytes - offset);
    if (::mincore(reinterpret_cast<void*>(begin + offset), n, in_memory.data()) != 0) {  // NOLINT: an address
      return out + (bytes - offset);
    }
    for (std::size_t i = 0; i < n / page; ++i) {
      if ((in_memory[i] & 1U) == 0) out += page;
    }
  }
  return out;
}

}  // namespace

PageLockCalls system_page_lock_calls() {
  PageLockCalls calls;
  // Locked as they are faulted in, and lock_pages() then reads each in: a plain mlock
  // faults a private, writable file mapping (a cache entry's) in for writing, copying
  // every page out of the page cache, 4 KiB at a time.
  calls.lock = [](const void* p, std::size_t n) { return ::mlock2(p, n, MLOCK_ONFAULT); };
  calls.unlock = [](const void* p, std::size_t n) { return static_cast<int>(::syscall(SYS_munlock, p, n)); };
  return calls;
}

std::vector<MemoryBlock> mesh_memory_blocks(const CollisionWorld& world) {
  std::vector<MemoryBlock> blocks;
  std::set<const MeshBvh*> seen;
  for (int i = 0; i < world.object_count(); ++i) {
    const MeshBvh& bvh = world.shape(i);
    if (seen.insert(&bvh).second) {
      const TriangleMesh& m = bvh.mesh();
      add_block(blocks, m.vertices_m.data(), m.vertices_m.size());
      add_block(blocks, m.triangles.data(), m.triangles.size());
      add_block(blocks, m.vertex_normals.data(), m.vertex_normals.size());
      add_block(blocks, bvh.face_normals_O().data(), bvh.face_normals_O().size());
      add_block(blocks, bvh.tree_nodes().data(), bvh.tree_nodes().size());
    }
    if (const ShadingNormals* normals = world.shading_normals(i)) {
      add_block(blocks, normals->corner_normals_O.data(), normals->corner_normals_O.size());
    }
  }
  return blocks;
}

LockedPages::LockedPages(LockedPages&& other) noexcept
    : spans_(std::move(other.spans_)), bytes_(std::exchange(other.bytes_, 0)), calls_(other.calls_) {
  other.spans_.clear();
}

LockedPages& LockedPages::operator=(LockedPages&& other) noexcept {
  if (this != &other) {
    unlock_all();
    spans_ = std::move(other.spans_);
    other.spans_.clear();
    bytes_ = std::exchange(other.bytes_, 0);
    calls_ = other.calls_;
  }
  return *this;
}

LockedPages::~LockedPages() { unlock_all(); }

void LockedPages::unlock_all() noexcept {
  for (const Span& s : spans_) {
    // Nothing to do about a failed unlock: the pages stay locked until the process ends.
    (void)calls_.unlock(reinterpret_cast<const void*>(s.begin), s.bytes);  // NOLINT: an address as a pointer
  }
  spans_.clear();
  bytes_ = 0;
}

PageLock lock_pages(std::span<const MemoryBlock> blocks, const std::function<void(double)>& progress,
                    PageLockCalls calls) {
  if (calls.lock == nullptr) calls.lock = system_page_lock_calls().lock;
  if (calls.unlock == nullptr) calls.unlock = system_page_lock_calls().unlock;
  const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  // The blocks rounded out to whole pages, sorted and merged: each page once.
  std::vector<std::pair<std::uintptr_t, std::uintptr_t>> ranges;
  std::uint64_t block_bytes = 0;
  for (const MemoryBlock& b : blocks) {
    if (b.bytes == 0) continue;
    block_bytes += b.bytes;
    const auto begin = reinterpret_cast<std::uintptr_t>(b.data);  // NOLINT: a pointer as an address
    const std::uintptr_t last = begin + (b.bytes - 1);
    const std::uintptr_t end = last < begin ? std::numeric_limits<std::uintptr_t>::max() : last + 1;
    ranges.emplace_back(begin / page * page, end / page * page + (end % page != 0 ? page : 0));
  }
  std::sort(ranges.begin(), ranges.end());
  std::vector<LockedPages::Span> merged;
  std::uint64_t wanted = 0;
  for (const auto& [begin, end] : ranges) {
    if (!merged.empty() && begin <= merged.back().begin + merged.back().bytes) {
      LockedPages::Span& s = merged.back();
      s.bytes = std::max<std::uintptr_t>(s.begin + s.bytes, end) - s.begin;
    } else {
      merged.push_back({begin, end - begin});
    }
  }
  for (const LockedPages::Span& s : merged) wanted += s.bytes;

  PageLock result;
  result.pages.calls_ = calls;
  if (progress) progress(0.0);
  // Only pages not in memory yet need memory to lock: the machine must have that much.
  std::uint64_t to_read = 0;
  for (const LockedPages::Span& s : merged) to_read += bytes_not_in_memory(s.begin, s.bytes, page);
  if (const std::uint64_t available = available_memory_bytes(); available > 0 && to_read > available) {
    result.error = fmt::format("cannot lock {} of mesh memory in RAM: {} of it is not in memory, and the machine has {} "
                               "available",
                               size_text(wanted), size_text(to_read), size_text(available));
    return result;
  }
  for (const LockedPages::Span& s : merged) {
    if (calls.lock(reinterpret_cast<const void*>(s.begin), s.bytes) != 0) {  // NOLINT: an address as a pointer
      const int error = errno;
      const std::uint64_t locked = result.pages.bytes();  // before the unlock counts it back to zero
      result.pages.unlock_all();
      result.error = fmt::format("cannot lock {} of mesh memory in RAM: mlock failed after {}: {}; {}",
                                 size_text(wanted), size_text(locked), std::strerror(error), how_to_raise());
      return result;
    }
    result.pages.spans_.push_back(s);
    result.pages.bytes_ += s.bytes;
  }
  // Every page of every block read once, inside the block (the rest of a rounded page
  // may be another object's), a chunk at a time for the progress.
  std::uint64_t done = 0;
  std::uint64_t reported = 0;
  for (const MemoryBlock& b : blocks) {
    const auto* bytes = static_cast<const volatile unsigned char*>(b.data);
    const auto begin = reinterpret_cast<std::uintptr_t>(b.data);  // NOLINT: a pointer as an address
    for (std::size_t offset = 0; offset < b.bytes; offset = (begin + offset) / page * page + page - begin) {
      (void)bytes[offset];
    }
    done += b.bytes;
    if (progress && done - reported >= kChunkBytes) {
      reported = done;
      progress(static_cast<double>(done) / static_cast<double>(block_bytes));
    }
  }
  if (progress) progress(1.0);
  return result;
}

}  // namespace mhd
