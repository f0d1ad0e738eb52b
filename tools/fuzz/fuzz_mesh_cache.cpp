// libFuzzer target: the mesh cache's entry reader (engine/mesh_io/mesh_cache.h), which
// maps an entry and adopts its Bullet tree in place. The input edits a real entry of a
// small sphere, or replaces it, and may seal it (mesh_cache_entry::seal rewrites both
// checksums), so the fuzzer reaches the checks behind the checksums: counts, index
// ranges, vertex data and the tree itself.
//
// Input: byte 0 holds the mode; bit 0: the rest is the whole entry, else the rest is
// 3-byte edits (offset, little-endian 16 bits, modulo the entry's size; then the byte to
// write); bit 1: seal the result; bit 2: cut the entry to the size byte 1 and 2 say
// (modulo its size plus one), before the edits.
//
// Invariants (a violation traps):
//  - the load of a good mesh file never fails, whatever the entry holds;
//  - a rejected entry gives a reason and the mesh rebuilt from the file;
//  - an adopted entry gives a mesh whose indices are in range and whose data are finite,
//    whose face normals are its triangles' own, and whose tree finds each of its triangles by
//    that triangle's own box.
#include "collision/segment_triangle.h"
#include "geometry/primitive_mesh.h"
#include "mesh_io/mesh_cache.h"
#include "mesh_io/mesh_cache_entry.h"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <span>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

[[noreturn]] void violated(const std::string& what) {
  std::fprintf(stderr, "\n*** mhd-fuzz-mesh-cache: invariant violated: %s\n", what.c_str());
  std::fflush(stderr);
  __builtin_trap();
}

std::vector<char> read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A sphere of 320 triangles as an OBJ file, its cache folder and a good entry of it.
struct Fixture {
  fs::path dir = fs::temp_directory_path() / ("mhd_fuzz_mesh_cache_" + std::to_string(::getpid()));
  fs::path mesh_file = dir / "sphere.obj";
  fs::path cache_dir = dir / "cache";
  fs::path entry;
  std::vector<char> good_entry;
  mhd::TriangleMesh mesh;

  Fixture() {
    spdlog::set_level(spdlog::level::off);
    fs::remove_all(dir);
    fs::create_directories(cache_dir);
    const mhd::TriangleMesh sphere = mhd::make_sphere_mesh(0.05, 2);
    {
      std::ofstream out(mesh_file);
      for (const auto& v : sphere.vertices_m) out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
      for (const auto& t : sphere.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    }
    mhd::MeshCache cache(cache_dir);
    const auto cold = cache.load(mesh_file, Eigen::Vector3d::Ones());
    if (!cold.ok() || !cold->written) violated("the fixture's entry was not written");
    entry = cold->cache_file;
    good_entry = read_bytes(entry);
    mesh = cold->mesh();
  }
  ~Fixture() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  Fixture(const Fixture&) = delete;
  Fixture& operator=(const Fixture&) = delete;
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

std::vector<char> entry_from(const std::uint8_t* data, std::size_t size, const std::vector<char>& good) {
  const std::uint8_t mode = data[0];
  if ((mode & 1U) != 0) return {data + 1, data + size};
  std::vector<char> entry = good;
  std::size_t at = 1;
  if ((mode & 4U) != 0 && size >= 3) {
    entry.resize((data[1] | (std::size_t{data[2]} << 8U)) % (entry.size() + 1));
    at = 3;
  }
  for (; at + 3 <= size && !entry.empty(); at += 3) {
    const std::size_t offset = (data[at] | (std::size_t{data[at + 1]} << 8U)) % entry.size();
    entry[offset] = static_cast<char>(data[at + 2]);
  }
  return entry;
}

void check_adopted(const mhd::CachedMesh& hit) {
  const mhd::TriangleMesh& m = hit.mesh();
  for (const auto& t : m.triangles) {
    for (const auto v : t) {
      if (v >= m.vertices_m.size()) violated("an adopted triangle names a vertex past the end");
    }
  }
  for (std::size_t i = 0; i < m.vertices_m.size(); ++i) {
    if (!m.vertices_m[i].allFinite() || !m.vertex_normals.at(i).allFinite()) violated("adopted non-finite data");
  }
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
    const auto& c = m.triangles[t];
    const Eigen::Vector3d n = mhd::unit_face_normal(m.vertices_m[c[0]], m.vertices_m[c[1]], m.vertices_m[c[2]]);
    if (!((hit.bvh->face_normal_O(t) - n).cwiseAbs().maxCoeff() <= mhd::MeshBvh::kFaceNormalTolerance)) {
      violated("an adopted face normal is not its triangle's: " + std::to_string(t));
    }
  }
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
    Eigen::AlignedBox3d box;
    for (const auto v : m.triangles[t]) box.extend(m.vertices_m[v]);
    bool found = false;
    hit.bvh->for_each_triangle_overlapping(box, [&](std::uint32_t i) { found = found || i == t; });
    if (!found) violated("the adopted tree misses triangle " + std::to_string(t));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  Fixture& f = fixture();
  std::vector<char> entry = entry_from(data, size, f.good_entry);
  if ((data[0] & 2U) != 0) mhd::mesh_cache_entry::seal(std::as_writable_bytes(std::span(entry)));
  {
    std::ofstream out(f.entry, std::ios::binary | std::ios::trunc);
    out.write(entry.data(), static_cast<std::streamsize>(entry.size()));
    if (!out) violated("cannot write the entry");
  }
  try {
    mhd::MeshCache cache(f.cache_dir);
    const auto loaded = cache.load(f.mesh_file, Eigen::Vector3d::Ones());
    if (!loaded.ok()) violated("a good mesh file failed to load: " + loaded.error_text());
    switch (loaded->outcome) {
      case mhd::CacheOutcome::Hit: check_adopted(*loaded); break;
      case mhd::CacheOutcome::Rejected:
      case mhd::CacheOutcome::Miss:
        if (loaded->outcome == mhd::CacheOutcome::Rejected && loaded->rejected_reason.empty()) {
          violated("rejected without a reason");
        }
        if (loaded->mesh().triangles != f.mesh.triangles || loaded->mesh().vertices_m != f.mesh.vertices_m) {
          violated("the rebuilt mesh is not the file's");
        }
        break;
      case mhd::CacheOutcome::Disabled: violated("the cache was disabled");
    }
  } catch (const std::exception& e) {
    violated(std::string("an exception escaped: ") + e.what());
  }
  return 0;
}
