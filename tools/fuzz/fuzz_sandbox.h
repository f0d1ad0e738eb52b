#pragma once
// A per-process folder of small files that fuzzed scenes can include and reference:
// the layout mirrors the repository around scenes/, so the seed corpus (scenes/*.xml,
// tests/data/scenes/**) finds the includes and meshes it names, all of them tiny.
//
//   <root>/scenes/input.xml          the fuzz input (rewritten on every run)
//   <root>/scenes/common/materials.xml, rigs/pomhi.xml, parts/floor.xml, inc.xml, ...
//   <root>/scenes/assets/*.ply, mesh.obj, empty.ply (no faces), not_a_mesh.obj, dir.ply/
//   <root>/assets/**.ply, <root>/valid/assets/tetrahedron.ply
//
// Every mesh file in it is a handful of triangles, so compiling a scene that names only
// these stays cheap.

#include <cstddef>
#include <filesystem>
#include <set>
#include <string_view>

namespace mhd::fuzz {

class Sandbox {
 public:
  /// Creates the folder under $TMPDIR (or /tmp); aborts when it cannot.
  Sandbox();
  ~Sandbox();
  Sandbox(const Sandbox&) = delete;
  Sandbox& operator=(const Sandbox&) = delete;

  [[nodiscard]] const std::filesystem::path& root() const { return root_; }
  /// <root>/scenes/input.xml.
  [[nodiscard]] const std::filesystem::path& input_file() const { return input_; }
  /// Replaces input.xml with `bytes`; aborts when it cannot.
  void write_input(const unsigned char* bytes, std::size_t size) const;
  /// Whether `file` (absolute) is one of the sandbox's own small mesh files.
  [[nodiscard]] bool is_small_mesh(const std::filesystem::path& file) const;

 private:
  void write_file(const std::filesystem::path& relative, std::string_view text);
  void write_mesh(const std::filesystem::path& relative, std::string_view text);

  std::filesystem::path root_;
  std::filesystem::path input_;
  std::set<std::filesystem::path> small_meshes_;
};

}  // namespace mhd::fuzz
