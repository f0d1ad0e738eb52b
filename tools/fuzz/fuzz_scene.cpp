// libFuzzer target: the scene loader. Each input is written to <sandbox>/scenes/input.xml
// (fuzz_sandbox.h) and read with read_scene_file(), so <include> and <mesh file> resolve
// against small helper files (or fail); a scene that reads and names only the sandbox's
// small meshes and few triangles is then compiled (engine/scene_compiler).
//
// Invariants (a violation traps, which libFuzzer reports as a crash):
//  - a rejected scene has diagnostics, each with a message, a file, and a line inside that
//    file (line 0 only for the few whole-file problems listed in kFileLevelMessages);
//  - an accepted scene has no diagnostics and only finite, in-range numbers: positive
//    forces and rates, valid materials, finite poses whose rotations are rotations,
//    positive finite shape sizes, mesh scales in [1e-6, 1e6];
//  - the compiler accepts an accepted scene whose meshes are all good; when it refuses one
//    (a sandbox mesh without faces), it says why, where.
#include "fuzz_sandbox.h"

#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <variant>

namespace {

using mhd::fuzz::Sandbox;

/// Scenes above this many (estimated) triangles are read but not compiled: the fuzzer
/// looks for wrong answers, not for how long a 300k-triangle icosphere takes.
constexpr std::size_t kMaxCompileTriangles = 20000;
constexpr std::size_t kMaxCompileObjects = 64;

/// Diagnostics that may carry line 0: the problem is the whole file.
constexpr std::array<std::string_view, 3> kFileLevelMessages = {
    "malformed XML: the document is empty",
    "malformed XML: no root element",
    "scene file ",
};

Sandbox* g_sandbox = nullptr;

[[noreturn]] void violated(const std::string& what) {
  std::fprintf(stderr, "\n*** mhd-fuzz-scene: invariant violated: %s\n", what.c_str());
  std::fflush(stderr);
  __builtin_trap();
}

/// Lines in a text, line ends as XML 1.0 section 2.11 defines them: LF, CR LF, or a lone
/// CR (a final line without one counts). tinyxml2 counts LF only, so this is the upper
/// bound for its line numbers and for the reader's own counting inside comments.
int line_count(std::string_view text) {
  int lines = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'))) ++lines;
  }
  return lines;
}

/// Lines of `file` when it is a sandbox file (the input or a helper), else -1 (unknown).
/// Helper files never change, so their counts are kept across runs.
int known_line_count(const std::string& file, std::string_view input) {
  static std::map<std::string, int> cache;
  if (file == g_sandbox->input_file().string()) return line_count(input);
  const std::string root = g_sandbox->root().string() + "/";
  if (file.rfind(root, 0) != 0) return -1;
  if (const auto it = cache.find(file); it != cache.end()) return it->second;
  std::ifstream in(file, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const int n = in ? line_count(text) : -1;
  cache.emplace(file, n);
  return n;
}

void check_diagnostics(const mhd::Diagnostics& diagnostics, std::string_view input, const char* stage) {
  for (const mhd::Diagnostic& d : diagnostics) {
    const std::string text = d.to_string();
    if (d.message.empty()) violated(std::string(stage) + ": a diagnostic without a message: " + text);
    if (d.where.file.empty()) violated(std::string(stage) + ": a diagnostic without a file: " + text);
    if (d.where.line < 0) violated(std::string(stage) + ": negative line: " + text);
    if (d.where.line == 0) {
      const bool file_level = std::any_of(kFileLevelMessages.begin(), kFileLevelMessages.end(),
                                          [&](std::string_view m) { return d.message.rfind(m, 0) == 0; });
      if (!file_level) violated(std::string(stage) + ": a diagnostic without a line: " + text);
    }
    const int n = known_line_count(d.where.file, input);
    if (n > 0 && d.where.line > n) {
      violated(std::string(stage) + ": line " + std::to_string(d.where.line) + " beyond the file's " +
               std::to_string(n) + " lines: " + text);
    }
  }
}

bool positive_finite(double x) { return std::isfinite(x) && x > 0.0; }
bool non_negative_finite(double x) { return std::isfinite(x) && x >= 0.0; }

void check_pose(const mhd::Pose& X, const std::string& what) {
  if (!X.matrix().allFinite()) violated(what + ": pose is not finite");
  const Eigen::Matrix3d R = X.linear();
  if (!(R.transpose() * R).isIdentity(1e-9) || R.determinant() < 0.0) {
    violated(what + ": pose rotation is not a rotation");
  }
}

void check_material(const mhd::HapticMaterial& m, const std::string& what) {
  if (!positive_finite(m.stiffness_N_per_m) || !non_negative_finite(m.damping_Ns_per_m) ||
      !non_negative_finite(m.static_friction) || !non_negative_finite(m.dynamic_friction) ||
      m.dynamic_friction > m.static_friction) {
    violated(what + ": invalid material values");
  }
}

/// Estimated triangles of `object` (0 for meshes: sandbox meshes are tiny).
std::size_t triangles_of(const mhd::ObjectDescription& object) {
  struct Count {
    std::size_t operator()(const mhd::MeshSource&) const { return 8; }
    std::size_t operator()(const mhd::PlaneSource&) const { return 2; }
    std::size_t operator()(const mhd::BoxSource&) const { return 12; }
    std::size_t operator()(const mhd::SphereSource& s) const {
      return s.subdivisions < 0 || s.subdivisions > 12 ? SIZE_MAX : 20u << (2 * s.subdivisions);
    }
    std::size_t operator()(const mhd::CylinderSource& s) const {
      return s.segments < 0 ? SIZE_MAX : 4 * static_cast<std::size_t>(s.segments);
    }
    std::size_t operator()(const mhd::CapsuleSource& s) const {
      return s.segments < 0 ? SIZE_MAX : static_cast<std::size_t>(s.segments) * static_cast<std::size_t>(s.segments);
    }
  };
  return std::visit(Count{}, object.shape);
}

/// Checks an accepted scene; returns whether it is cheap and self-contained enough to
/// compile, and (through `bad_mesh`) whether it names a sandbox mesh that cannot load.
bool check_scene(const mhd::SceneDescription& scene, bool& bad_mesh) {
  if ((scene.haptics.max_force_N && !positive_finite(*scene.haptics.max_force_N)) || !positive_finite(scene.haptics.update_rate_Hz)) {
    violated("haptics values not positive and finite");
  }
  for (const auto& [name, material] : scene.materials) {
    if (name.empty()) violated("a material without a name");
    check_material(material, "material '" + name + "'");
  }
  bool compilable = scene.objects.size() <= kMaxCompileObjects;
  std::size_t triangles = 0;
  bad_mesh = false;
  for (const mhd::ObjectDescription& object : scene.objects) {
    const std::string what = "object '" + object.name + "'";
    if (object.name.empty()) violated("an object without a name");
    if (object.where.file.empty() || object.where.line <= 0) violated(what + ": no file:line");
    check_pose(object.X_WO, what);
    check_material(object.material, what);
    if (const auto* mesh = std::get_if<mhd::MeshSource>(&object.shape)) {
      if (!mesh->scale_to_m.allFinite() || mesh->scale_to_m.minCoeff() < 1e-6 || mesh->scale_to_m.maxCoeff() > 1e6) {
        violated(what + ": mesh scale outside [1e-6, 1e6]");
      }
      if (!mesh->file.is_absolute()) violated(what + ": mesh path not absolute: " + mesh->file.string());
      if (!g_sandbox->is_small_mesh(mesh->file)) compilable = false;
      const std::string leaf = mesh->file.filename().string();
      if (leaf == "empty.ply" || leaf == "not_a_mesh.obj") bad_mesh = true;
    } else if (const auto* plane = std::get_if<mhd::PlaneSource>(&object.shape)) {
      if (!positive_finite(plane->size_x_m) || !positive_finite(plane->size_y_m)) violated(what + ": plane size");
    } else if (const auto* sphere = std::get_if<mhd::SphereSource>(&object.shape)) {
      if (!positive_finite(sphere->radius_m) || sphere->subdivisions < 0 || sphere->subdivisions > 7) {
        violated(what + ": sphere radius or subdivisions");
      }
    } else if (const auto* box = std::get_if<mhd::BoxSource>(&object.shape)) {
      if (!box->size_m.allFinite() || box->size_m.minCoeff() <= 0.0) violated(what + ": box size");
    } else if (const auto* cylinder = std::get_if<mhd::CylinderSource>(&object.shape)) {
      if (!positive_finite(cylinder->radius_m) || !positive_finite(cylinder->height_m) || cylinder->segments < 3 ||
          cylinder->segments > 4096) {
        violated(what + ": cylinder radius, height or segments");
      }
    } else if (const auto* capsule = std::get_if<mhd::CapsuleSource>(&object.shape)) {
      if (!positive_finite(capsule->radius_m) || !positive_finite(capsule->length_m) || capsule->segments < 3 ||
          capsule->segments > 4096) {
        violated(what + ": capsule radius, length or segments");
      }
    }
    const std::size_t t = triangles_of(object);
    triangles = t > kMaxCompileTriangles ? SIZE_MAX : triangles + t;
    if (triangles > kMaxCompileTriangles) compilable = false;
  }
  for (const mhd::FrameDescription& frame : scene.rig_frames) {
    if (frame.name.empty() || frame.parent.empty() || frame.name == "world") violated("rig frame names");
    check_pose(frame.X_PF, "rig frame '" + frame.name + "'");
  }
  for (const mhd::PluginDescription& plugin : scene.plugins) {
    if (plugin.name.empty()) violated("a plugin without a name");
  }
  return compilable;
}

void compile_and_check(const mhd::SceneDescription& scene, bool bad_mesh, std::string_view input) {
  mhd::CompileOptions options;
  options.use_cache = false;  // nothing written; every mesh comes from its file
  const mhd::Result<std::unique_ptr<mhd::CompiledScene>> compiled = mhd::compile_scene(scene, options);
  if (!compiled.ok()) {
    if (compiled.diagnostics().empty()) violated("compile: refused without a diagnostic");
    check_diagnostics(compiled.diagnostics(), input, "compile");
    if (!bad_mesh) {
      violated("compile: refused a scene the reader accepted: " + compiled.diagnostics().front().to_string());
    }
    return;
  }
  if (!compiled.diagnostics().empty()) violated("compile: a compiled scene with diagnostics");
  const mhd::CompiledScene& c = *compiled.value();
  if (static_cast<std::size_t>(c.world.object_count()) != scene.objects.size() ||
      c.materials.size() != scene.objects.size() || c.object_names.size() != scene.objects.size()) {
    violated("compile: object counts differ from the description");
  }
  if (!scene.objects.empty() && c.triangle_count == 0) violated("compile: objects but no triangles");
  if (!std::isfinite(c.proxy.max_force_N) || c.proxy.max_force_N <= 0.0) violated("compile: proxy max force");
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  spdlog::set_level(spdlog::level::off);
  static Sandbox sandbox;  // removed at exit
  g_sandbox = &sandbox;
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  g_sandbox->write_input(data, size);
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const mhd::Result<mhd::SceneDescription> result = mhd::read_scene_file(g_sandbox->input_file());
  if (!result.ok()) {
    if (result.diagnostics().empty()) violated("read: rejected without a diagnostic");
    check_diagnostics(result.diagnostics(), input, "read");
    return 0;
  }
  if (!result.diagnostics().empty()) violated("read: accepted with diagnostics");
  bool bad_mesh = false;
  if (check_scene(*result, bad_mesh)) compile_and_check(*result, bad_mesh, input);
  return 0;
}
