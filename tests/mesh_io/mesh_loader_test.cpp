#include "mesh_io/mesh_loader.h"

#include "geometry/primitive_mesh.h"
#include "test_mesh_files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

namespace mhd {
namespace {

using test::TempDir;

double signed_volume(const TriangleMesh& m) {
  double six_v = 0.0;
  for (const auto& t : m.triangles) {
    six_v += m.vertices_m[t[0]].dot(m.vertices_m[t[1]].cross(m.vertices_m[t[2]]));
  }
  return six_v / 6.0;
}

/// Each edge shared by exactly two triangles walking it in opposite directions.
bool is_closed_and_consistent(const TriangleMesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : m.triangles) {
    for (std::size_t k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& [e, n] : directed) {
    if (n != 1 || !directed.contains({e.second, e.first})) return false;
  }
  return true;
}

using Corner = std::tuple<double, double, double>;
using TriangleKey = std::array<Corner, 3>;

/// Triangles as corner positions, rotated so the smallest corner comes first (keeps
/// the winding), sorted: compares meshes independently of vertex numbering.
std::vector<TriangleKey> triangle_keys(const TriangleMesh& m) {
  std::vector<TriangleKey> keys;
  for (const auto& t : m.triangles) {
    TriangleKey k;
    for (std::size_t i = 0; i < 3; ++i) {
      const auto& v = m.vertices_m[t[i]];
      k[i] = {v.x(), v.y(), v.z()};
    }
    std::rotate(k.begin(), std::min_element(k.begin(), k.end()), k.end());
    keys.push_back(k);
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

void expect_unit_normals(const TriangleMesh& m) {
  ASSERT_EQ(m.vertex_normals.size(), m.vertices_m.size());
  // Single precision: unit within a few float roundings.
  for (const auto& n : m.vertex_normals) EXPECT_NEAR(n.norm(), 1.0f, 4 * std::numeric_limits<float>::epsilon());
}

// A UTF-8 byte order mark before the first vertex (as editors on Windows write it) is
// skipped: the mesh loads as the same file without it does, first vertex included.
TEST(MeshLoader, AnObjWithAByteOrderMarkLoadsAsWithoutIt) {
  TempDir dir;
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  test::write_text(dir / "plain.obj", obj);
  test::write_text(dir / "marked.obj", "\xEF\xBB\xBF" + obj);
  const Result<LoadedMesh, MeshLoadError> plain = load_mesh_file(dir / "plain.obj", Eigen::Vector3d::Ones());
  const Result<LoadedMesh, MeshLoadError> marked = load_mesh_file(dir / "marked.obj", Eigen::Vector3d::Ones());
  ASSERT_TRUE(plain.ok()) << plain.error_text();
  ASSERT_TRUE(marked.ok()) << marked.error_text();
  EXPECT_EQ(marked->mesh.triangle_count(), 4u);
  EXPECT_EQ(marked->mesh.vertices_m, plain->mesh.vertices_m);
  EXPECT_EQ(marked->mesh.triangles, plain->mesh.triangles);
}

TEST(MeshLoader, ObjQuadsAreTriangulatedIntoAClosedOutwardBox) {
  TempDir dir;
  const Eigen::Vector3d lo(-0.1, -0.2, 0.0), hi(0.3, 0.2, 0.25);
  test::write_box_obj(dir / "box.obj", lo, hi);
  const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir / "box.obj", Eigen::Vector3d::Ones());
  ASSERT_TRUE(r.ok()) << r.error_text();
  const TriangleMesh& m = r->mesh;
  EXPECT_EQ(m.triangle_count(), 12u);
  EXPECT_EQ(m.vertices_m.size(), 8u);
  EXPECT_EQ(r->dropped_triangles, 0u);
  EXPECT_TRUE(is_closed_and_consistent(m));
  EXPECT_NEAR(signed_volume(m), (hi - lo).prod(), 1e-7);  // float precision in assimp
  const auto box = mesh_bounds(m);
  EXPECT_TRUE(box.min().isApprox(lo, 1e-6));
  EXPECT_TRUE(box.max().isApprox(hi, 1e-6));
  expect_unit_normals(m);
}

TEST(MeshLoader, MillimetreScaleGivesMetres) {
  TempDir dir;
  test::write_box_obj(dir / "box_mm.obj", Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(100, 50, 20));
  const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir / "box_mm.obj", Eigen::Vector3d::Constant(0.001));
  ASSERT_TRUE(r.ok()) << r.error_text();
  const auto box = mesh_bounds(r->mesh);
  EXPECT_NEAR(box.max().x(), 0.1, 1e-12);
  EXPECT_NEAR(box.max().y(), 0.05, 1e-12);
  EXPECT_NEAR(box.max().z(), 0.02, 1e-12);
  EXPECT_NEAR(signed_volume(r->mesh), 0.1 * 0.05 * 0.02, 1e-12);

  // Per-axis scale.
  const Result<LoadedMesh, MeshLoadError> s = load_mesh_file(dir / "box_mm.obj", Eigen::Vector3d(0.001, 0.002, 0.01));
  ASSERT_TRUE(s.ok());
  const auto sbox = mesh_bounds(s->mesh);
  EXPECT_NEAR(sbox.max().x(), 0.1, 1e-12);
  EXPECT_NEAR(sbox.max().y(), 0.1, 1e-12);
  EXPECT_NEAR(sbox.max().z(), 0.2, 1e-12);
}

TEST(MeshLoader, MirroringScaleKeepsTheMeshFacingOutwards) {
  TempDir dir;
  test::write_box_obj(dir / "box.obj", Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 2, 3));
  for (const Eigen::Vector3d& scale : {Eigen::Vector3d(-1, 1, 1), Eigen::Vector3d(1, -1, 1), Eigen::Vector3d(-1, -1, -1),
                                      Eigen::Vector3d(-1, -1, 1)}) {
    SCOPED_TRACE(::testing::Message() << scale.transpose());
    const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir / "box.obj", scale);
    ASSERT_TRUE(r.ok());
    EXPECT_NEAR(signed_volume(r->mesh), 6.0, 1e-9);
    EXPECT_TRUE(is_closed_and_consistent(r->mesh));
    const auto box = mesh_bounds(r->mesh);
    EXPECT_NEAR(box.min().x(), scale.x() < 0 ? -1.0 : 0.0, 1e-12);
  }
}

TEST(MeshLoader, BinaryPlyRoundTripsTheMesh) {
  TempDir dir;
  const TriangleMesh sphere = make_sphere_mesh(0.5, 3);
  test::write_binary_ply(dir / "sphere.ply", sphere);
  const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir / "sphere.ply", Eigen::Vector3d::Ones());
  ASSERT_TRUE(r.ok()) << r.error_text();
  const TriangleMesh& m = r->mesh;
  EXPECT_EQ(m.triangle_count(), sphere.triangle_count());
  EXPECT_EQ(m.vertices_m.size(), sphere.vertices_m.size());  // shared vertices stay shared
  EXPECT_TRUE(is_closed_and_consistent(m));
  // Same triangles, same winding, at float precision.
  TriangleMesh expected = sphere;
  // Through a float array in memory: GCC 12's SLP vectorizer drops an in-register
  // double -> float -> double round trip of vector components.
  std::vector<float> as_float;
  for (const auto& v : sphere.vertices_m) {
    for (int k = 0; k < 3; ++k) as_float.push_back(static_cast<float>(v[k]));
  }
  for (std::size_t i = 0; i < expected.vertices_m.size(); ++i) {
    expected.vertices_m[i] = Eigen::Vector3f(&as_float[3 * i]).cast<double>();
  }
  EXPECT_EQ(triangle_keys(m), triangle_keys(expected));
  expect_unit_normals(m);
  for (std::size_t i = 0; i < m.vertices_m.size(); ++i) {
    EXPECT_GT(m.vertex_normals[i].cast<double>().dot(m.vertices_m[i].normalized()), 0.99);
  }
}

/// `mesh` with its positions rounded through single precision, as a float file holds them.
TriangleMesh through_floats(const TriangleMesh& mesh) {
  TriangleMesh rounded = mesh;
  std::vector<float> as_float;  // in memory: see BinaryPlyRoundTripsTheMesh
  for (const auto& v : mesh.vertices_m) {
    for (int k = 0; k < 3; ++k) as_float.push_back(static_cast<float>(v[k]));
  }
  for (std::size_t i = 0; i < rounded.vertices_m.size(); ++i) {
    rounded.vertices_m[i] = Eigen::Vector3f(&as_float[3 * i]).cast<double>();
  }
  return rounded;
}

/// `mesh` with the triangles `flip` picks wound the other way.
template <class Pick>
TriangleMesh with_flipped(const TriangleMesh& mesh, Pick&& flip) {
  TriangleMesh out = mesh;
  for (std::size_t t = 0; t < out.triangles.size(); ++t) {
    if (flip(t)) std::swap(out.triangles[t][1], out.triangles[t][2]);
  }
  return out;
}

TEST(MeshLoader, TrianglesWoundAgainstTheirNeighboursAreTurnedToThem) {
  // A closed sphere (1,280 triangles) and an open sheet (a scan's shape), each written with
  // some of its triangles wound the wrong way: one, or a scattered few percent up to a
  // third. The loaded mesh is the mesh as made, every triangle facing out, and so are its
  // vertex normals. In PLY, with shared corners, and in STL, whose triangles share none
  // until the loader welds them.
  TempDir dir;
  const TriangleMesh sphere = make_sphere_mesh(0.5, 3);
  const TriangleMesh sheet = test::sheet_mesh(20);
  std::mt19937 rng(20261202);
  for (const TriangleMesh* made : {&sphere, &sheet}) {
    for (const double fraction : {0.0, 0.03, 0.1, 0.33}) {
      for (const std::string_view format : {"ply", "stl"}) {
        SCOPED_TRACE(::testing::Message() << made->triangle_count() << " triangles, " << fraction << " flipped, "
                                          << format);
        std::bernoulli_distribution pick(fraction);
        std::size_t flipped = 0;
        const TriangleMesh written = with_flipped(*made, [&](std::size_t t) {
          const bool f = fraction == 0.0 ? t == made->triangles.size() / 2 : pick(rng);
          flipped += f ? 1 : 0;
          return f;
        });
        const std::filesystem::path file = dir / ("flipped." + std::string(format));
        if (format == "ply") {
          test::write_binary_ply(file, written);
        } else {
          test::write_binary_stl(file, written);
        }
        const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(file, Eigen::Vector3d::Ones());
        ASSERT_TRUE(r.ok()) << r.error_text();
        EXPECT_TRUE(triangle_keys(r->mesh) == triangle_keys(through_floats(*made)));  // printed, it fills pages
        EXPECT_EQ(r->flipped_triangles, flipped);
        EXPECT_EQ(r->mesh.vertices_m.size(), made->vertices_m.size());  // welded
        expect_unit_normals(r->mesh);
      }
    }
  }
  // The normals face out again on the sphere (a flipped triangle's corners pulled them in).
  test::write_binary_ply(dir / "one.ply", with_flipped(sphere, [](std::size_t t) { return t % 5 == 0; }));
  const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir / "one.ply", Eigen::Vector3d::Ones());
  ASSERT_TRUE(r.ok()) << r.error_text();
  for (std::size_t i = 0; i < r->mesh.vertices_m.size(); ++i) {
    EXPECT_GT(r->mesh.vertex_normals[i].cast<double>().dot(r->mesh.vertices_m[i].normalized()), 0.99);
  }
}

TEST(MeshLoader, MostOfEachSurfaceDecidesItsWinding) {
  // The dual: a surface wound one way throughout keeps it, whichever way that is (a room
  // seen from inside is an inside-out box), and so does each of two surfaces that share
  // no edge, wound the opposite ways. Two thirds of a sheet flipped turns the last third.
  TempDir dir;
  const TriangleMesh sphere = make_sphere_mesh(0.5, 3);
  const TriangleMesh inside_out = with_flipped(sphere, [](std::size_t) { return true; });
  TriangleMesh pair = sphere;  // the sphere, and the inside-out one 2 m along x
  const auto offset = static_cast<std::uint32_t>(pair.vertices_m.size());
  for (const auto& v : inside_out.vertices_m) pair.vertices_m.push_back(v + Eigen::Vector3d(2, 0, 0));
  for (const auto& t : inside_out.triangles) pair.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const TriangleMesh sheet = test::sheet_mesh(6);  // 72 triangles
  const TriangleMesh mostly_flipped = with_flipped(sheet, [](std::size_t t) { return t % 3 != 0; });
  const TriangleMesh all_flipped = with_flipped(sheet, [](std::size_t) { return true; });
  struct Case {
    const TriangleMesh* written;
    const TriangleMesh* expected;
    std::size_t flipped;
  };
  for (const Case& c : {Case{&sphere, &sphere, 0}, Case{&inside_out, &inside_out, 0}, Case{&pair, &pair, 0},
                        Case{&mostly_flipped, &all_flipped, sheet.triangle_count() / 3}}) {
    SCOPED_TRACE(::testing::Message() << c.written->triangle_count() << " triangles");
    test::write_binary_ply(dir / "kept.ply", *c.written);
    const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir / "kept.ply", Eigen::Vector3d::Ones());
    ASSERT_TRUE(r.ok()) << r.error_text();
    EXPECT_TRUE(triangle_keys(r->mesh) == triangle_keys(through_floats(*c.expected)));
    EXPECT_EQ(r->flipped_triangles, c.flipped);
  }
}

TEST(MeshLoader, DegenerateTrianglesAndUnusedVerticesAreDropped) {
  TempDir dir;
  // Two good triangles, one with a repeated corner, one with collinear corners and an
  // unused vertex.
  test::write_text(dir / "mixed.ply",
                   "ply\nformat ascii 1.0\nelement vertex 7\nproperty float x\nproperty float y\nproperty float z\n"
                   "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
                   "0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 0 0\n9 9 9\n3 0 0\n"
                   "3 0 1 2\n3 1 3 2\n3 0 1 1\n3 0 1 4\n");
  const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir / "mixed.ply", Eigen::Vector3d::Ones());
  ASSERT_TRUE(r.ok()) << r.error_text();
  EXPECT_EQ(r->mesh.triangle_count(), 2u);
  EXPECT_EQ(r->dropped_triangles, 2u);
  EXPECT_EQ(r->mesh.vertices_m.size(), 4u);  // 2 0 0, 9 9 9 and 3 0 0 are unused
  const auto box = mesh_bounds(r->mesh);
  EXPECT_EQ(box.max(), Eigen::Vector3d(1, 1, 0));
  expect_unit_normals(r->mesh);
}

TEST(MeshLoader, MeshesOfOneFileAreMergedAndWelded) {
  TempDir dir;
  // Two OBJ objects: the two halves of a unit square, sharing an edge by position.
  test::write_text(dir / "two.obj",
                   "o a\nv 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n"
                   "o b\nv 0 0 0\nv 1 1 0\nv 0 1 0\nf 4 5 6\n");
  const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir / "two.obj", Eigen::Vector3d::Ones());
  ASSERT_TRUE(r.ok()) << r.error_text();
  EXPECT_EQ(r->mesh.triangle_count(), 2u);
  EXPECT_EQ(r->mesh.vertices_m.size(), 4u);
  for (const auto& n : r->mesh.vertex_normals) EXPECT_EQ(n.z(), 1.0f);
}

TEST(MeshLoader, MissingFileIsReportedWithItsName) {
  TempDir dir;
  const auto file = dir / "nope.obj";
  const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(file, Eigen::Vector3d::Ones());
  ASSERT_FALSE(r.ok());
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().reason, "file not found");
  EXPECT_NE(r.error().message().find(file.string()), std::string::npos) << r.error().message();
}

TEST(MeshLoader, FolderIsNotAMeshFile) {
  TempDir dir;
  const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir.path(), Eigen::Vector3d::Ones());
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().reason, "is a directory, not a regular file");
}

TEST(MeshLoader, PointsAndLinesOnlyMeansNoTriangles) {
  TempDir dir;
  test::write_text(dir / "lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\np 1\n");
  const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir / "lines.obj", Eigen::Vector3d::Ones());
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().reason.find("no triangles"), std::string::npos) << r.error().message();
  EXPECT_NE(r.error().message().find("lines.obj"), std::string::npos);
}

TEST(MeshLoader, GarbageIsAnAssimpError) {
  TempDir dir;
  std::string junk(4096, '\0');
  std::mt19937 rng(7);
  for (char& c : junk) c = static_cast<char>(rng() & 0xff);
  for (const char* name : {"junk.ply", "junk.stl", "junk.bin"}) {
    SCOPED_TRACE(name);
    test::write_text(dir / name, junk);
    const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir / name, Eigen::Vector3d::Ones());
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message().find(name), std::string::npos) << r.error().message();
    EXPECT_FALSE(r.error().reason.empty());
  }
}

TEST(MeshLoader, EmptyFile) {
  TempDir dir;
  test::write_text(dir / "empty.obj", "");
  const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir / "empty.obj", Eigen::Vector3d::Ones());
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().reason, "file is empty");
}

TEST(MeshLoader, NonFiniteCoordinatesAreRejected) {
  TempDir dir;
  test::write_box_obj(dir / "box.obj", Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 10, 10));
  // 10 * 1e308 overflows to infinity.
  const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir / "box.obj", Eigen::Vector3d(1e308, 1, 1));
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().reason.find("non-finite"), std::string::npos) << r.error().message();
}

TEST(MeshLoader, InvalidScaleIsRejected) {
  TempDir dir;
  test::write_box_obj(dir / "box.obj", Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1));
  EXPECT_FALSE(load_mesh_file(dir / "box.obj", Eigen::Vector3d(1, 0, 1)).ok());
  EXPECT_FALSE(load_mesh_file(dir / "box.obj", Eigen::Vector3d(1, std::nan(""), 1)).ok());
}

TEST(MeshLoader, ProgressIsForwarded) {
  TempDir dir;
  test::write_binary_ply(dir / "sphere.ply", make_sphere_mesh(1.0, 2));
  std::vector<double> fractions;
  const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir / "sphere.ply", Eigen::Vector3d::Ones(),
                                          [&](std::string_view, double f) { fractions.push_back(f); });
  ASSERT_TRUE(r.ok());
  ASSERT_FALSE(fractions.empty());
  for (double f : fractions) {
    EXPECT_GE(f, 0.0);
    EXPECT_LE(f, 1.0);
  }
}

}  // namespace
}  // namespace mhd
