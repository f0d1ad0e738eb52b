#pragma once
// Test helpers: a private temp folder per test and writers for small OBJ / PLY / STL files.

#include "geometry/triangle_mesh.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace mhd::test {

/// A fresh folder under the system temp folder, removed when the test ends.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = "mhd_test_" + std::to_string(::getpid()) + "_";
    if (info != nullptr) name += std::string(info->test_suite_name()) + "_" + info->name();
    for (char& c : name) {
      if (c == '/') c = '_';
    }
    path_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  [[nodiscard]] std::filesystem::path operator/(std::string_view name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

inline void write_text(const std::filesystem::path& file, std::string_view text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  ASSERT_TRUE(out.good()) << file;
}

/// Axis-aligned box [lo, hi] as an OBJ with 8 vertices and 6 quads (CCW from outside).
inline void write_box_obj(const std::filesystem::path& file, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  std::ofstream out(file);
  out.precision(17);
  out << "# box\no box\n";
  for (int i = 0; i < 8; ++i) {
    out << "v " << ((i & 1) ? hi.x() : lo.x()) << ' ' << ((i & 2) ? hi.y() : lo.y()) << ' '
        << ((i & 4) ? hi.z() : lo.z()) << '\n';
  }
  // OBJ indices are 1-based.
  out << "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  ASSERT_TRUE(out.good()) << file;
}

/// The unit square in z = 0 as two triangles facing +z.
inline TriangleMesh unit_square_mesh() {
  TriangleMesh mesh;
  mesh.vertices_m = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
  return mesh;
}

/// An open sheet of n x n quads of 1 mm in z = 0 from the origin, facing +z: a scan's shape.
inline TriangleMesh sheet_mesh(int n) {
  TriangleMesh m;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) m.vertices_m.push_back(Eigen::Vector3d(1e-3 * i, 1e-3 * j, 0.0));
  }
  const auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return m;
}

/// Binary little-endian PLY (float32 positions, int32 indices).
inline void write_binary_ply(const std::filesystem::path& file, const TriangleMesh& mesh) {
  std::ofstream out(file, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\ncomment written by an MHD test\n"
      << "element vertex " << mesh.vertices_m.size() << "\nproperty float x\nproperty float y\nproperty float z\n"
      << "element face " << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  std::string body;
  body.reserve(mesh.vertices_m.size() * 12 + mesh.triangles.size() * 13);
  auto put = [&body](const auto& value) {
    char bytes[sizeof value];
    std::memcpy(bytes, &value, sizeof value);
    body.append(bytes, sizeof value);
  };
  for (const auto& v : mesh.vertices_m) {
    put(static_cast<float>(v.x()));
    put(static_cast<float>(v.y()));
    put(static_cast<float>(v.z()));
  }
  for (const auto& t : mesh.triangles) {
    put(std::uint8_t{3});
    for (auto i : t) put(static_cast<std::int32_t>(i));
  }
  out.write(body.data(), static_cast<std::streamsize>(body.size()));
  ASSERT_TRUE(out.good()) << file;
}

/// Binary STL: every triangle with corners of its own, as STL files have them (the
/// loader welds them), and a zero facet normal, which readers recompute.
inline void write_binary_stl(const std::filesystem::path& file, const TriangleMesh& mesh) {
  std::string body(80, ' ');
  auto put = [&body](const auto& value) {
    char bytes[sizeof value];
    std::memcpy(bytes, &value, sizeof value);
    body.append(bytes, sizeof value);
  };
  put(static_cast<std::uint32_t>(mesh.triangles.size()));
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) put(0.0F);
    for (auto i : t) {
      for (int k = 0; k < 3; ++k) put(static_cast<float>(mesh.vertices_m[i][k]));
    }
    put(std::uint16_t{0});
  }
  std::ofstream out(file, std::ios::binary);
  out.write(body.data(), static_cast<std::streamsize>(body.size()));
  ASSERT_TRUE(out.good()) << file;
}

}  // namespace mhd::test
