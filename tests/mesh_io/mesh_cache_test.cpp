#include "mesh_io/mesh_cache.h"

#include "mesh_io/mesh_cache_entry.h"

#include "collision/segment_triangle.h"
#include "geometry/primitive_mesh.h"
#include "support/large_mesh.h"
#include "sphere_cache_fixture.h"
#include "test_mesh_files.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstring>
#include <functional>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace mhd {
namespace {

using test::read_bytes;
using test::write_bytes;

std::vector<std::uint32_t> query(const MeshBvh& bvh, const Eigen::AlignedBox3d& box) {
  std::vector<std::uint32_t> hits;
  bvh.for_each_triangle_overlapping(box, [&](std::uint32_t t) { hits.push_back(t); });
  std::sort(hits.begin(), hits.end());
  return hits;
}

/// Random boxes of varied sizes around the mesh.
std::vector<Eigen::AlignedBox3d> random_boxes(const Eigen::AlignedBox3d& bounds, int count) {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Eigen::AlignedBox3d> boxes;
  const Eigen::Vector3d size = bounds.sizes();
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3d c = bounds.min() - 0.1 * size +
                              Eigen::Vector3d(u(rng), u(rng), u(rng)).cwiseProduct(1.2 * size);
    const Eigen::Vector3d half = size * (0.001 + 0.2 * u(rng) * u(rng));
    boxes.emplace_back(c - half, c + half);
  }
  return boxes;
}

/// The triangles whose own bounding box overlaps `box` (what a BVH query must report
/// at least).
std::vector<std::uint32_t> brute_force(const TriangleMesh& m, const Eigen::AlignedBox3d& box) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t i = 0; i < m.triangles.size(); ++i) {
    Eigen::AlignedBox3d tb;
    for (auto v : m.triangles[i]) tb.extend(m.vertices_m[v]);
    if (tb.intersects(box)) out.push_back(i);
  }
  return out;
}

using MeshCacheTest = test::SphereCacheFixture;

TEST_F(MeshCacheTest, SecondLoadHitsAndMatchesAFreshBuild) {
  MeshCache cache(cache_dir_);
  EXPECT_TRUE(cache.writable());
  const Result<CachedMesh, MeshLoadError> cold = cache.load(mesh_file_, Eigen::Vector3d::Ones());
  ASSERT_TRUE(cold.ok()) << cold.error_text();
  EXPECT_EQ(cold->outcome, CacheOutcome::Miss);
  EXPECT_TRUE(cold->written);
  EXPECT_TRUE(std::filesystem::is_regular_file(cold->cache_file));
  EXPECT_EQ(cold->cache_file.parent_path(), cache_dir_);

  const Result<CachedMesh, MeshLoadError> warm = cache.load(mesh_file_, Eigen::Vector3d::Ones());
  ASSERT_TRUE(warm.ok());
  EXPECT_EQ(warm->outcome, CacheOutcome::Hit);
  EXPECT_FALSE(warm->written);
  EXPECT_EQ(warm->cache_file, cold->cache_file);
  EXPECT_EQ(cache.stats().hits, 1u);
  EXPECT_EQ(cache.stats().misses, 1u);
  EXPECT_EQ(cache.stats().writes, 1u);
  EXPECT_NE(&warm->mesh(), &cold->mesh());

  // Bit-identical mesh data.
  EXPECT_EQ(warm->mesh().vertices_m, cold->mesh().vertices_m);
  EXPECT_EQ(warm->mesh().triangles, cold->mesh().triangles);
  EXPECT_EQ(warm->mesh().vertex_normals, cold->mesh().vertex_normals);
  EXPECT_EQ(warm->bvh->bounds().min(), cold->bvh->bounds().min());
  EXPECT_EQ(warm->bvh->bounds().max(), cold->bvh->bounds().max());

  // The cached BVH answers box queries exactly like a freshly built one.
  const MeshBvh fresh(warm->bvh->mesh_ptr());
  std::size_t reported = 0;
  for (const auto& box : random_boxes(fresh.bounds(), 300)) {
    const auto from_cache = query(*warm->bvh, box);
    EXPECT_EQ(from_cache, query(fresh, box));
    EXPECT_EQ(from_cache, query(*cold->bvh, box));
    const auto must = brute_force(warm->mesh(), box);
    EXPECT_TRUE(std::includes(from_cache.begin(), from_cache.end(), must.begin(), must.end()));
    reported += from_cache.size();
  }
  EXPECT_GT(reported, 0u);

  // The entry names the mesh file it was written from.
  EXPECT_EQ(mesh_cache_entry_source(cold->cache_file), std::filesystem::absolute(mesh_file_).lexically_normal().string());
  EXPECT_EQ(mesh_cache_entry_source(mesh_file_), std::nullopt);  // not an entry

  // A second cache object (another process, say) finds the file too.
  MeshCache other(cache_dir_);
  EXPECT_EQ(other.load(mesh_file_, Eigen::Vector3d::Ones())->outcome, CacheOutcome::Hit);
}

TEST_F(MeshCacheTest, AnEntryOverTheSizeLimitIsReportedWithItsSizeAndTheVariableNotDropped) {
  MeshCache small(cache_dir_);
  small.set_limit_bytes(1000);
  const Result<CachedMesh, MeshLoadError> over = small.load(mesh_file_, Eigen::Vector3d::Ones());
  ASSERT_TRUE(over.ok()) << over.error_text();
  ASSERT_TRUE(over->written);
  const auto entry_bytes = std::filesystem::file_size(over->cache_file);
  ASSERT_GT(entry_bytes, 1000u);
  EXPECT_EQ(over->over_limit, "the cache entry of '" + mesh_file_.string() + "' takes " +
                                  (entry_bytes < (1u << 20) ? std::to_string(entry_bytes) + " bytes" : std::string("?")) +
                                  ", more than the cache's limit of 1000 bytes (set by MHD_CACHE_MAX_MB); it is kept "
                                  "until another mesh is cached");
  EXPECT_TRUE(std::filesystem::is_regular_file(over->cache_file));  // kept, and used:
  EXPECT_EQ(small.load(mesh_file_, Eigen::Vector3d::Ones())->outcome, CacheOutcome::Hit);
  // Within the limit, nothing is said.
  MeshCache roomy(dir_ / "roomy");
  const Result<CachedMesh, MeshLoadError> fits = roomy.load(mesh_file_, Eigen::Vector3d::Ones());
  ASSERT_TRUE(fits.ok());
  EXPECT_TRUE(fits->written);
  EXPECT_EQ(fits->over_limit, "");
}

TEST_F(MeshCacheTest, ProcessesLoadingOneMeshAtOnceEachGetACorrectTreeAndLeaveOneWholeEntry) {
  // Four processes load the same (100 k-triangle) mesh into one empty cache folder at
  // once, so their writes overlap: each must answer like a fresh build, and what is left
  // is one entry that a later load uses.
  const auto file = dir_ / "shared.ply";
  test::write_binary_ply(file, make_uv_sphere_mesh(0.1, 160, 320));
  const auto answers_like_a_fresh_build = [&](const CachedMesh& loaded) {
    const MeshBvh fresh(loaded.bvh->mesh_ptr());
    for (const auto& box : random_boxes(fresh.bounds(), 50)) {
      if (query(*loaded.bvh, box) != query(fresh, box)) return false;
    }
    return true;
  };
  constexpr int kProcesses = 4;
  std::vector<pid_t> children;
  for (int i = 0; i < kProcesses; ++i) {
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      MeshCache cache(cache_dir_);
      const Result<CachedMesh, MeshLoadError> r = cache.load(file, Eigen::Vector3d::Ones());
      ::_exit(r.ok() && answers_like_a_fresh_build(*r) ? 0 : 1);
    }
    children.push_back(pid);
  }
  for (const pid_t pid : children) {
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "a process got no correct tree";
  }
  std::size_t entries = 0, temps = 0;
  for (const auto& item : std::filesystem::directory_iterator(cache_dir_)) {
    entries += item.path().extension() == ".mhdbvh" ? 1 : 0;
    temps += item.path().string().find(".tmp.") != std::string::npos ? 1 : 0;
  }
  EXPECT_EQ(entries, 1u);
  EXPECT_EQ(temps, 0u);
  MeshCache after(cache_dir_);
  const Result<CachedMesh, MeshLoadError> hit = after.load(file, Eigen::Vector3d::Ones());
  ASSERT_TRUE(hit.ok());
  EXPECT_EQ(hit->outcome, CacheOutcome::Hit) << hit->rejected_reason;
  EXPECT_TRUE(answers_like_a_fresh_build(*hit));
}

// Bytes of `file` mapped into this process (/proc/self/maps), 0 when it is not mapped.
std::uint64_t mapped_bytes_of(const std::filesystem::path& file) {
  std::ifstream maps("/proc/self/maps");
  std::uint64_t bytes = 0;
  const std::string name = file.string();
  for (std::string line; std::getline(maps, line);) {
    // The path is the line's last field, after a space.
    if (line.size() <= name.size() || !line.ends_with(name) || line[line.size() - name.size() - 1] != ' ') continue;
    const auto dash = line.find('-'), space = line.find(' ');
    bytes += std::stoull(line.substr(dash + 1, space - dash - 1), nullptr, 16) - std::stoull(line.substr(0, dash), nullptr, 16);
  }
  return bytes;
}

// Bytes of `file`'s mappings in this process that are resident (/proc/self/smaps, Rss).
std::uint64_t resident_bytes_of(const std::filesystem::path& file) {
  std::ifstream smaps("/proc/self/smaps");
  std::uint64_t bytes = 0;
  bool in_file = false;
  const std::string name = file.string();
  for (std::string line; std::getline(smaps, line);) {
    if (line.find('-') < line.find(' ') && std::isxdigit(static_cast<unsigned char>(line[0])) != 0) {
      in_file = line.size() > name.size() && line.ends_with(name) && line[line.size() - name.size() - 1] == ' ';
    } else if (in_file && line.starts_with("Rss:")) {
      bytes += std::stoull(line.substr(4)) * 1024;
    }
  }
  return bytes;
}

TEST_F(MeshCacheTest, AHitAdoptsTheTreeWhereItLiesInTheMappedEntryUntilTheMeshIsGone) {
  MeshCache cache(cache_dir_);
  const Result<CachedMesh, MeshLoadError> cold = cache.load(mesh_file_, Eigen::Vector3d::Ones());
  ASSERT_TRUE(cold.ok());
  EXPECT_EQ(mapped_bytes_of(cold->cache_file), 0u);  // a built tree is in memory of its own
  std::optional<Result<CachedMesh, MeshLoadError>> warm(cache.load(mesh_file_, Eigen::Vector3d::Ones()));
  ASSERT_TRUE(warm->ok());
  ASSERT_EQ((*warm)->outcome, CacheOutcome::Hit);
  EXPECT_GE(mapped_bytes_of(cold->cache_file), std::filesystem::file_size(cold->cache_file));
  // It answers as the built one, and an entry renamed over it (another writer) does not
  // disturb the mapped one.
  const MeshBvh fresh((*warm)->bvh->mesh_ptr());
  const auto box = fresh.bounds();
  EXPECT_EQ(query(*(*warm)->bvh, box), query(fresh, box));
  std::filesystem::copy_file(cold->cache_file, dir_ / "copy.mhdbvh");
  std::filesystem::rename(dir_ / "copy.mhdbvh", cold->cache_file);
  EXPECT_EQ(query(*(*warm)->bvh, box), query(fresh, box));
  warm.reset();
  EXPECT_EQ(mapped_bytes_of(cold->cache_file), 0u);
}

TEST_F(MeshCacheTest, TruncatedCacheFileIsRejectedAndRebuilt) {
  MeshCache cache(cache_dir_);
  const Result<CachedMesh, MeshLoadError> cold = cache.load(mesh_file_, Eigen::Vector3d::Ones());
  ASSERT_TRUE(cold.ok());
  const auto bytes = read_bytes(cold->cache_file);
  ASSERT_GT(bytes.size(), 200u);
  for (const std::size_t keep : {bytes.size() - 1, bytes.size() / 2, std::size_t{100}, std::size_t{0}}) {
    SCOPED_TRACE(keep);
    write_bytes(cold->cache_file, std::vector<char>(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(keep)));
    const Result<CachedMesh, MeshLoadError> again = cache.load(mesh_file_, Eigen::Vector3d::Ones());
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again->outcome, CacheOutcome::Rejected);
    EXPECT_FALSE(again->rejected_reason.empty());
    EXPECT_TRUE(again->written);
    EXPECT_EQ(again->mesh().triangles, cold->mesh().triangles);
    // Rebuilt: the same size (Bullet's in-place image holds pointer values, so the
    // bytes may differ) and valid.
    EXPECT_EQ(std::filesystem::file_size(cold->cache_file), bytes.size());
    EXPECT_EQ(cache.load(mesh_file_, Eigen::Vector3d::Ones())->outcome, CacheOutcome::Hit);
  }
}

TEST_F(MeshCacheTest, FlippedBytesAreRejectedAndRebuilt) {
  MeshCache cache(cache_dir_);
  const Result<CachedMesh, MeshLoadError> cold = cache.load(mesh_file_, Eigen::Vector3d::Ones());
  ASSERT_TRUE(cold.ok());
  const auto bytes = read_bytes(cold->cache_file);
  mesh_cache_entry::FileHeader h;
  std::memcpy(&h, bytes.data(), sizeof h);
  const auto layout = mesh_cache_entry::layout_for(h.vertex_count, h.triangle_count, h.normal_count, h.bvh_bytes,
                                                   h.source_bytes, bytes.size());
  ASSERT_TRUE(layout.has_value());
  // Header fields, vertices, triangles, normals, the tree's head (which its adoption
  // writes while the checksum is read: the checksum reads the file's) and its first node,
  // and the BVH at the very end.
  const std::size_t head = layout->bvh, head_end = layout->bvh + MeshBvh::kSerializedHeadBytes;
  const std::vector<std::size_t> flipped{0, 20, 60, 127, 128, bytes.size() / 4, bytes.size() / 2, head, head + 8,
                                        head_end - 1, head_end, bytes.size() * 3 / 4, bytes.size() - 1};
  for (const std::size_t at : flipped) {
    SCOPED_TRACE(at);
    auto bad = bytes;
    bad[at] = static_cast<char>(bad[at] ^ 0x10);
    write_bytes(cold->cache_file, bad);
    const Result<CachedMesh, MeshLoadError> again = cache.load(mesh_file_, Eigen::Vector3d::Ones());
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again->outcome, CacheOutcome::Rejected);
    // Past the header, the checksum names it, wherever the byte lies: it is judged before
    // the mesh's own checks speak and before the tree is adopted.
    if (at >= sizeof(mesh_cache_entry::FileHeader)) {
      EXPECT_EQ(again->rejected_reason, "payload checksum mismatch");
    }
    EXPECT_EQ(again->mesh().vertices_m, cold->mesh().vertices_m);
    EXPECT_TRUE(again->written);
    EXPECT_EQ(std::filesystem::file_size(cold->cache_file), bytes.size());
  }
  EXPECT_EQ(cache.stats().rejected, flipped.size());
  EXPECT_EQ(cache.load(mesh_file_, Eigen::Vector3d::Ones())->outcome, CacheOutcome::Hit);
}

TEST_F(MeshCacheTest, CacheFileOfAnotherKeyIsRejected) {
  MeshCache cache(cache_dir_);
  const Result<CachedMesh, MeshLoadError> a = cache.load(mesh_file_, Eigen::Vector3d::Ones());
  const Result<CachedMesh, MeshLoadError> b = cache.load(mesh_file_, Eigen::Vector3d::Constant(2.0));
  ASSERT_TRUE(a.ok() && b.ok());
  std::filesystem::copy_file(a->cache_file, b->cache_file, std::filesystem::copy_options::overwrite_existing);
  const Result<CachedMesh, MeshLoadError> again = cache.load(mesh_file_, Eigen::Vector3d::Constant(2.0));
  EXPECT_EQ(again->outcome, CacheOutcome::Rejected);
  EXPECT_EQ(again->rejected_reason, "key mismatch");
  EXPECT_NEAR(mesh_bounds(again->mesh()).max().x(), 0.08, 1e-6);
}

TEST_F(MeshCacheTest, ScaleAndContentChangeTheKey) {
  const auto k1 = mesh_cache_key(mesh_file_, Eigen::Vector3d::Ones());
  const auto k1_again = mesh_cache_key(mesh_file_, Eigen::Vector3d::Ones());
  const auto k_mm = mesh_cache_key(mesh_file_, Eigen::Vector3d::Constant(0.001));
  const auto k_axis = mesh_cache_key(mesh_file_, Eigen::Vector3d(1, 1, -1));
  ASSERT_TRUE(k1 && k1_again && k_mm && k_axis);
  EXPECT_EQ(*k1, *k1_again);
  EXPECT_NE(*k1, *k_mm);
  EXPECT_NE(*k1, *k_axis);
  EXPECT_EQ(k1->hex().size(), 32u);
  EXPECT_EQ(k1->hex().find_first_not_of("0123456789abcdef"), std::string::npos);

  MeshCache cache(cache_dir_);
  const Result<CachedMesh, MeshLoadError> m1 = cache.load(mesh_file_, Eigen::Vector3d::Ones());
  const Result<CachedMesh, MeshLoadError> mm = cache.load(mesh_file_, Eigen::Vector3d::Constant(0.001));
  EXPECT_EQ(m1->outcome, CacheOutcome::Miss);
  EXPECT_EQ(mm->outcome, CacheOutcome::Miss);
  EXPECT_NE(m1->cache_file, mm->cache_file);
  EXPECT_EQ(m1->cache_file, cache.file_for(*k1));
  EXPECT_EQ(mm->cache_file, cache.file_for(*k_mm));
  EXPECT_NEAR(mesh_bounds(mm->mesh()).max().x(), 0.04e-3, 1e-9);

  // New content under the same name: a new key, never the old entry.
  test::write_binary_ply(mesh_file_, make_sphere_mesh(0.04, 3));
  const auto k2 = mesh_cache_key(mesh_file_, Eigen::Vector3d::Ones());
  ASSERT_TRUE(k2);
  EXPECT_NE(*k1, *k2);
  const Result<CachedMesh, MeshLoadError> changed = cache.load(mesh_file_, Eigen::Vector3d::Ones());
  EXPECT_EQ(changed->outcome, CacheOutcome::Miss);
  EXPECT_EQ(changed->mesh().triangle_count(), 1280u);
}

TEST_F(MeshCacheTest, DisabledCacheStillLoads) {
  MeshCache cache(std::nullopt);
  EXPECT_FALSE(cache.writable());
  const Result<CachedMesh, MeshLoadError> r = cache.load(mesh_file_, Eigen::Vector3d::Ones());
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->outcome, CacheOutcome::Disabled);
  EXPECT_EQ(r->mesh().triangle_count(), 5120u);
  EXPECT_FALSE(std::filesystem::exists(cache_dir_));
}

TEST_F(MeshCacheTest, UnusableCacheFolderFallsBackToLoading) {
  // A regular file where the folder should be: it can be neither created nor written.
  test::write_text(dir_ / "blocker", "x");
  MeshCache cache(dir_ / "blocker" / "cache");
  EXPECT_FALSE(cache.writable());
  const Result<CachedMesh, MeshLoadError> r = cache.load(mesh_file_, Eigen::Vector3d::Ones());
  ASSERT_TRUE(r.ok());
  EXPECT_FALSE(r->written);
  EXPECT_EQ(cache.load(mesh_file_, Eigen::Vector3d::Ones())->outcome, CacheOutcome::Miss);
}

TEST_F(MeshCacheTest, LoadErrorsPassThrough) {
  MeshCache cache(cache_dir_);
  const Result<CachedMesh, MeshLoadError> r = cache.load(dir_ / "missing.stl", Eigen::Vector3d::Ones());
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().reason, "file not found");
  EXPECT_EQ(cache.stats().writes, 0u);
}

TEST_F(MeshCacheTest, AHeaderOverMaxTrianglesIsRefusedBeforeTheFileIsHashed) {
  // The key hashes every byte of the file: a header that refuses the mesh must do so
  // first, or a huge file costs its whole read before the refusal.
  MeshCache cache(cache_dir_);
  const Result<CachedMesh, MeshLoadError> refused =
      cache.load(mesh_file_, Eigen::Vector3d::Ones(), {}, TriangleBudget{5119});
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().reason, "the header claims 5120 faces, more than max_triangles (5119)");
  EXPECT_EQ(cache.stats().keys_hashed, 0u);
  // The dual: a header within the limit is hashed and loaded.
  const Result<CachedMesh, MeshLoadError> loaded =
      cache.load(mesh_file_, Eigen::Vector3d::Ones(), {}, TriangleBudget{5120});
  ASSERT_TRUE(loaded.ok()) << loaded.error_text();
  EXPECT_EQ(cache.stats().keys_hashed, 1u);
}

TEST_F(MeshCacheTest, MemoryForTheCachedMeshIsCheckedBeforeHashingAndForABuildBeforeBuilding) {
  constexpr std::uint64_t kFaces = 5120;
  const std::uint64_t cached = kFaces * TriangleBudget::kCachedBytesPerTriangle;
  const std::uint64_t built = kFaces * TriangleBudget::kLoadBytesPerTriangle;
  ASSERT_LT(cached, built);
  {  // Too little even for the cached mesh: refused from the header, nothing hashed.
    MeshCache cache(cache_dir_);
    const Result<CachedMesh, MeshLoadError> r =
        cache.load(mesh_file_, Eigen::Vector3d::Ones(), {}, TriangleBudget{kFaces, 0, cached - 1});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().reason, "the header claims 5120 faces, about " + std::to_string(cached) +
                                    " bytes to load, more than the " + std::to_string(cached - 1) +
                                    " bytes of memory available");
    EXPECT_EQ(cache.stats().keys_hashed, 0u);
  }
  {  // Enough for the cached mesh but not for a build, and no entry: refused before building.
    MeshCache cache(cache_dir_);
    const Result<CachedMesh, MeshLoadError> r =
        cache.load(mesh_file_, Eigen::Vector3d::Ones(), {}, TriangleBudget{kFaces, 0, built - 1});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().reason, "the header claims 5120 faces, about " + std::to_string(built) +
                                    " bytes to load, more than the " + std::to_string(built - 1) +
                                    " bytes of memory available");
    EXPECT_EQ(cache.stats().writes, 0u);
  }
  {  // With the entry written, the same memory holds the cached mesh: a hit.
    MeshCache cache(cache_dir_);
    ASSERT_TRUE(cache.load(mesh_file_, Eigen::Vector3d::Ones()).ok());
    const Result<CachedMesh, MeshLoadError> r =
        cache.load(mesh_file_, Eigen::Vector3d::Ones(), {}, TriangleBudget{kFaces, 0, cached});
    ASSERT_TRUE(r.ok()) << r.error_text();
    EXPECT_EQ(r->outcome, CacheOutcome::Hit);
  }
}

TEST_F(MeshCacheTest, LargeMeshesReportProgress) {
  // 2 * 320 * 159 = 101760 triangles: over the progress threshold.
  const auto big_file = dir_ / "big.ply";
  test::write_binary_ply(big_file, make_uv_sphere_mesh(0.1, 160, 320));
  MeshCache cache(cache_dir_);
  std::vector<std::pair<std::string, double>> calls;
  auto record = [&](std::string_view what, double f) { calls.emplace_back(std::string(what), f); };

  const Result<CachedMesh, MeshLoadError> cold = cache.load(big_file, Eigen::Vector3d::Ones(), record);
  ASSERT_TRUE(cold.ok());
  ASSERT_GE(cold->mesh().triangle_count(), kProgressMinTriangles);
  auto saw = [&](std::string_view prefix, double f) {
    return std::any_of(calls.begin(), calls.end(), [&](const auto& c) { return c.first.starts_with(prefix) && c.second == f; });
  };
  EXPECT_TRUE(saw("building BVH of big.ply", 0.0));
  EXPECT_TRUE(saw("building BVH of big.ply", 1.0));
  EXPECT_TRUE(saw("reading big.ply", 1.0));
  // Writing the entry is a step of its own (seconds at 100 M triangles), after the build's
  // end, its fractions rising to the end.
  ASSERT_TRUE(cold->written);
  EXPECT_TRUE(saw("writing cached BVH of big.ply", 0.0));
  EXPECT_TRUE(saw("writing cached BVH of big.ply", 1.0));
  const auto built = std::find_if(calls.begin(), calls.end(), [](const auto& c) {
    return c.first.starts_with("building BVH of big.ply") && c.second == 1.0;
  });
  const auto writing = std::find_if(calls.begin(), calls.end(),
                                    [](const auto& c) { return c.first.starts_with("writing cached BVH of big.ply"); });
  EXPECT_LT(built, writing);
  double last = 0.0;
  for (const auto& c : calls) {
    EXPECT_GE(c.second, 0.0);
    EXPECT_LE(c.second, 1.0);
    if (!c.first.starts_with("writing cached BVH")) continue;
    EXPECT_GE(c.second, last);
    last = c.second;
  }

  calls.clear();
  const Result<CachedMesh, MeshLoadError> warm = cache.load(big_file, Eigen::Vector3d::Ones(), record);
  EXPECT_EQ(warm->outcome, CacheOutcome::Hit);
  EXPECT_TRUE(saw("reading cached BVH of big.ply", 0.0));
  EXPECT_TRUE(saw("reading cached BVH of big.ply", 1.0));
  EXPECT_FALSE(saw("writing cached BVH of big.ply", 0.0));  // a hit writes nothing

  // A small mesh stays quiet.
  calls.clear();
  ASSERT_TRUE(cache.load(mesh_file_, Eigen::Vector3d::Ones(), record).ok());
  EXPECT_TRUE(calls.empty());
}

TEST_F(MeshCacheTest, AMeshPastOneBulletPartRoundTripsInLeafOrderAndIsTouchedWhereItsLastTrianglesAre) {
  // Past 2^21 triangles a tree spans several Bullet parts: its cache entry is kept and
  // used, not rejected and rebuilt on every load, and the adopted tree finds the last
  // triangles (the only ones in the box below) as the built one does. Once checked, the
  // entry's pages leave memory, and come back where the tree is walked.
  const auto file = dir_ / "past_one_part.ply";
  test::write_binary_ply(file, *test::mesh_past_one_bullet_part());
  MeshCache cache(cache_dir_);
  cache.set_limit_bytes(std::uint64_t{1} << 30);
  // Its tree is built in pieces, whose progress the build step tells as it goes.
  std::vector<double> building;
  const auto record = [&](std::string_view what, double f) {
    if (what.starts_with("building BVH of past_one_part.ply")) building.push_back(f);
  };
  const Result<CachedMesh, MeshLoadError> cold = cache.load(file, Eigen::Vector3d::Ones(), record);
  ASSERT_TRUE(cold.ok()) << cold.error_text();
  ASSERT_GT(cold->mesh().triangle_count(), std::size_t{1} << 21);
  EXPECT_EQ(cold->outcome, CacheOutcome::Miss);
  ASSERT_TRUE(cold->written);
  ASSERT_GE(building.size(), 3u);
  EXPECT_EQ(building.front(), 0.0);
  EXPECT_EQ(building.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(building.begin(), building.end()));
  EXPECT_EQ(std::count(building.begin(), building.end(), 1.0), 1) << "the end told once";
  EXPECT_TRUE(std::any_of(building.begin(), building.end(), [](double f) { return f > 0.5 && f < 1.0; }));
  const Result<CachedMesh, MeshLoadError> warm = cache.load(file, Eigen::Vector3d::Ones());
  ASSERT_TRUE(warm.ok()) << warm.error_text();
  ASSERT_EQ(warm->outcome, CacheOutcome::Hit) << warm->rejected_reason;
  // The mesh's arrays and its face normals are the entry's own pages, not a copy; the
  // tree's pages leave the process once checked: they are mapped, not resident.
  const TriangleMesh& adopted = warm->mesh();
  EXPECT_TRUE(adopted.vertices_m.get_allocator().adopted());
  EXPECT_TRUE(adopted.triangles.get_allocator().adopted());
  EXPECT_TRUE(adopted.vertex_normals.get_allocator().adopted());
  EXPECT_FALSE(cold->mesh().vertices_m.get_allocator().adopted());
  const std::uint64_t entry_bytes = std::filesystem::file_size(warm->cache_file);
  const std::uint64_t mesh_bytes = 2 * adopted.vertices_m.size() * sizeof(Eigen::Vector3d) +
                                   adopted.triangles.size() * (sizeof(TriangleIndices) + sizeof(Eigen::Vector3d));
  ASSERT_GE(mapped_bytes_of(warm->cache_file), entry_bytes);
  const std::uint64_t after_load = resident_bytes_of(warm->cache_file);
  EXPECT_LT(after_load, mesh_bytes + (entry_bytes - mesh_bytes) / 10) << "of " << entry_bytes << " bytes mapped";
  EXPECT_EQ(warm->mesh().triangles, cold->mesh().triangles);
  // Built in pieces, the mesh is kept in its leaves' order: leaf k names triangle k, past
  // 2^21 too.
  std::uint32_t next = 0;
  bool in_leaf_order = true;
  warm->bvh->for_each_triangle_overlapping(warm->bvh->bounds(),
                                           [&](std::uint32_t t) { in_leaf_order = in_leaf_order && t == next++; });
  EXPECT_TRUE(in_leaf_order);
  const auto on_patch = [&](std::uint32_t t) {
    const TriangleMesh& m = warm->mesh();
    return m.vertices_m[m.triangles[t][0]].z() == 0.5 && m.vertices_m[m.triangles[t][1]].z() == 0.5 &&
           m.vertices_m[m.triangles[t][2]].z() == 0.5;
  };
  const Eigen::AlignedBox3d patch(Eigen::Vector3d(0.45, 0.45, 0.4), Eigen::Vector3d(0.55, 0.55, 0.6));
  const auto must = brute_force(warm->mesh(), patch);
  ASSERT_FALSE(must.empty());
  EXPECT_TRUE(std::all_of(must.begin(), must.end(), on_patch));
  const auto from_cache = query(*warm->bvh, patch);
  EXPECT_EQ(from_cache, query(*cold->bvh, patch));
  EXPECT_TRUE(std::includes(from_cache.begin(), from_cache.end(), must.begin(), must.end()));
  EXPECT_TRUE(std::all_of(from_cache.begin(), from_cache.end(), on_patch)) << "a leaf names a triangle far from its box";
  // The last triangles, wherever they lie, are found there.
  for (std::uint32_t t = static_cast<std::uint32_t>(warm->mesh().triangle_count()) - 64;
       t < warm->mesh().triangle_count(); ++t) {
    Eigen::AlignedBox3d own;
    for (const auto v : warm->mesh().triangles[t]) own.extend(warm->mesh().vertices_m[v]);
    const auto found = query(*warm->bvh, own);
    ASSERT_TRUE(std::binary_search(found.begin(), found.end(), t)) << "triangle " << t;
  }
  // Walks bring back the pages they read, and answer as the built tree everywhere.
  for (const auto& box : random_boxes(mesh_bounds(warm->mesh()), 200)) {
    ASSERT_EQ(query(*warm->bvh, box), query(*cold->bvh, box));
  }
  EXPECT_EQ(query(*warm->bvh, warm->bvh->bounds()).size(), warm->mesh().triangle_count());
  EXPECT_GT(resident_bytes_of(warm->cache_file), after_load);
}

TEST_F(MeshCacheTest, AMeshLargeEnoughForTwoThreadsLoadsFromTheCacheAsBuilt) {
  // Just over 2^20 triangles and tree nodes: the face normals and the tree's check run on
  // two threads, beside the checksum's thread (the threads ThreadSanitizer watches here).
  constexpr int kQuads = 725;  // 725^2 quads, 1,051,250 triangles
  const auto mesh = std::make_shared<TriangleMesh>();
  for (int j = 0; j <= kQuads; ++j) {
    for (int i = 0; i <= kQuads; ++i) {
      mesh->vertices_m.emplace_back(double(i) / kQuads, double(j) / kQuads, 0.01 * std::sin(i * 0.1 + j * 0.07));
    }
  }
  const auto id = [](int i, int j) { return static_cast<std::uint32_t>(j * (kQuads + 1) + i); };
  for (int j = 0; j < kQuads; ++j) {
    for (int i = 0; i < kQuads; ++i) {
      mesh->triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh->triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  ASSERT_GT(mesh->triangle_count(), std::size_t{1} << 20);
  const auto file = dir_ / "two_threads.ply";
  test::write_binary_ply(file, *mesh);
  MeshCache cache(cache_dir_);
  cache.set_limit_bytes(std::uint64_t{1} << 30);
  const Result<CachedMesh, MeshLoadError> cold = cache.load(file, Eigen::Vector3d::Ones());
  ASSERT_TRUE(cold.ok()) << cold.error_text();
  const Result<CachedMesh, MeshLoadError> warm = cache.load(file, Eigen::Vector3d::Ones());
  ASSERT_TRUE(warm.ok()) << warm.error_text();
  ASSERT_EQ(warm->outcome, CacheOutcome::Hit) << warm->rejected_reason;
  EXPECT_EQ(warm->mesh().triangles, cold->mesh().triangles);
  for (std::uint32_t t = 0; t < warm->mesh().triangle_count(); t += 997) {
    ASSERT_EQ(warm->bvh->face_normal_O(t), cold->bvh->face_normal_O(t)) << t;
  }
  const std::uint32_t last = static_cast<std::uint32_t>(warm->mesh().triangle_count() - 1);
  EXPECT_EQ(warm->bvh->face_normal_O(last), cold->bvh->face_normal_O(last));
  for (const auto& box : random_boxes(mesh_bounds(warm->mesh()), 40)) {
    ASSERT_EQ(query(*warm->bvh, box), query(*cold->bvh, box));
  }
}

/// An entry's checksums say only that the bytes are the ones written, not that a careful
/// writer wrote them: a tree that names a triangle twice, or skips one, or whose escape
/// indices lead out of it, must be refused even when the entry is sealed.
class HostileTreeTest : public MeshCacheTest {
 protected:
  /// The cold entry with `edit` applied to its bytes, then sealed: the load must reject it
  /// and rebuild a correct tree.
  void expect_rejected_entry(const std::function<void(std::vector<char>&, const mesh_cache_entry::Layout&,
                                                      const CachedMesh&)>& edit) {
    MeshCache cache(cache_dir_);
    const Result<CachedMesh, MeshLoadError> cold = cache.load(mesh_file_, Eigen::Vector3d::Ones());
    ASSERT_TRUE(cold.ok());
    auto bytes = read_bytes(cold->cache_file);
    mesh_cache_entry::FileHeader h;
    std::memcpy(&h, bytes.data(), sizeof h);
    const auto layout = mesh_cache_entry::layout_for(h.vertex_count, h.triangle_count, h.normal_count, h.bvh_bytes,
                                                     h.source_bytes, bytes.size());
    ASSERT_TRUE(layout.has_value());
    edit(bytes, *layout, *cold);
    if (::testing::Test::HasFatalFailure()) return;
    mesh_cache_entry::seal(std::as_writable_bytes(std::span(bytes)));
    write_bytes(cold->cache_file, bytes);

    const Result<CachedMesh, MeshLoadError> again = cache.load(mesh_file_, Eigen::Vector3d::Ones());
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again->outcome, CacheOutcome::Rejected);
    EXPECT_NE(again->rejected_reason.find("BVH"), std::string::npos) << again->rejected_reason;
    EXPECT_EQ(again->mesh().vertices_m, cold->mesh().vertices_m);
    for (const auto& box : random_boxes(mesh_bounds(again->mesh()), 50)) {
      const auto found = query(*again->bvh, box);
      const auto must = brute_force(again->mesh(), box);
      EXPECT_TRUE(std::includes(found.begin(), found.end(), must.begin(), must.end()));
    }
  }

  /// The cold entry with `edit` applied to its tree's nodes (Bullet's array, in the
  /// entry's bytes), then sealed: as expect_rejected_entry.
  void expect_rejected(const std::function<void(std::span<btQuantizedBvhNode>)>& edit) {
    expect_rejected_entry([&](std::vector<char>& bytes, const mesh_cache_entry::Layout& layout, const CachedMesh& cold) {
      // The node array lies in the tree's section exactly as the built tree holds it;
      // Bullet sizes the built array 2n, the entry holds the root's span.
      auto& built = const_cast<btBvhTriangleMeshShape&>(cold.bvh->shape()).getOptimizedBvh()->getQuantizedNodeArray();  // NOLINT
      const auto node_count = static_cast<std::size_t>(built[0].isLeafNode() ? 1 : built[0].getEscapeIndex());
      const auto* first = reinterpret_cast<const char*>(&built[0]);
      const std::size_t node_bytes = node_count * sizeof(btQuantizedBvhNode);
      const auto tree_begin = bytes.begin() + static_cast<std::ptrdiff_t>(layout.bvh);
      const auto tree_end = bytes.begin() + static_cast<std::ptrdiff_t>(layout.source);
      const auto at = std::search(tree_begin, tree_end, first, first + node_bytes);
      ASSERT_NE(at, tree_end) << "the nodes are in the entry";
      std::vector<btQuantizedBvhNode> nodes(node_count);
      std::memcpy(static_cast<void*>(nodes.data()), &*at, node_bytes);
      edit(nodes);
      std::memcpy(&*at, nodes.data(), node_bytes);
    });
  }
  /// Index of the first leaf of `nodes` from `from` on.
  static std::size_t leaf_from(std::span<const btQuantizedBvhNode> nodes, std::size_t from) {
    while (!nodes[from].isLeafNode()) ++from;
    return from;
  }
};

TEST_F(HostileTreeTest, ALeafNamingAnotherLeafsTriangleIsRejected) {
  // Far from the triangles the spot check samples: only a check of every leaf sees it.
  expect_rejected([](std::span<btQuantizedBvhNode> nodes) {
    const std::size_t a = leaf_from(nodes, nodes.size() / 2 + 7);
    const std::size_t b = leaf_from(nodes, a + 1);
    nodes[a].m_escapeIndexOrTriangleIndex = nodes[b].m_escapeIndexOrTriangleIndex;
  });
}

TEST_F(HostileTreeTest, AnEscapeIndexPastItsParentIsRejected) {
  expect_rejected([](std::span<btQuantizedBvhNode> nodes) {
    std::size_t inner = nodes.size() / 2;
    while (nodes[inner].isLeafNode()) ++inner;
    nodes[inner].m_escapeIndexOrTriangleIndex -= 2;  // stored negated: two nodes further
  });
}

TEST_F(HostileTreeTest, AVertexMovedOutOfItsTrianglesBoxesIsRejected) {
  // The sphere is symmetric: a vertex moved to its opposite keeps the mesh's bounds, and
  // its triangles now cross the sphere, far outside their leaves' boxes. Their face
  // normals are written as the moved corners give them, so only the boxes tell.
  expect_rejected_entry([](std::vector<char>& bytes, const mesh_cache_entry::Layout& layout, const CachedMesh& cold) {
    TriangleMesh moved = cold.mesh();
    const std::size_t vertex = moved.vertices_m.size() / 2 + 3;
    moved.vertices_m[vertex] = -moved.vertices_m[vertex];
    std::memcpy(bytes.data() + layout.vertices + vertex * sizeof(Eigen::Vector3d), moved.vertices_m[vertex].data(),
                sizeof(Eigen::Vector3d));
    for (std::size_t t = 0; t < moved.triangles.size(); ++t) {
      const auto& c = moved.triangles[t];
      if (c[0] != vertex && c[1] != vertex && c[2] != vertex) continue;
      const Eigen::Vector3d n = unit_face_normal(moved.vertices_m[c[0]], moved.vertices_m[c[1]], moved.vertices_m[c[2]]);
      std::memcpy(bytes.data() + layout.face_normals + t * sizeof(Eigen::Vector3d), n.data(), sizeof n);
    }
  });
}

TEST_F(HostileTreeTest, AFaceNormalTurnedIsRejected) {
  // A sweep trusts a triangle's face normal for its side: one turned away from its
  // corners' is refused, though the tree and the checksum hold.
  expect_rejected_entry([](std::vector<char>& bytes, const mesh_cache_entry::Layout& layout, const CachedMesh& cold) {
    const std::size_t t = cold.mesh().triangles.size() / 2 + 5;
    char* at = bytes.data() + layout.face_normals + t * sizeof(Eigen::Vector3d);
    Eigen::Vector3d n;
    std::memcpy(n.data(), at, sizeof n);
    ASSERT_NEAR(n.norm(), 1.0, 1e-12);
    n = -n;
    std::memcpy(at, n.data(), sizeof n);
  });
}

// The face normal's tolerance from both sides: a stored normal turned, or lengthened, by
// four times MeshBvh::kFaceNormalTolerance is refused; by a tenth of it, kept as stored.
TEST_F(HostileTreeTest, AFaceNormalIsKeptWithinItsToleranceAndRefusedPastIt) {
  const auto edited = [](const Eigen::Vector3d& n, bool turn, double by) -> Eigen::Vector3d {
    if (!turn) return (1.0 + by) * n;
    return std::cos(by) * n + std::sin(by) * n.unitOrthogonal();
  };
  const auto normal_at = [](const std::vector<char>& bytes, std::size_t offset) {
    Eigen::Vector3d n;
    std::memcpy(n.data(), bytes.data() + offset, sizeof n);
    return n;
  };
  for (const bool turn : {true, false}) {
    SCOPED_TRACE(turn ? "turned" : "lengthened");
    std::filesystem::remove_all(cache_dir_);  // each case from a cold load
    expect_rejected_entry([&](std::vector<char>& bytes, const mesh_cache_entry::Layout& layout, const CachedMesh& cold) {
      const std::size_t at = layout.face_normals + (cold.mesh().triangles.size() / 2 + 5) * sizeof(Eigen::Vector3d);
      const Eigen::Vector3d n = edited(normal_at(bytes, at), turn, 4.0 * MeshBvh::kFaceNormalTolerance);
      std::memcpy(bytes.data() + at, n.data(), sizeof n);
    });
    // The dual: a tenth of the tolerance is kept, and the sweeps get the stored normal.
    MeshCache cache(cache_dir_);
    std::filesystem::path entry;
    std::size_t t = 0;
    {
      // Let go before the entry is rewritten: a hit maps it.
      const Result<CachedMesh, MeshLoadError> cold = cache.load(mesh_file_, Eigen::Vector3d::Ones());
      ASSERT_TRUE(cold.ok());
      entry = cold->cache_file;
      t = cold->mesh().triangles.size() / 2 + 5;
    }
    auto bytes = read_bytes(entry);
    mesh_cache_entry::FileHeader h;
    std::memcpy(&h, bytes.data(), sizeof h);
    const auto layout = mesh_cache_entry::layout_for(h.vertex_count, h.triangle_count, h.normal_count, h.bvh_bytes,
                                                     h.source_bytes, bytes.size());
    ASSERT_TRUE(layout.has_value());
    const std::size_t at = layout->face_normals + t * sizeof(Eigen::Vector3d);
    const Eigen::Vector3d n = edited(normal_at(bytes, at), turn, 0.1 * MeshBvh::kFaceNormalTolerance);
    ASSERT_NE(n, normal_at(bytes, at));
    std::memcpy(bytes.data() + at, n.data(), sizeof n);
    mesh_cache_entry::seal(std::as_writable_bytes(std::span(bytes)));
    write_bytes(entry, bytes);
    const Result<CachedMesh, MeshLoadError> again = cache.load(mesh_file_, Eigen::Vector3d::Ones());
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again->outcome, CacheOutcome::Hit) << again->rejected_reason;
    EXPECT_EQ(again->bvh->face_normal_O(static_cast<std::uint32_t>(t)), n);
  }
}

/// Writes `value` over the `index`th element of the entry's section at `offset`.
template <class T>
void overwrite(std::vector<char>& bytes, std::size_t offset, std::size_t index, const T& value) {
  std::memcpy(bytes.data() + offset + index * sizeof(T), &value, sizeof(T));
}

TEST_F(HostileTreeTest, ATriangleCornerOutOfRangeIsRejected) {
  expect_rejected_entry([](std::vector<char>& bytes, const mesh_cache_entry::Layout& layout, const CachedMesh& cold) {
    TriangleIndices t = cold.mesh().triangles[cold.mesh().triangles.size() / 3];
    t[2] = static_cast<std::uint32_t>(cold.mesh().vertices_m.size());
    overwrite(bytes, layout.triangles, cold.mesh().triangles.size() / 3, t);
  });
}

TEST_F(HostileTreeTest, ATriangleWithARepeatedCornerIsRejected) {
  // Its face normal written as the corners give it (none) and its box still holding it:
  // only the corners' own check sees it.
  expect_rejected_entry([](std::vector<char>& bytes, const mesh_cache_entry::Layout& layout, const CachedMesh& cold) {
    const std::size_t k = cold.mesh().triangles.size() / 2 + 9;
    TriangleIndices t = cold.mesh().triangles[k];
    t[1] = t[0];
    overwrite(bytes, layout.triangles, k, t);
    overwrite(bytes, layout.face_normals, k, Eigen::Vector3d::Zero().eval());
  });
}

TEST_F(HostileTreeTest, ANonFiniteVertexIsRejected) {
  expect_rejected_entry([](std::vector<char>& bytes, const mesh_cache_entry::Layout& layout, const CachedMesh& cold) {
    overwrite(bytes, layout.vertices, cold.mesh().vertices_m.size() - 2,
              Eigen::Vector3d(0.0, std::numeric_limits<double>::quiet_NaN(), 0.0));
  });
}

TEST_F(HostileTreeTest, ANonFiniteVertexNormalIsRejected) {
  // Only shading reads it, and a force shaded by it would not be finite.
  expect_rejected_entry([](std::vector<char>& bytes, const mesh_cache_entry::Layout& layout, const CachedMesh& cold) {
    overwrite(bytes, layout.normals, cold.mesh().vertices_m.size() / 2,
              Eigen::Vector3f(std::numeric_limits<float>::infinity(), 0.0F, 0.0F));
  });
}

TEST_F(HostileTreeTest, ALeafBoxShrunkOffItsTriangleIsRejected) {
  expect_rejected([](std::span<btQuantizedBvhNode> nodes) {
    btQuantizedBvhNode& leaf = nodes[leaf_from(nodes, nodes.size() / 2 + 11)];
    leaf.m_quantizedAabbMax[0] = leaf.m_quantizedAabbMin[0];
  });
}

TEST_F(HostileTreeTest, TheSmallestEscapeIndexIsRejected) {
  expect_rejected([](std::span<btQuantizedBvhNode> nodes) { nodes[0].m_escapeIndexOrTriangleIndex = INT_MIN; });
}

TEST_F(HostileTreeTest, AnInnerNodeTurnedLeafIsRejected) {
  expect_rejected([](std::span<btQuantizedBvhNode> nodes) {
    std::size_t inner = nodes.size() / 3;
    while (nodes[inner].isLeafNode()) ++inner;
    nodes[inner].m_escapeIndexOrTriangleIndex = 0;
  });
}

/// Sets an environment variable for the scope (nullptr unsets it).
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value != nullptr) {
      ::setenv(name, value, 1);
    } else {
      ::unsetenv(name);
    }
  }
  ~ScopedEnv() {
    if (old_) {
      ::setenv(name_, old_->c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(MeshCacheDir, EnvironmentOrder) {
  {
    ScopedEnv a("MHD_CACHE_DIR", "/tmp/mhd-a");
    ScopedEnv b("XDG_CACHE_HOME", "/tmp/xdg");
    ScopedEnv c("HOME", "/home/someone");
    EXPECT_EQ(default_mesh_cache_dir(), std::filesystem::path("/tmp/mhd-a"));
  }
  {
    ScopedEnv a("MHD_CACHE_DIR", "");
    ScopedEnv b("XDG_CACHE_HOME", "/tmp/xdg");
    ScopedEnv c("HOME", "/home/someone");
    EXPECT_EQ(default_mesh_cache_dir(), std::filesystem::path("/tmp/xdg/mhd"));
  }
  {
    ScopedEnv a("MHD_CACHE_DIR", nullptr);
    ScopedEnv b("XDG_CACHE_HOME", "relative/path");  // not absolute: ignored per XDG spec
    ScopedEnv c("HOME", "/home/someone");
    EXPECT_EQ(default_mesh_cache_dir(), std::filesystem::path("/home/someone/.cache/mhd"));
  }
  {
    ScopedEnv a("MHD_CACHE_DIR", nullptr);
    ScopedEnv b("XDG_CACHE_HOME", nullptr);
    ScopedEnv c("HOME", nullptr);
    EXPECT_EQ(default_mesh_cache_dir(), std::nullopt);
  }
}

}  // namespace
}  // namespace mhd
