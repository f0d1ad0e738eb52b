#include "command_scene.h"

#include "load_progress.h"

#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"

#include <fmt/core.h>

#include <cstdio>

namespace mhd::cli {

std::optional<SceneDescription> read_command_scene(const std::filesystem::path& file) {
  Result<SceneDescription> read = read_scene_file(file);
  for (const auto& d : read.diagnostics()) fmt::print(stderr, "{}\n", d.to_string());
  if (!read.ok()) return std::nullopt;
  return std::move(read).value();
}

std::unique_ptr<CompiledScene> compile_command_scene(const SceneDescription& scene, bool use_cache) {
  CompileOptions options;
  options.use_cache = use_cache;
  options.progress = stderr_load_progress();
  Result<std::unique_ptr<CompiledScene>> compiled = compile_scene(scene, options);
  for (const auto& d : compiled.diagnostics()) fmt::print(stderr, "{}\n", d.to_string());
  if (!compiled.ok()) return nullptr;
  return std::move(compiled).value();
}

}  // namespace mhd::cli
