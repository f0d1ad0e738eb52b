#include "mesh_gen/dolphin_mesh.h"
#include "mesh_gen/mesh_export.h"
#include "mesh_gen/uv_sphere_mesh.h"

#include "mesh_checks.h"
#include "mesh_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace mhd::mesh_gen {
namespace {

class MeshGenExport : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    for (char& c : name) c = c == '/' ? '_' : c;
    dir_ = std::filesystem::temp_directory_path() / ("mhd_mesh_gen_test_" + name);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

TEST_P(MeshGenExport, RoundTripsInMillimetres) {
  const TriangleMesh mesh = make_uv_sphere(0.1, uv_sphere_layout(2'000));
  const std::filesystem::path file = dir_ / ("sphere" + GetParam());
  write_mesh_file(mesh, file, 1000.0);
  ASSERT_TRUE(std::filesystem::exists(file));
  const TriangleMesh back = test::read_mesh_file(file, 0.001);
  EXPECT_EQ(back.triangle_count(), mesh.triangle_count());
  EXPECT_EQ(back.vertices_m.size(), mesh.vertices_m.size());
  const Eigen::AlignedBox3d box = mesh_bounds(back);
  EXPECT_NEAR(box.sizes().y(), 0.2, 1e-5);
  const test::EdgeStats edges = test::edge_stats(back);
  EXPECT_EQ(edges.manifold_oriented, edges.edges);
  EXPECT_GT(test::enclosed_volume(back), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Formats, MeshGenExport, ::testing::Values(".ply", ".obj", ".stl"),
                         [](const auto& param_info) { return param_info.param.substr(1); });

// Another build regenerates the assets while tests read them: a reader keeps the mesh it
// opened, and the path then holds the new one, with no part file left beside it.
TEST_P(MeshGenExport, ReplacesAFileWholeUnderAReaderThatHasItOpen) {
  const std::filesystem::path file = dir_ / ("mesh" + GetParam());
  write_mesh_file(make_uv_sphere(0.1, uv_sphere_layout(2'000)), file, 1000.0);
  const auto old_size = std::filesystem::file_size(file);
  std::ifstream reader(file, std::ios::binary);
  ASSERT_TRUE(reader.good());

  const TriangleMesh larger = make_uv_sphere(0.1, uv_sphere_layout(8'000));
  write_mesh_file(larger, file, 1000.0);

  const std::string read_on((std::istreambuf_iterator<char>(reader)), std::istreambuf_iterator<char>());
  EXPECT_EQ(read_on.size(), old_size);
  EXPECT_EQ(test::read_mesh_file(file, 0.001).triangle_count(), larger.triangle_count());
  int entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir_)) ++entries;
  EXPECT_EQ(entries, 1);
}

TEST(MeshGenExportErrors, UnknownExtensionThrows) {
  const TriangleMesh mesh = make_uv_sphere(0.1, uv_sphere_layout(100));
  EXPECT_THROW(write_mesh_file(mesh, std::filesystem::temp_directory_path() / "mhd_mesh.xyz", 1000.0),
               std::runtime_error);
}

TEST(MeshGenExportErrors, BinaryPlyIsCompact) {
  const TriangleMesh mesh = make_dolphin(dolphin_layout(3'000));
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "mhd_mesh_gen_compact_dolphin.ply";
  write_mesh_file(mesh, file, 1000.0);
  // 12 bytes per float vertex, 13 per triangle (count byte + 3 indices), plus a header.
  EXPECT_LT(std::filesystem::file_size(file), mesh.vertices_m.size() * 12 + mesh.triangle_count() * 13 + 1024);
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace mhd::mesh_gen
