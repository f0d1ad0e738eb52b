#pragma once
// The meshes' memory locked in RAM (mlock) before a run starts, so that no haptic tick
// waits on a page fault. Without it, a page of a mesh's arrays or tree that the kernel
// has let go comes back, from the page cache or the disk, inside the tick that first
// reads it: a cached tree's pages are let go once checked (mesh_cache.h), and any page
// may go under memory pressure. Opt-in (`mhd run --lock-meshes`): a 100 M-triangle mesh
// locks 8.7 GB, and locking needs the limit on locked memory (RLIMIT_MEMLOCK) raised or
// CAP_IPC_LOCK.

#include "collision/collision_world.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace mhd {

/// A block of memory that haptic ticks read.
struct MemoryBlock {
  const void* data = nullptr;
  std::size_t bytes = 0;
};

/// Every block a tick may read of the world's meshes: each mesh's vertices, triangles,
/// vertex normals, face normals and tree nodes, and each object's shading normals. A mesh
/// that several objects share is listed once; empty arrays are left out.
[[nodiscard]] std::vector<MemoryBlock> mesh_memory_blocks(const CollisionWorld& world);

/// The calls that lock and unlock pages, replaceable by a test.
struct PageLockCalls {
  int (*lock)(const void*, std::size_t) = nullptr;    ///< null: system_page_lock_calls()'s
  int (*unlock)(const void*, std::size_t) = nullptr;  ///< null: system_page_lock_calls()'s
};

/// The kernel's: mlock2 with MLOCK_ONFAULT, and munlock made as a system call, since the
/// sanitizers replace munlock (and mlock) with calls that do nothing.
[[nodiscard]] PageLockCalls system_page_lock_calls();

struct PageLock;

/// Pages locked in RAM; unlocked when this goes. Move-only.
class LockedPages {
 public:
  LockedPages() = default;
  LockedPages(const LockedPages&) = delete;
  LockedPages& operator=(const LockedPages&) = delete;
  LockedPages(LockedPages&& other) noexcept;
  LockedPages& operator=(LockedPages&& other) noexcept;
  ~LockedPages();

  /// Bytes locked: the blocks rounded out to whole pages, each page counted once.
  [[nodiscard]] std::size_t bytes() const { return bytes_; }

 private:
  friend PageLock lock_pages(std::span<const MemoryBlock> blocks, const std::function<void(double)>& progress,
                             PageLockCalls calls);
  struct Span {
    std::uintptr_t begin = 0;
    std::size_t bytes = 0;
  };
  void unlock_all() noexcept;

  std::vector<Span> spans_;
  std::size_t bytes_ = 0;
  PageLockCalls calls_;
};

/// What locking gave: the pages, or why none are locked.
struct PageLock {
  LockedPages pages;
  std::optional<std::string> error;  ///< set: nothing is locked
};

/// Locks the pages holding `blocks` and reads each in, calling `progress` with the
/// fraction read (0 first, 1 last). Refuses, locking nothing, when those not in memory yet
/// are more than the machine has available; on a failed lock, unlocks what it locked and
/// says how much was wanted, the limit on locked memory (RLIMIT_MEMLOCK) and how to raise
/// it.
[[nodiscard]] PageLock lock_pages(std::span<const MemoryBlock> blocks, const std::function<void(double)>& progress = {},
                                  PageLockCalls calls = {});

}  // namespace mhd
