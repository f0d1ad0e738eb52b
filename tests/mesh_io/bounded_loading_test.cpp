// Loading within bounds, through load_mesh_file and real files: each
// hostile input is refused at once with its exact message, and good meshes still load.
#include "mesh_io/available_memory.h"
#include "mesh_io/mesh_loader.h"
#include "mesh_io/read_memory_limit.h"
#include "test_mesh_files.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
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

TEST(BoundedLoading, AReadThatOutgrowsItsMemoryIsStoppedAndSaidSo) {
  // Found by tools/fuzz/probe_importers.py: assimp 5.2.5's NFF reader, given a polygon
  // patch claiming 99,999,999,993 vertices, grew to 21.8 GB in the 30 s of its time limit
  // (a COLLADA file with a cut index list to 11 GB). The reader may take 1 GiB and 256
  // bytes for each byte of the files it opens; an allocation past that ends the read.
  if (!ReadMemoryLimit::kInThisBuild) GTEST_SKIP() << "no memory limit in a sanitizer build (read_memory_limit.h)";
  TempDir dir;
  test::write_text(dir / "patch.nff", "pp 99999999993\n03\n00 90 09993\n\n1 0 0\n0 1 0\n");
  const std::string reason = reason_of(load_mesh_file(dir / "patch.nff", Eigen::Vector3d::Ones()));
  EXPECT_EQ(reason.rfind("assimp needed more than 1.0 GiB of memory to read it (", 0), 0u) << reason;
  // The dual: a mesh read within a small allowance loads, and no allowance stops it.
  test::write_binary_ply(dir / "sheet.ply", test::sheet_mesh(40));
  const auto limited = [](std::uint64_t base_bytes, double per_file_byte) {
    MeshReadLimits limits;
    limits.memory_base_bytes = base_bytes;
    limits.memory_per_file_byte = per_file_byte;
    return limits;
  };
  const Result<LoadedMesh, MeshLoadError> within =
      load_mesh_file(dir / "sheet.ply", Eigen::Vector3d::Ones(), {}, std::nullopt, limited(0, 256.0));
  ASSERT_TRUE(within.ok()) << within.error_text();
  EXPECT_EQ(within->mesh.triangle_count(), 2u * 40 * 40);
  const std::string none =
      reason_of(load_mesh_file(dir / "sheet.ply", Eigen::Vector3d::Ones(), {}, std::nullopt, limited(0, 0.0)));
  EXPECT_EQ(none.rfind("assimp needed more than 0 bytes of memory to read it (", 0), 0u) << none;
}

/// What a child process wrote and how it ended.
struct ChildRun {
  int status = 0;
  std::string out;
};

/// Runs `body` in a child process in which no process or thread can start: clone, clone3
/// and fork fail with ENOMEM, as fork does for a large process under strict overcommit.
/// The child writes what `body` returns; status 2 and "no filter: ..." if the kernel
/// refused the filter.
ChildRun run_where_nothing_can_start(const std::function<std::string()>& body) {
  std::array<int, 2> ends{};
  if (::pipe(ends.data()) != 0) return {-1, "no pipe"};
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(ends[0]);
    std::array<sock_filter, 6> filter{{
        BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, nr)),
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, __NR_clone, 3, 0),
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, __NR_clone3, 2, 0),
#ifdef __NR_fork
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, __NR_fork, 1, 0),
#else
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, __NR_clone, 1, 0),
#endif
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW),
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ERRNO | (ENOMEM & SECCOMP_RET_DATA)),
    }};
    sock_fprog program{static_cast<unsigned short>(filter.size()), filter.data()};
    std::string out;
    int status = 0;
    if (::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0 ||
        ::syscall(SYS_seccomp, SECCOMP_SET_MODE_FILTER, 0, &program) != 0) {
      out = fmt::format("no filter: {}", std::strerror(errno));
      status = 2;
    } else {
      out = body();
    }
    (void)!::write(ends[1], out.data(), out.size());
    ::_exit(status);  // nothing of the test process's runs twice
  }
  ::close(ends[1]);
  ChildRun run;
  std::array<char, 4096> buffer{};
  for (ssize_t n; (n = ::read(ends[0], buffer.data(), buffer.size())) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    run.out.append(buffer.data(), static_cast<std::size_t>(n));
  }
  ::close(ends[0]);
  while (::waitpid(pid, &run.status, 0) < 0 && errno == EINTR) {
  }
  return run;
}

/// A loaded mesh as text, every coordinate exact.
std::string mesh_text(const Result<LoadedMesh, MeshLoadError>& r) {
  if (!r.ok()) return "error: " + r.error_text();
  std::string text = fmt::format("{} triangles:", r->mesh.triangle_count());
  for (const auto& t : r->mesh.triangles) text += fmt::format(" {} {} {}", t[0], t[1], t[2]);
  for (const auto& v : r->mesh.vertices_m) text += fmt::format(" ({:a} {:a} {:a})", v.x(), v.y(), v.z());
  return text;
}

TEST(BoundedLoading, WhenNoReaderProcessCanStartTheFileIsReadHereAndSaidSo) {
  TempDir dir;
  test::write_binary_ply(dir / "sheet.ply", test::sheet_mesh(6));
  const Result<LoadedMesh, MeshLoadError> apart = load_mesh_file(dir / "sheet.ply", Eigen::Vector3d::Ones());
  ASSERT_TRUE(apart.ok()) << apart.error_text();
  EXPECT_EQ(apart->unisolated_read, "");  // read in a child process, as always where one starts

  const ChildRun here = run_where_nothing_can_start([&] {
    const Result<LoadedMesh, MeshLoadError> r = load_mesh_file(dir / "sheet.ply", Eigen::Vector3d::Ones());
    return (r.ok() ? r->unisolated_read : std::string()) + "\n" + mesh_text(r);
  });
  if (WIFEXITED(here.status) && WEXITSTATUS(here.status) == 2) GTEST_SKIP() << here.out;
  ASSERT_TRUE(WIFEXITED(here.status) && WEXITSTATUS(here.status) == 0) << here.status << " " << here.out;
  const std::size_t line = here.out.find('\n');
  ASSERT_NE(line, std::string::npos) << here.out;
  EXPECT_EQ(here.out.substr(0, line), "cannot start a process for the reader: Cannot allocate memory");
  // The same mesh, bit for bit, as the child process read.
  EXPECT_EQ(here.out.substr(line + 1), mesh_text(apart));
  // And a file assimp refuses is refused the same way read here.
  test::write_text(dir / "bad.obj", "v 0 0 0\nf 1 2 3\n");
  const std::string refused_apart = reason_of(load_mesh_file(dir / "bad.obj", Eigen::Vector3d::Ones()));
  const ChildRun refused_here =
      run_where_nothing_can_start([&] { return reason_of(load_mesh_file(dir / "bad.obj", Eigen::Vector3d::Ones())); });
  EXPECT_NE(refused_apart, "(loaded)");
  EXPECT_EQ(refused_here.out, refused_apart);
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
