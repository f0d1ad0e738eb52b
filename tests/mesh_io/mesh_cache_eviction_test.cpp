#include "mesh_io/mesh_cache_eviction.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace mhd {
namespace {

namespace fs = std::filesystem;

class MeshCacheEviction : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("mhd_cache_eviction_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // An entry of `bytes` last used `age_s` seconds ago.
  fs::path entry(const std::string& name, std::size_t bytes, int age_s) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << std::string(bytes, 'x');
    fs::last_write_time(p, fs::file_time_type::clock::now() - std::chrono::seconds(age_s));
    return p;
  }

  fs::path dir_;
};

TEST_F(MeshCacheEviction, ListsEntriesMostRecentlyUsedFirstAndNothingElse) {
  entry("a.mhdbvh", 10, 30);
  entry("b.mhdbvh", 20, 10);
  entry("notes.txt", 5, 0);
  const auto entries = list_mesh_cache(dir_);
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].file.filename(), "b.mhdbvh");
  EXPECT_EQ(entries[0].size_bytes, 20u);
  EXPECT_EQ(entries[1].file.filename(), "a.mhdbvh");
  EXPECT_TRUE(list_mesh_cache(dir_ / "missing").empty());
}

TEST_F(MeshCacheEviction, RemovesTheLeastRecentlyUsedUntilUnderTheLimit) {
  entry("old.mhdbvh", 100, 300);
  entry("middle.mhdbvh", 100, 200);
  entry("new.mhdbvh", 100, 100);
  const MeshCacheRemoval r = evict_mesh_cache(dir_, 250);
  EXPECT_EQ(r.removed, 1u);
  EXPECT_EQ(r.freed_bytes, 100u);
  EXPECT_EQ(r.kept_bytes, 200u);
  EXPECT_FALSE(fs::exists(dir_ / "old.mhdbvh"));
  EXPECT_TRUE(fs::exists(dir_ / "middle.mhdbvh"));
  EXPECT_TRUE(fs::exists(dir_ / "new.mhdbvh"));
  EXPECT_EQ(evict_mesh_cache(dir_, 250).removed, 0u);  // already within
}

TEST_F(MeshCacheEviction, NeverRemovesTheEntryToKeepNorOtherFiles) {
  const fs::path just_written = entry("big.mhdbvh", 500, 400);  // oldest time, still kept
  entry("other.mhdbvh", 100, 10);
  entry("readme.txt", 1000, 500);
  const MeshCacheRemoval r = evict_mesh_cache(dir_, 100, just_written);
  EXPECT_EQ(r.removed, 1u);
  EXPECT_TRUE(fs::exists(just_written));
  EXPECT_FALSE(fs::exists(dir_ / "other.mhdbvh"));
  EXPECT_TRUE(fs::exists(dir_ / "readme.txt"));
}

TEST_F(MeshCacheEviction, ClearRemovesEntriesAndLeftoverTempFiles) {
  entry("a.mhdbvh", 10, 0);
  entry("b.mhdbvh.tmp.123.0", 7, 0);
  entry("keep.txt", 3, 0);
  const MeshCacheRemoval r = clear_mesh_cache(dir_);
  EXPECT_EQ(r.removed, 2u);
  EXPECT_EQ(r.freed_bytes, 17u);
  EXPECT_TRUE(list_mesh_cache(dir_).empty());
  EXPECT_TRUE(fs::exists(dir_ / "keep.txt"));
}

TEST(MeshCacheLimit, ComesFromTheEnvironmentInMiB) {
  ::setenv("MHD_CACHE_MAX_MB", "3", 1);
  EXPECT_EQ(mesh_cache_limit_bytes(), 3u * 1024 * 1024);
  EXPECT_EQ(mesh_cache_limit_problem(), "");
  ::setenv("MHD_CACHE_MAX_MB", "lots", 1);
  EXPECT_EQ(mesh_cache_limit_bytes(), kDefaultMeshCacheLimit_bytes);
  EXPECT_EQ(mesh_cache_limit_problem(), "MHD_CACHE_MAX_MB='lots' is not a whole number of MiB from 1 to 2^40; using 512 MiB");
  ::unsetenv("MHD_CACHE_MAX_MB");
  EXPECT_EQ(mesh_cache_limit_bytes(), kDefaultMeshCacheLimit_bytes);
}

}  // namespace
}  // namespace mhd
