#pragma once
// The mesh cache's tests start alike: a small sphere written as a binary PLY in a private
// temp folder, a cache folder beside it (made by the first MeshCache), and an entry's or
// a mesh file's bytes read and written whole.

#include "geometry/primitive_mesh.h"
#include "test_mesh_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

namespace mhd::test {

inline std::vector<char> read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_bytes(const std::filesystem::path& file, const std::vector<char>& bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

class SphereCacheFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    mesh_file_ = dir_ / "sphere.ply";
    write_binary_ply(mesh_file_, make_sphere_mesh(0.04, 4));
    cache_dir_ = dir_ / "cache";
  }
  TempDir dir_;
  std::filesystem::path mesh_file_;
  std::filesystem::path cache_dir_;
};

}  // namespace mhd::test
