// libFuzzer target: mesh files before and through assimp (engine/mesh_io). The first
// input byte picks the file name (0: input.ply, 1: input.obj, 2: input.stl, modulo 3);
// the rest is the file. It is checked by check_mesh_header() and loaded by
// load_mesh_file() from a per-process folder that also holds side files an OBJ can name
// with mtllib: side.mtl (regular), fifo.mtl (a FIFO), dir.mtl/ (a folder), loop.mtl (a
// symlink loop), zero.mtl (-> /dev/zero).
//
// The load step runs only with MHD_FUZZ_MESH_LOAD=1: what it finds is in assimp, not
// ours (docs/reliability/fuzzing.md, finding 3), and a short CI run must not fail on a
// library finding met by chance. Without it the target fuzzes the header checks alone.
//
// Invariants (a violation traps; an allocation over -malloc_limit_mb is a crash too, so
// header counts that do not fit the file can never reach assimp):
//  - a refused header says why ("PLY header...", "binary STL...", or the wrong kind: "not a
//    PLY file" for a .ply without the magic word, "not an OBJ file" for a .obj with a NUL
//    in its head), claims nothing, and the loader refuses the file with that same reason;
//  - an accepted binary STL is exactly 84 + 50 * its count bytes; an accepted PLY claims
//    no more faces than it has bytes;
//  - the loader returns a mesh or an error, never both; an error names the file and says
//    why; a mesh has triangles, at most the budget, valid indices and finite vertices;
//  - nothing blocks (a FIFO side file is refused, never opened: -timeout catches a hang).
#include "mesh_io/mesh_header.h"
#include "mesh_io/mesh_loader.h"
#include "mesh_io/ply_header.h"

#include <spdlog/spdlog.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace {

namespace fs = std::filesystem;

constexpr std::array<std::string_view, 3> kNames = {"input.ply", "input.obj", "input.stl"};
constexpr std::uint64_t kBudget = 100'000;

fs::path g_root;

[[noreturn]] void violated(const std::string& what) {
  std::fprintf(stderr, "\n*** mhd-fuzz-mesh-header: invariant violated: %s\n", what.c_str());
  std::fflush(stderr);
  __builtin_trap();
}

void write_file(const fs::path& file, std::string_view bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out.good()) violated("cannot write " + file.string());
}

void make_sandbox() {
  const char* tmp = std::getenv("TMPDIR");
  g_root = fs::path(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") / ("mhd-fuzz-mesh-" + std::to_string(::getpid()));
  fs::remove_all(g_root);
  fs::create_directories(g_root / "dir.mtl");
  write_file(g_root / "side.mtl", "newmtl m\nKd 1 1 1\nmap_Kd dir.mtl\n");
  if (::mkfifo((g_root / "fifo.mtl").c_str(), 0600) != 0) violated("cannot make the FIFO");
  fs::create_symlink("loop.mtl", g_root / "loop.mtl");
  fs::create_symlink("/dev/zero", g_root / "zero.mtl");
  std::atexit([] {
    std::error_code ec;
    fs::remove_all(g_root, ec);
  });
}


}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  spdlog::set_level(spdlog::level::off);
  make_sandbox();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const fs::path file = g_root / kNames[data[0] % kNames.size()];
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  write_file(file, bytes);

  const mhd::MeshHeaderCheck header =
      mhd::check_mesh_header(bytes.substr(0, mhd::kMeshHeaderBytes), bytes.size(), file.extension().string());
  if (!header.ok()) {
    if (!header.error().starts_with("PLY header") && !header.error().starts_with("binary STL") &&
        !header.error().starts_with("not a PLY file") && !header.error().starts_with("not an OBJ file")) {
      violated("a header refusal without its format: " + header.error());
    }
    // A kind refusal only where the kind is wrong: a .ply without the magic word, a .obj
    // with a NUL in the bytes the check reads.
    if (header.error().starts_with("not a PLY file") && (file.extension() != ".ply" || mhd::has_ply_magic(bytes))) {
      violated("a PLY kind refusal of " + file.filename().string() + " with the magic word or another name");
    }
    if (header.error().starts_with("not an OBJ file") &&
        (file.extension() != ".obj" || bytes.substr(0, mhd::kMeshHeaderBytes).find('\0') == std::string_view::npos)) {
      violated("an OBJ kind refusal of " + file.filename().string() + " without a NUL in its head");
    }
  } else if (header->claimed_faces) {
    // The PLY magic wins over the name, as in assimp.
    if (mhd::has_ply_magic(bytes)) {
      if (*header->claimed_faces > bytes.size()) violated("a PLY accepted with more faces than bytes");
    } else if (file.extension() != ".stl" || 84 + 50 * *header->claimed_faces != bytes.size()) {
      violated("a binary STL accepted with the wrong size, or a count from neither PLY nor STL");
    }
  }

  static const bool load = [] {
    const char* v = std::getenv("MHD_FUZZ_MESH_LOAD");
    return v != nullptr && std::string_view(v) == "1";
  }();
  if (!load) return 0;
  const mhd::Result<mhd::LoadedMesh, mhd::MeshLoadError> loaded =
      mhd::load_mesh_file(file, Eigen::Vector3d::Ones(), {}, mhd::TriangleBudget{kBudget});
  if (!loaded.ok()) {
    const mhd::MeshLoadError& error = loaded.error();
    if (error.reason.empty()) violated("an error without a reason");
    if (error.message().find(file.string()) == std::string::npos) violated("an error without the file");
    if (!header.ok() && error.reason != header.error() && !bytes.empty()) {
      violated("the loader refused a bad header differently: " + error.reason);
    }
    return 0;
  }
  if (!header.ok()) violated("the loader accepted a refused header: " + header.error());
  const mhd::TriangleMesh& mesh = loaded->mesh;
  if (mesh.triangles.empty() || mesh.triangles.size() > kBudget) violated("triangle count out of range");
  for (const auto& t : mesh.triangles) {
    for (const auto i : t) {
      if (i >= mesh.vertices_m.size()) violated("an index past the vertices");
    }
  }
  for (const auto& v : mesh.vertices_m) {
    if (!v.allFinite()) violated("a non-finite vertex");
  }
  return 0;
}
