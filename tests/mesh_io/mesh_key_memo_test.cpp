// A cached load of a settled, unchanged mesh file takes its key from the file's memo; any
// change to the file, even one that keeps its size and modification time, is keyed from
// its contents again, and a memo that fails its check is never used.
#include "mesh_io/mesh_key_memo.h"

#include "mesh_io/mesh_cache.h"
#include "mesh_io/mesh_cache_eviction.h"

#include "sphere_cache_fixture.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

namespace mhd::mesh_key_memo_test {

namespace fs = std::filesystem;
using test::read_bytes;
using test::write_bytes;

// A memo is written only for a file unchanged for kMeshKeySettle_s.
void let_settle() { std::this_thread::sleep_for(std::chrono::duration<double>(kMeshKeySettle_s + 0.1)); }

std::vector<fs::path> memos_in(const fs::path& dir) {
  std::vector<fs::path> memos;
  for (const auto& item : fs::directory_iterator(dir)) {
    if (item.path().extension() == kMeshKeyMemoExtension) memos.push_back(item.path());
  }
  return memos;
}

class MeshKeyMemoTest : public test::SphereCacheFixture {
 protected:
  // Each load through a new MeshCache, as a new process makes one.
  CachedMesh load(std::size_t expect_remembered, const Eigen::Vector3d& scale = Eigen::Vector3d::Ones()) {
    MeshCache cache(cache_dir_);
    Result<CachedMesh, MeshLoadError> r = cache.load(mesh_file_, scale);
    EXPECT_TRUE(r.ok()) << r.error_text();
    EXPECT_EQ(cache.stats().keys_remembered, expect_remembered);
    const std::optional<MeshCacheKey> key = mesh_cache_key(mesh_file_, scale);
    EXPECT_TRUE(key.has_value());
    // Whatever gave the key, it is the one the file's bytes give.
    if (key) {
      EXPECT_EQ(r->cache_file, cache.file_for(*key));
    }
    return std::move(*r);
  }
};

TEST_F(MeshKeyMemoTest, ASettledMeshIsKeyedFromItsMemoPerScale) {
  let_settle();
  EXPECT_EQ(load(0).outcome, CacheOutcome::Miss);
  ASSERT_EQ(memos_in(cache_dir_).size(), 1u);
  EXPECT_EQ(load(1).outcome, CacheOutcome::Hit);
  EXPECT_EQ(load(1).outcome, CacheOutcome::Hit);
  // Another scale is another key and another memo.
  EXPECT_EQ(load(0, Eigen::Vector3d::Constant(0.001)).outcome, CacheOutcome::Miss);
  EXPECT_EQ(load(1, Eigen::Vector3d::Constant(0.001)).outcome, CacheOutcome::Hit);
  EXPECT_EQ(memos_in(cache_dir_).size(), 2u);
  // Clearing the cache removes the memos with the entries.
  const MeshCacheRemoval cleared = clear_mesh_cache(cache_dir_);
  EXPECT_EQ(cleared.removed, 2u);  // the two entries
  EXPECT_EQ(cleared.keys_removed, 2u);
  EXPECT_TRUE(memos_in(cache_dir_).empty());
  EXPECT_EQ(load(0).outcome, CacheOutcome::Miss);
}

TEST_F(MeshKeyMemoTest, AMeshRewrittenWithItsSizeAndModificationTimeIsKeyedAfresh) {
  let_settle();
  const CachedMesh cold = load(0);
  EXPECT_EQ(cold.outcome, CacheOutcome::Miss);
  EXPECT_EQ(load(1).outcome, CacheOutcome::Hit);

  // One byte of the first vertex changed in place: the same size, and the modification
  // time put back as it was.
  const fs::file_time_type modified = fs::last_write_time(mesh_file_);
  std::vector<char> bytes = read_bytes(mesh_file_);
  const std::string end_header = "end_header\n";
  const std::size_t body = std::string(bytes.begin(), bytes.end()).find(end_header);
  ASSERT_NE(body, std::string::npos);
  bytes[body + end_header.size()] = static_cast<char>(bytes[body + end_header.size()] ^ 0x5a);
  write_bytes(mesh_file_, bytes);
  fs::last_write_time(mesh_file_, modified);
  ASSERT_EQ(fs::last_write_time(mesh_file_), modified);

  const CachedMesh changed = load(0);
  EXPECT_EQ(changed.outcome, CacheOutcome::Miss);
  EXPECT_NE(changed.cache_file, cold.cache_file);
  // Just changed, the file is not remembered yet; once settled, it is.
  EXPECT_EQ(load(0).outcome, CacheOutcome::Hit);
  let_settle();
  EXPECT_EQ(load(0).outcome, CacheOutcome::Hit);
  EXPECT_EQ(load(1).outcome, CacheOutcome::Hit);
  EXPECT_EQ(memos_in(cache_dir_).size(), 1u);
}

TEST_F(MeshKeyMemoTest, AMemoThatFailsItsCheckIsIgnoredAndWrittenAgain) {
  let_settle();
  EXPECT_EQ(load(0).outcome, CacheOutcome::Miss);
  const std::vector<fs::path> memos = memos_in(cache_dir_);
  ASSERT_EQ(memos.size(), 1u);
  const std::vector<char> good = read_bytes(memos[0]);
  ASSERT_FALSE(good.empty());
  // Every byte flipped in turn (magic, the file's stamp, scale, versions, key, checksum),
  // then cut short, then empty: each is ignored, the file hashed, the memo written again.
  std::vector<std::vector<char>> bad;
  for (std::size_t i = 0; i < good.size(); ++i) {
    bad.push_back(good);
    bad.back()[i] = static_cast<char>(bad.back()[i] ^ 0x01);
  }
  bad.emplace_back(good.begin(), good.end() - 1);
  bad.emplace_back();
  for (const std::vector<char>& b : bad) {
    write_bytes(memos[0], b);
    EXPECT_EQ(load(0).outcome, CacheOutcome::Hit);
    EXPECT_EQ(read_bytes(memos[0]), good);
  }
  EXPECT_EQ(load(1).outcome, CacheOutcome::Hit);
}

TEST_F(MeshKeyMemoTest, BuildsOfAnotherCacheFormatKeepTheirOwnMemos) {
  // Two builds sharing a cache folder (an installed mhd and a new one) keep their entries
  // apart by format; they keep their memos apart too, or each would overwrite the other's
  // and the mesh file be hashed on every other load.
  let_settle();
  EXPECT_EQ(load(0).outcome, CacheOutcome::Miss);
  const std::optional<fs::path> ours = mesh_key_memo_file(cache_dir_, mesh_file_, Eigen::Vector3d::Ones());
  const std::optional<fs::path> theirs =
      mesh_key_memo_file(cache_dir_, mesh_file_, Eigen::Vector3d::Ones(), kMeshCacheFormatVersion + 1);
  ASSERT_TRUE(ours && theirs);
  ASSERT_EQ(memos_in(cache_dir_), std::vector<fs::path>{*ours});
  EXPECT_NE(*ours, *theirs);
  const std::vector<char> their_memo(104, 'x');  // this build cannot make theirs
  write_bytes(*theirs, their_memo);
  EXPECT_EQ(load(1).outcome, CacheOutcome::Hit);
  EXPECT_EQ(read_bytes(*theirs), their_memo);
  EXPECT_EQ(memos_in(cache_dir_).size(), 2u);
  // A memo's name holds for the file where it is: none for a file that is not there.
  EXPECT_FALSE(mesh_key_memo_file(cache_dir_, dir_ / "absent.ply", Eigen::Vector3d::Ones()).has_value());
}

TEST_F(MeshKeyMemoTest, AMemoGoesWithItsEvictedEntryAndStaysWithAKeptOne) {
  // A memo whose entry is gone only spares hashing a file that must then be read and built
  // anyway, so eviction takes the memos of the entries it removes, and keeps the others
  // and any it cannot read (another build's).
  let_settle();
  const Eigen::Vector3d twice = Eigen::Vector3d::Constant(2.0);
  const CachedMesh evicted = load(0);
  const CachedMesh kept = load(0, twice);
  ASSERT_EQ(evicted.outcome, CacheOutcome::Miss);
  ASSERT_EQ(kept.outcome, CacheOutcome::Miss);
  const std::optional<fs::path> evicted_memo = mesh_key_memo_file(cache_dir_, mesh_file_, Eigen::Vector3d::Ones());
  const std::optional<fs::path> kept_memo = mesh_key_memo_file(cache_dir_, mesh_file_, twice);
  ASSERT_TRUE(evicted_memo && kept_memo);
  ASSERT_EQ(memos_in(cache_dir_).size(), 2u);
  const fs::path foreign = cache_dir_ / ("0123456789abcdef0123456789abcdef" + std::string(kMeshKeyMemoExtension));
  write_bytes(foreign, std::vector<char>(104, 'x'));
  fs::last_write_time(evicted.cache_file, fs::file_time_type::clock::now() - std::chrono::seconds(100));

  const MeshCacheRemoval r = evict_mesh_cache(cache_dir_, fs::file_size(kept.cache_file));
  EXPECT_EQ(r.removed, 1u);
  EXPECT_EQ(r.keys_removed, 1u);
  EXPECT_FALSE(fs::exists(evicted.cache_file));
  EXPECT_FALSE(fs::exists(*evicted_memo));
  EXPECT_TRUE(fs::exists(kept.cache_file));
  EXPECT_TRUE(fs::exists(*kept_memo));
  EXPECT_TRUE(fs::exists(foreign));
  // Nothing over the limit: every memo stays.
  EXPECT_EQ(evict_mesh_cache(cache_dir_, fs::file_size(kept.cache_file)).keys_removed, 0u);
  EXPECT_TRUE(fs::exists(*kept_memo));

  EXPECT_EQ(load(1, twice).outcome, CacheOutcome::Hit);  // keyed from the memo kept
  EXPECT_EQ(load(0).outcome, CacheOutcome::Miss);        // hashed, built and remembered again
  EXPECT_TRUE(fs::exists(*evicted_memo));
  EXPECT_EQ(load(1).outcome, CacheOutcome::Hit);
}

}  // namespace mhd::mesh_key_memo_test
