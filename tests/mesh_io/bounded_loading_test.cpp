// Loading within bounds, through load_mesh_file and real files: each
// hostile input is refused at once with its exact message, and good meshes still load.
#include "mesh_io/available_memory.h"
#include "mesh_io/mesh_loader.h"
#include "test_mesh_files.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace mhd {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

/// 170 header bytes and 6 of data: 176 bytes claiming 1e8 vertices and 1e8 faces.
constexpr std::string_view kHugePly =
    "ply\nformat ascii 1.0\nelement vertex 100000000\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 100000000\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n";

std::string reason_of(const Result<LoadedMesh, MeshLoadError>& r) { return r.ok() ? std::string("(loaded)") : r.error().reason; }

const std::string kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

TEST(BoundedLoading, PlyClaimingHundredMillionElementsIsRefusedAtOnce) {
  TempDir dir;
  test::write_text(dir / "huge.ply", kHugePly);
  ASSERT_EQ(fs::file_size(dir / "huge.ply"), 176u);
  const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir / "huge.ply", Eigen::Vector3d::Ones());
  EXPECT_EQ(reason_of(r),
            "PLY header claims 100000000 vertex and 100000000 face elements, at least 800000000 bytes of ASCII data, "
            "but only 6 bytes follow the header");
  EXPECT_EQ(r.error().message(), "mesh file '" + (dir / "huge.ply").string() + "': " + reason_of(r));
}

TEST(BoundedLoading, BinaryStlWithALyingCountIsRefused) {
  TempDir dir;
  std::string stl(80, ' ');
  stl += std::string("\x40\x42\x0f\x00", 4);  // 1,000,000 triangles
  stl.append(50, '\x02');                      // but room for one
  test::write_text(dir / "liar.stl", stl);
  EXPECT_EQ(reason_of(load_mesh_file(dir / "liar.stl", Eigen::Vector3d::Ones())),
            "binary STL header claims 1000000 triangles (50000084 bytes), but the file has 134 bytes");
}

TEST(BoundedLoading, HeaderFaceCountAboveMaxTrianglesIsRefusedBeforeLoading) {
  TempDir dir;
  test::write_binary_ply(dir / "two.ply", test::unit_square_mesh());
  EXPECT_EQ(reason_of(load_mesh_file(dir / "two.ply", Eigen::Vector3d::Ones(), {}, TriangleBudget{1})),
            "the header claims 2 faces, more than max_triangles (1)");
  EXPECT_TRUE(load_mesh_file(dir / "two.ply", Eigen::Vector3d::Ones(), {}, TriangleBudget{2}).ok());
}

TEST(BoundedLoading, AHeaderClaimingMoreThanMemoryHoldsIsRefusedBeforeLoading) {
  // Refused from the header at what a load takes per triangle, and loaded when it fits.
  TempDir dir;
  test::write_binary_ply(dir / "two.ply", test::unit_square_mesh());
  const std::uint64_t needed = 2 * TriangleBudget::kLoadBytesPerTriangle;
  EXPECT_EQ(reason_of(load_mesh_file(dir / "two.ply", Eigen::Vector3d::Ones(), {}, TriangleBudget{10, 0, needed - 1})),
            "the header claims 2 faces, about " + std::to_string(needed) + " bytes to load, more than the " +
                std::to_string(needed - 1) + " bytes of memory available");
  EXPECT_TRUE(load_mesh_file(dir / "two.ply", Eigen::Vector3d::Ones(), {}, TriangleBudget{10, 0, needed}).ok());
  EXPECT_TRUE(load_mesh_file(dir / "two.ply", Eigen::Vector3d::Ones(), {}, TriangleBudget{10, 0, 0}).ok());
  // A billion triangles, what a scene may declare, in the units a user reads.
  const TriangleBudget machine{1'000'000'000, 0, std::uint64_t{24} << 30};
  EXPECT_EQ(machine.memory_refusal("the header claims", 1'000'000'000, "faces"),
            "the header claims 1000000000 faces, about 139.7 GiB to load, more than the 24.0 GiB of memory available");
  EXPECT_EQ(machine.memory_refusal("the header claims", 100'000'000, "faces"), "");
  // This machine's figure is read, and the repository's meshes fit it.
  EXPECT_GT(available_memory_bytes(), std::uint64_t{1} << 28);
}

TEST(BoundedLoading, LoadedTrianglesAboveMaxTrianglesAreRefused) {
  TempDir dir;
  test::write_box_obj(dir / "box.obj", Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());  // OBJ: no header count
  EXPECT_EQ(reason_of(load_mesh_file(dir / "box.obj", Eigen::Vector3d::Ones(), {}, TriangleBudget{11})),
            "12 triangles, more than max_triangles (11)");
  EXPECT_EQ(reason_of(load_mesh_file(dir / "box.obj", Eigen::Vector3d::Ones(), {}, TriangleBudget{20, 10})),
            "12 triangles, more than the 10 left of max_triangles (20) after the scene's other 10 triangles");
}

TEST(BoundedLoading, MtllibNamingAFifoFailsInsteadOfBlocking) {
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "evil.mtl").c_str(), 0600), 0);
  test::write_text(dir / "fifo.obj", "mtllib evil.mtl\n" + kTriangleObj);
  EXPECT_EQ(reason_of(load_mesh_file(dir / "fifo.obj", Eigen::Vector3d::Ones())),
            "side file '" + (dir / "evil.mtl").string() + "' is a FIFO, not a regular file");
}

TEST(BoundedLoading, MtllibNamingADeviceOrDirectoryIsRefused) {
  TempDir dir;
  fs::create_symlink("/dev/zero", dir / "zero.mtl");
  test::write_text(dir / "dev.obj", "mtllib zero.mtl\n" + kTriangleObj);
  fs::create_directory(dir / "folder.mtl");
  test::write_text(dir / "dir.obj", "mtllib folder.mtl\n" + kTriangleObj);
  EXPECT_EQ(reason_of(load_mesh_file(dir / "dev.obj", Eigen::Vector3d::Ones())),
            "side file '" + (dir / "zero.mtl").string() + "' is a device, not a regular file");
  EXPECT_EQ(reason_of(load_mesh_file(dir / "dir.obj", Eigen::Vector3d::Ones())),
            "side file '" + (dir / "folder.mtl").string() + "' is a directory, not a regular file");
}

TEST(BoundedLoading, TexturePathToADirectoryIsRefused) {
  TempDir dir;
  fs::create_directory(dir / "textures");
  test::write_text(dir / "skin.mtl", "newmtl skin\nKd 1 1 1\nmap_Kd textures\n");
  test::write_text(dir / "textured.obj", "mtllib skin.mtl\nusemtl skin\n" + kTriangleObj);
  EXPECT_EQ(reason_of(load_mesh_file(dir / "textured.obj", Eigen::Vector3d::Ones())),
            "texture '" + (dir / "textures").string() + "' is a directory, not a regular file");
}

TEST(BoundedLoading, MissingSideFilesAreNotAnError) {
  // MHD reads neither materials nor textures: a mesh that lost them still loads.
  TempDir dir;
  test::write_text(dir / "lost.mtl", "newmtl skin\nmap_Kd no_such_texture.png\n");
  test::write_text(dir / "lost.obj", "mtllib no_such.mtl\nmtllib lost.mtl\nusemtl skin\n" + kTriangleObj);
  const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir / "lost.obj", Eigen::Vector3d::Ones());
  ASSERT_TRUE(r.ok()) << r.error_text();
  EXPECT_EQ(r->mesh.triangle_count(), 1u);
}

TEST(BoundedLoading, MeshFileThatIsASymlinkLoopIsNamedAsOne) {
  TempDir dir;
  fs::create_symlink(dir / "b.obj", dir / "a.obj");
  fs::create_symlink(dir / "a.obj", dir / "b.obj");
  EXPECT_EQ(reason_of(load_mesh_file(dir / "a.obj", Eigen::Vector3d::Ones())), "is a symlink loop");
}

TEST(BoundedLoading, MeshFileThatIsAFifoIsRefused) {
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "pipe.ply").c_str(), 0600), 0);
  EXPECT_EQ(reason_of(load_mesh_file(dir / "pipe.ply", Eigen::Vector3d::Ones())), "is a FIFO, not a regular file");
}

TEST(BoundedLoading, FaceIndexPastTheVerticesIsRefusedNotACrash) {
  // Found by mhd-fuzz-mesh-header: assimp's post-processing crashed on it.
  TempDir dir;
  TriangleMesh mesh;
  mesh.vertices_m = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 130816}};
  test::write_binary_ply(dir / "index.ply", mesh);
  EXPECT_EQ(reason_of(load_mesh_file(dir / "index.ply", Eigen::Vector3d::Ones())),
            "assimp could not read it: Validation failed: aiMesh::mFaces[0]::mIndices[2] is out of range");
}

/// A binary PLY of the four corners of a unit tetrahedron and one face per entry of
/// `corner_counts`, each listing that many of the corners 0, 1, 2, 3, 0, 1, ...
void write_ply_with_faces(const fs::path& file, const std::vector<int>& corner_counts) {
  std::string bytes = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                      "property float z\nelement face " +
                      std::to_string(corner_counts.size()) +
                      "\nproperty list uchar int vertex_indices\nend_header\n";
  const std::array<float, 12> corners{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  bytes.append(reinterpret_cast<const char*>(corners.data()), sizeof(corners));
  for (const int count : corner_counts) {
    bytes.push_back(static_cast<char>(count));
    for (int k = 0; k < count; ++k) {
      const std::int32_t index = k % 4;
      bytes.append(reinterpret_cast<const char*>(&index), sizeof(index));
    }
  }
  test::write_text(file, bytes);
}

TEST(BoundedLoading, AFaceWithNoCornersIsRefusedNotACrash) {
  // Found by mhd-fuzz-mesh-header: assimp 5.2.5 types such a face a polygon, and its
  // triangulation then aborts the process (an ai_assert) unless a real polygon is beside it.
  TempDir dir;
  for (const auto& [faces, first_empty] : std::vector<std::pair<std::vector<int>, int>>{
           {{0}, 0}, {{3, 0}, 1}, {{0, 3}, 0}, {{1, 0}, 1}, {{2, 0}, 1}, {{3, 0, 0}, 1}, {{4, 0}, 1}, {{0, 5}, 0}}) {
    SCOPED_TRACE(::testing::PrintToString(faces));
    write_ply_with_faces(dir / "empty_face.ply", faces);
    EXPECT_EQ(reason_of(load_mesh_file(dir / "empty_face.ply", Eigen::Vector3d::Ones())),
              "face " + std::to_string(first_empty) + " has no vertex indices");
  }
  test::write_text(dir / "empty_face_ascii.ply",
                   "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                   "element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n0\n");
  EXPECT_EQ(reason_of(load_mesh_file(dir / "empty_face_ascii.ply", Eigen::Vector3d::Ones())),
            "face 1 has no vertex indices");
}

TEST(BoundedLoading, FacesOfEveryOtherCornerCountStillLoad) {
  // The dual: points and lines are dropped, triangles kept, polygons triangulated.
  TempDir dir;
  for (const auto& [faces, triangles] : std::vector<std::pair<std::vector<int>, std::size_t>>{
           {{3}, 1}, {{1, 3}, 1}, {{2, 3}, 1}, {{3, 4}, 3}, {{4}, 2}}) {
    SCOPED_TRACE(::testing::PrintToString(faces));
    write_ply_with_faces(dir / "faces.ply", faces);
    const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir / "faces.ply", Eigen::Vector3d::Ones());
    ASSERT_TRUE(r.ok()) << r.error_text();
    EXPECT_EQ(r->mesh.triangle_count(), triangles);
  }
}

TEST(BoundedLoading, SmdFilesAreRefusedUnreadNotLeftToHang) {
  // Found by probing assimp's readers with mutated files: its SMD reader (chosen by the
  // extension, .smd or .vta) loops for ever on a "nodes" section the file ends in.
  TempDir dir;
  for (const char* name : {"model.smd", "model.vta", "MODEL.SMD", "ply_inside.smd"}) {
    SCOPED_TRACE(name);
    test::write_text(dir / name, std::string(name) == "ply_inside.smd" ? "ply\nformat ascii 1.0\nend_header\n"
                                                                         : "version 1\nnodes\n");
    EXPECT_EQ(reason_of(load_mesh_file(dir / name, Eigen::Vector3d::Ones())),
              "SMD files are not read: assimp 5.2.5's SMD reader can loop for ever on a truncated file "
              "(convert it to PLY, OBJ or glTF)");
  }
}

TEST(BoundedLoading, AReaderThatCrashesEndsAsAnErrorNotACrash) {
  // Found by tools/fuzz/probe_importers.py: assimp 5.2.5's COLLADA reader segfaults on a
  // <float_array> whose count attribute is misspelt. It reads in a child process, so the
  // crash is the child's, and the load says so.
  TempDir dir;
  const auto collada = [](const std::string& count_attribute) {
    return "<?xml version=\"1.0\"?><COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" "
                   "version=\"1.4.1\"><library_geometries><geometry id=\"g\"><mesh><source id=\"p\">"
                   "<float_array id=\"pa\" " + count_attribute + "=\"9\">0 0 0 1 0 0 0 1 0</float_array><technique_common>"
                   "<accessor source=\"#pa\" count=\"3\" stride=\"3\"><param name=\"X\" type=\"float\"/>"
                   "<param name=\"Y\" type=\"float\"/><param name=\"Z\" type=\"float\"/></accessor>"
                   "</technique_common></source><vertices id=\"v\"><input semantic=\"POSITION\" source=\"#p\"/>"
                   "</vertices><triangles count=\"1\"><input semantic=\"VERTEX\" source=\"#v\" offset=\"0\"/>"
                   "<p>0 1 2</p></triangles></mesh></geometry></library_geometries><library_visual_scenes>"
                   "<visual_scene id=\"s\"><node><instance_geometry url=\"#g\"/></node></visual_scene>"
                   "</library_visual_scenes><scene><instance_visual_scene url=\"#s\"/></scene></COLLADA>";
  };
  test::write_text(dir / "crash.dae", collada("counnant"));
  const std::string reason = reason_of(load_mesh_file(dir / "crash.dae", Eigen::Vector3d::Ones()));
  EXPECT_EQ(reason.rfind("assimp crashed reading it (", 0), 0u) << reason;
  // The dual: the same file spelt right loads.
  test::write_text(dir / "good.dae", collada("count"));
  const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir / "good.dae", Eigen::Vector3d::Ones());
  ASSERT_TRUE(r.ok()) << r.error_text();
  EXPECT_EQ(r->mesh.triangle_count(), 1u);
}

TEST(BoundedLoading, AReadPastItsLimitIsStoppedAndSaidSo) {
  // No read ends before a limit of 0 s: the child is killed, the load says why; with the
  // default limits the same file loads.
  TempDir dir;
  test::write_binary_ply(dir / "sheet.ply", test::sheet_mesh(40));
  const std::string reason = reason_of(
      load_mesh_file(dir / "sheet.ply", Eigen::Vector3d::Ones(), {}, std::nullopt, MeshReadLimits{0.0, 0.0}));
  EXPECT_EQ(reason.rfind("assimp did not finish reading it within 0 s (the limit for a file of ", 0), 0u) << reason;
  EXPECT_TRUE(load_mesh_file(dir / "sheet.ply", Eigen::Vector3d::Ones()).ok());
}

/// Good input is never refused: the repository's assets, and Debian's bunny when present.
void expect_loads(const fs::path& file) {
  SCOPED_TRACE(file.string());
  const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(file, Eigen::Vector3d::Ones(), {}, TriangleBudget{50'000'000});
  ASSERT_TRUE(r.ok()) << r.error_text();
  EXPECT_GT(r->mesh.triangle_count(), 0u);
}

TEST(BoundedLoading, RepositoryAssetsStillLoad) {
  int loaded = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(MHD_SOURCE_DIR) / "assets")) {
    if (entry.path().extension() != ".ply") continue;
    expect_loads(entry.path());
    ++loaded;
  }
  EXPECT_GE(loaded, 2);
}

TEST(BoundedLoading, GeneratedAssetsStillLoad) {
  // assets/generated is written by mhd-mesh-gen (docs/assets.md); absent in a fresh tree.
  const fs::path folder = fs::path(MHD_SOURCE_DIR) / "assets" / "generated";
  if (!fs::is_directory(folder)) GTEST_SKIP() << folder << " not generated";
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() == ".ply" && entry.file_size() < 8'000'000) expect_loads(entry.path());
  }
}

TEST(BoundedLoading, DebianBunnyAndThreeDsModelsStillLoad) {
  const fs::path folder = "/usr/share/glmark2/models";
  if (!fs::exists(folder / "bunny.obj")) GTEST_SKIP() << "glmark2-data is not installed";
  expect_loads(folder / "bunny.obj");
  for (const char* name : {"cube.3ds", "horse.3ds", "cat.3ds"}) expect_loads(folder / name);
}

}  // namespace
}  // namespace mhd
