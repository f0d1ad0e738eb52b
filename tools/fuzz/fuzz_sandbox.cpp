#include "fuzz_sandbox.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

namespace mhd::fuzz {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void die(const std::string& what) {
  std::fprintf(stderr, "fuzz sandbox: %s\n", what.c_str());
  std::abort();
}

// A closed tetrahedron, 4 triangles (tests/data/scenes/valid/assets/tetrahedron.ply).
constexpr std::string_view kTetrahedronPly = R"(ply
format ascii 1.0
element vertex 4
property float x
property float y
property float z
element face 4
property list uchar int vertex_indices
end_header
0 0 0
10 0 0
0 10 0
0 0 10
3 0 2 1
3 0 1 3
3 0 3 2
3 1 2 3
)";

// Vertices but no faces: the scene compiler must refuse it with a message.
constexpr std::string_view kEmptyPly = R"(ply
format ascii 1.0
element vertex 3
property float x
property float y
property float z
element face 0
property list uchar int vertex_indices
end_header
0 0 0
1 0 0
0 1 0
)";

// Two triangles, one of them degenerate (the loader drops it).
constexpr std::string_view kSmallObj = R"(v 0 0 0
v 1 0 0
v 0 1 0
v 0 0 1
v 2 0 0
f 1 2 3
f 1 3 4
f 1 2 5
)";

constexpr std::string_view kNotAMesh = "this is not a mesh file\n\x01\x02\x03\n";

// Every material name the seed scenes use.
constexpr std::string_view kMaterialsXml = R"(<?xml version="1.0" encoding="UTF-8"?>
<scene version="1" name="materials" unit="mm">
  <material name="dolphin_skin" stiffness_N_per_m="600" damping_Ns_per_m="0.5"
            static_friction="0.3" dynamic_friction="0.2" force_shading="true"/>
  <material name="wall" stiffness_N_per_m="2000" damping_Ns_per_m="1.0"/>
  <material name="rubber" stiffness_N_per_m="400" damping_Ns_per_m="0.8"/>
  <material name="floor" stiffness_N_per_m="1500"/>
  <material name="smooth" stiffness_N_per_m="1000"/>
  <material name="benchmark" stiffness_N_per_m="1000" damping_Ns_per_m="0"/>
  <material name="skin" stiffness_N_per_m="800" static_friction="0.4" dynamic_friction="0.3"/>
  <material name="steel" stiffness_N_per_m="3000"/>
</scene>
)";

constexpr std::string_view kRigXml = R"(<?xml version="1.0" encoding="UTF-8"?>
<scene version="1" name="rig" unit="mm">
  <rig>
    <frame name="is900" parent="world" position="0 2624 0" quaternion_wxyz="0.5 0.5 0.5 -0.5"/>
    <frame name="base_sensor" parent="is900" position="206 0 1443.2" rpy_deg="180 0 180"/>
    <frame name="robot" parent="base_sensor" position="206 0 -370" rpy_deg="0 0 90"/>
    <frame name="phantom" parent="robot" position="-1.6 -235.8 59.2" rpy_deg="90 0 0"/>
    <frame name="base" parent="robot" position="0 0 -810.8" rpy_deg="90 0 0"/>
  </rig>
</scene>
)";

constexpr std::string_view kFloorXml = R"(<?xml version="1.0" encoding="UTF-8"?>
<scene version="1" name="floor_part">
  <object name="floor_part" material="steel">
    <plane size="4 3"/>
  </object>
  <object name="part_tetra" material="steel">
    <scale value="2"/>
    <mesh file="../assets/tetrahedron.ply"/>
    <pose position="1 2 3"/>
  </object>
</scene>
)";

// An include that includes: nested file:line reporting, duplicate names across files.
constexpr std::string_view kIncXml = R"(<?xml version="1.0" encoding="UTF-8"?>
<scene version="1" name="inc" unit="mm">
  <include file="parts/floor.xml"/>
  <object name="inc_obj">
    <mesh file="mesh.obj"/>
    <material stiffness_N_per_m="500"/>
  </object>
</scene>
)";

// Including this from input.xml closes an include cycle.
constexpr std::string_view kCycleXml = R"(<?xml version="1.0" encoding="UTF-8"?>
<scene version="1">
  <include file="input.xml"/>
</scene>
)";

// A broken include: its errors must name it, with its own lines.
constexpr std::string_view kBadXml = R"(<?xml version="1.0" encoding="UTF-8"?>
<scene version="1">
  <object name="bad">
    <box size="1 2"/>
  </object>
  <unclosed>
</scene>
)";

}  // namespace

Sandbox::Sandbox() {
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") + "/mhd_fuzz_scene_XXXXXX";
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  if (mkdtemp(buffer.data()) == nullptr) die("cannot create a folder from " + pattern);
  std::error_code canonical_ec;
  root_ = fs::canonical(fs::path(buffer.data()), canonical_ec);  // mesh paths compare canonical
  if (canonical_ec) die("cannot resolve " + std::string(buffer.data()));
  input_ = root_ / "scenes" / "input.xml";

  write_file("scenes/common/materials.xml", kMaterialsXml);
  write_file("scenes/rigs/pomhi.xml", kRigXml);
  write_file("scenes/parts/floor.xml", kFloorXml);
  write_file("scenes/inc.xml", kIncXml);
  write_file("scenes/cycle.xml", kCycleXml);
  write_file("scenes/bad.xml", kBadXml);
  write_file("scenes/empty.xml", "");
  write_mesh("scenes/assets/tetrahedron.ply", kTetrahedronPly);
  write_mesh("scenes/mesh.obj", kSmallObj);
  write_mesh("scenes/empty.ply", kEmptyPly);
  write_mesh("scenes/not_a_mesh.obj", kNotAMesh);
  for (const char* name : {"assets/tetrahedron.ply", "assets/dolphin.ply", "assets/bowl.ply",
                           "assets/bunny.ply", "assets/generated/dolphin_100k.ply",
                           "assets/generated/dolphin_1m.ply", "assets/generated/uv_sphere_1m.ply",
                           "valid/assets/tetrahedron.ply"}) {
    write_mesh(name, kTetrahedronPly);
  }
  std::error_code ec;
  fs::create_directories(root_ / "scenes" / "dir.ply", ec);  // a mesh "file" that is a folder
  if (ec) die("cannot create " + (root_ / "scenes" / "dir.ply").string());
}

Sandbox::~Sandbox() {
  std::error_code ec;
  fs::remove_all(root_, ec);
}

void Sandbox::write_file(const fs::path& relative, std::string_view text) {
  const fs::path path = root_ / relative;
  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out) die("cannot write " + path.string());
}

void Sandbox::write_mesh(const fs::path& relative, std::string_view text) {
  write_file(relative, text);
  small_meshes_.insert((root_ / relative).lexically_normal());
}

void Sandbox::write_input(const unsigned char* bytes, std::size_t size) const {
  std::FILE* f = std::fopen(input_.c_str(), "wb");
  if (f == nullptr) die("cannot open " + input_.string());
  const bool ok = size == 0 || std::fwrite(bytes, 1, size, f) == size;
  if (std::fclose(f) != 0 || !ok) die("cannot write " + input_.string());
}

bool Sandbox::is_small_mesh(const fs::path& file) const {
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(file, ec);
  return !ec && small_meshes_.contains(canonical);
}

}  // namespace mhd::fuzz
