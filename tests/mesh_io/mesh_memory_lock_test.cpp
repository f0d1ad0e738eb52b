// The meshes' memory locked in RAM: judged from the kernel's side (VmLck in
// /proc/self/status), with the failures a real lock can meet made by replacing the calls.

#include "mesh_io/mesh_memory_lock.h"

#include "geometry/primitive_mesh.h"
#include "geometry/shading_normals.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <sys/mman.h>
#include <unistd.h>

namespace mhd {
namespace memory_lock_test {

// Locked bytes of this process, as the kernel counts them.
std::size_t locked_bytes_now() {
  std::ifstream in("/proc/self/status");
  std::string key;
  while (in >> key) {
    if (key == "VmLck:") {
      std::size_t kib = 0;
      in >> kib;
      return kib * 1024;
    }
    in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  ADD_FAILURE() << "no VmLck in /proc/self/status";
  return 0;
}

std::shared_ptr<const MeshBvh> sphere(int rings, int segments) {
  auto mesh = std::make_shared<TriangleMesh>(make_uv_sphere_mesh(0.05, rings, segments));
  compute_vertex_normals(*mesh);
  return std::make_shared<MeshBvh>(std::move(mesh));
}

// The world of the tests: one sphere in two places and a second, shaded sphere.
struct TwoSpheres {
  CollisionWorld world;
  std::shared_ptr<const MeshBvh> shared = sphere(24, 48);
  std::shared_ptr<const MeshBvh> shaded = sphere(16, 32);
  std::shared_ptr<const ShadingNormals> normals;
  TwoSpheres() {
    world.add_object(shared, Pose::Identity());
    world.add_object(shared, Pose(Eigen::Translation3d(0.2, 0.0, 0.0)));
    const int id = world.add_object(shaded, Pose(Eigen::Translation3d(-0.2, 0.0, 0.0)));
    normals = std::make_shared<ShadingNormals>(compute_shading_normals(shaded->mesh(), 0.5));
    world.set_shading_normals(id, normals);
  }
};

template <class T>
bool has_block(const std::vector<MemoryBlock>& blocks, const T* data, std::size_t count) {
  for (const MemoryBlock& b : blocks) {
    if (b.data == static_cast<const void*>(data) && b.bytes == count * sizeof(T)) return true;
  }
  return false;
}

void expect_mesh_blocks(const std::vector<MemoryBlock>& blocks, const MeshBvh& bvh) {
  const TriangleMesh& m = bvh.mesh();
  EXPECT_TRUE(has_block(blocks, m.vertices_m.data(), m.vertices_m.size()));
  EXPECT_TRUE(has_block(blocks, m.triangles.data(), m.triangles.size()));
  EXPECT_TRUE(has_block(blocks, m.vertex_normals.data(), m.vertex_normals.size()));
  EXPECT_TRUE(has_block(blocks, bvh.face_normals_O().data(), bvh.face_normals_O().size()));
  EXPECT_TRUE(has_block(blocks, bvh.tree_nodes().data(), bvh.tree_nodes().size()));
}

// Locking calls that fail from the second on (as a low RLIMIT_MEMLOCK makes them), and
// what the unlocking calls were given.
int lock_calls = 0;
std::size_t unlocked = 0;
int lock_once_then_fail(const void* p, std::size_t n) {
  if (lock_calls++ == 0) return system_page_lock_calls().lock(p, n);
  errno = ENOMEM;
  return -1;
}
int count_unlock(const void* p, std::size_t n) {
  unlocked += n;
  return system_page_lock_calls().unlock(p, n);
}
int never_lock(const void* /*p*/, std::size_t /*n*/) {
  ++lock_calls;
  return 0;
}

TEST(MeshMemoryLockTest, BlocksAreWhatATickReadsOfEachMeshOnce) {
  const TwoSpheres s;
  const std::vector<MemoryBlock> blocks = mesh_memory_blocks(s.world);
  // Five arrays a mesh (the shared one once), and the shaded object's normals.
  EXPECT_EQ(blocks.size(), 11U);
  expect_mesh_blocks(blocks, *s.shared);
  expect_mesh_blocks(blocks, *s.shaded);
  EXPECT_TRUE(has_block(blocks, s.normals->corner_normals_O.data(), s.normals->corner_normals_O.size()));
}

TEST(MeshMemoryLockTest, LocksEveryPageOfTheBlocksAndUnlocksThemWhenItGoes) {
  const TwoSpheres s;
  const std::vector<MemoryBlock> blocks = mesh_memory_blocks(s.world);
  std::size_t block_bytes = 0;
  for (const MemoryBlock& b : blocks) block_bytes += b.bytes;
  const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  const std::size_t before = locked_bytes_now();
  std::vector<double> progress;
  {
    PageLock locked = lock_pages(blocks, [&](double f) { progress.push_back(f); });
    ASSERT_FALSE(locked.error) << *locked.error;
    // Whole pages round blocks that do not share one: at least their bytes, at most two
    // pages more each.
    EXPECT_GE(locked.pages.bytes(), block_bytes);
    EXPECT_LE(locked.pages.bytes(), block_bytes + 2 * page * blocks.size());
    EXPECT_EQ(locked.pages.bytes() % page, 0U);
    EXPECT_EQ(locked_bytes_now() - before, locked.pages.bytes());
    // Moved, the pages stay locked, once.
    const LockedPages moved = std::move(locked.pages);
    EXPECT_EQ(locked_bytes_now() - before, moved.bytes());
  }
  EXPECT_EQ(locked_bytes_now(), before);
  ASSERT_GE(progress.size(), 2U);
  EXPECT_EQ(progress.front(), 0.0);
  EXPECT_EQ(progress.back(), 1.0);
}

TEST(MeshMemoryLockTest, AFailedLockUnlocksWhatItLockedAndSaysHowToRaiseTheLimit) {
  // Two pages with an unmapped one between: two calls, the second of which fails.
  const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  void* region = ::mmap(nullptr, 3 * page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(region, MAP_FAILED);
  auto* bytes = static_cast<std::byte*>(region);
  ASSERT_EQ(::munmap(bytes + page, page), 0);
  const std::vector<MemoryBlock> blocks{{bytes, page}, {bytes + 2 * page, page}};
  const std::size_t before = locked_bytes_now();
  lock_calls = 0;
  unlocked = 0;
  const PageLock locked = lock_pages(blocks, {}, PageLockCalls{lock_once_then_fail, count_unlock});
  ASSERT_TRUE(locked.error);
  EXPECT_EQ(lock_calls, 2);
  EXPECT_EQ(locked.pages.bytes(), 0U);
  EXPECT_EQ(unlocked, page);  // the first page, locked before the failure
  EXPECT_EQ(locked_bytes_now(), before);
  const std::string wanted = "cannot lock " + std::to_string(2 * page / 1024) + " KiB";
  EXPECT_NE(locked.error->find(wanted), std::string::npos) << *locked.error;
  // How much was locked when it failed: the first page, though it is unlocked since.
  const std::string after = "failed after " + std::to_string(page / 1024) + " KiB";
  EXPECT_NE(locked.error->find(after), std::string::npos) << *locked.error;
  EXPECT_NE(locked.error->find("RLIMIT_MEMLOCK"), std::string::npos) << *locked.error;
  EXPECT_NE(locked.error->find("CAP_IPC_LOCK"), std::string::npos) << *locked.error;
  EXPECT_NE(locked.error->find(std::strerror(ENOMEM)), std::string::npos) << *locked.error;
  ::munmap(bytes, page);
  ::munmap(bytes + 2 * page, page);
}

TEST(MeshMemoryLockTest, MoreThanTheMachineHasIsRefusedWithoutLockingAnything) {
  static const char byte = 0;
  const MemoryBlock huge{&byte, std::size_t{1} << 50};  // a petabyte
  lock_calls = 0;
  const PageLock locked = lock_pages(std::span<const MemoryBlock>(&huge, 1), {}, PageLockCalls{never_lock, count_unlock});
  ASSERT_TRUE(locked.error);
  EXPECT_EQ(lock_calls, 0);
  EXPECT_NE(locked.error->find("available"), std::string::npos) << *locked.error;
}

TEST(MeshMemoryLockTest, AWorldWithoutMeshesLocksNothing) {
  const CollisionWorld world;
  const std::vector<MemoryBlock> blocks = mesh_memory_blocks(world);
  EXPECT_TRUE(blocks.empty());
  const PageLock locked = lock_pages(blocks);
  EXPECT_FALSE(locked.error);
  EXPECT_EQ(locked.pages.bytes(), 0U);
}

}  // namespace memory_lock_test
}  // namespace mhd
