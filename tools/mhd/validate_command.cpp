#include "validate_command.h"

#include "load_progress.h"

#include "command_exit.h"
#include "haptic_server/run_check.h"
#include "plugin_host/plugin_search_path.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"
#include "rig_scale_check.h"
#include "world_size_check.h"

#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace {

struct ValidateOptions {
  std::vector<std::string> files;
  std::vector<std::string> plugin_paths;
  bool no_meshes = false;
  bool no_cache = false;
};

void print_diagnostics(const mhd::Diagnostics& diagnostics) {
  for (const mhd::Diagnostic& d : diagnostics) fmt::print(stderr, "{}\n", d.to_string());
}

/// Diagnostic::to_string says "error"; a warning leaves the scene good.
void print_warning(const mhd::Diagnostic& w) {
  fmt::print(stderr, "{}{}: warning: {}\n", w.where.file, w.where.line > 0 ? fmt::format(":{}", w.where.line) : "",
             w.message);
}

/// Loads meshes and builds the collision scene; prints the ok line or the problems.
bool compile_and_report(const std::string& file, const mhd::SceneDescription& scene,
                        const ValidateOptions& options) {
  mhd::CompileOptions compile_options;
  compile_options.use_cache = !options.no_cache;
  compile_options.progress = mhd::cli::stderr_load_progress();
  const mhd::Result<std::unique_ptr<mhd::CompiledScene>> compiled = mhd::compile_scene(scene, compile_options);
  print_diagnostics(compiled.diagnostics());
  if (!compiled.ok()) return false;
  fmt::print("{}: ok ({} objects, {} triangles)\n", file, scene.objects.size(),
             compiled.value()->triangle_count);
  const mhd::cli::WorldSize size = mhd::cli::check_world_size(scene, *compiled.value());
  for (const mhd::cli::ObjectExtents& o : size.objects) {
    fmt::print("  {}: {:.4g} x {:.4g} x {:.4g} m (x, y, z in its own frame)\n", o.name, o.size_m.x(), o.size_m.y(),
               o.size_m.z());
  }
  if (size.warning) print_warning(*size.warning);
  return true;
}

bool validate_file(const std::string& file, const ValidateOptions& options) {
  spdlog::debug("validating {}", file);
  const mhd::Result<mhd::SceneDescription> read = mhd::read_scene_file(file);
  print_diagnostics(read.diagnostics());
  if (!read.ok()) return false;
  // The settings (<server>, <simulated_user>) by run's own function, then the plugins, by
  // the function Python's mhd.validate calls too. What a file may leave to the scene that
  // includes it (the rig's frames, the plugins a run needs) is run's to refuse.
  const std::vector<std::filesystem::path> command_line(options.plugin_paths.begin(), options.plugin_paths.end());
  const mhd::Diagnostics problems =
      mhd::check_scene_for_validate(*read, mhd::PluginSearchPath::standard(command_line));
  if (!problems.empty()) {
    print_diagnostics(problems);
    return false;
  }
  if (const std::optional<mhd::Diagnostic> w = mhd::cli::check_rig_scale(*read)) print_warning(*w);
  if (options.no_meshes) {
    fmt::print("{}: ok ({} objects, meshes not loaded)\n", file, read->objects.size());
    return true;
  }
  try {
    return compile_and_report(file, *read, options);
  } catch (const std::exception& e) {
    fmt::print(stderr, "{}: error: {}\n", file, e.what());
    return false;
  }
}

}  // namespace

void add_validate_command(CLI::App& app) {
  auto options = std::make_shared<ValidateOptions>();
  CLI::App* validate = app.add_subcommand(
      "validate", "Check scene files: read and (unless --no-meshes) compile each one");
  validate->add_option("files", options->files, "Scene XML files")->required()->type_name("FILE");
  validate->add_option("--plugin-path", options->plugin_paths, "Look for plugins in this folder first (repeatable)")
      ->type_name("DIR")
      ->allow_extra_args(false);
  validate->add_flag("--no-meshes", options->no_meshes,
                     "Only read the XML (mesh files must exist but are not loaded)");
  validate->add_flag("--no-cache", options->no_cache,
                     "Neither read nor write the BVH cache while compiling");
  validate->footer(
      "Each <plugin> is found and loaded (never opened) and its <param>s are checked against\n"
      "the plugin's declarations (mhd plugins --describe NAME), as mhd run does before it opens it.\n"
      "Diagnostics go to stderr as FILE:LINE: error: MESSAGE; each good file prints\n"
      "FILE: ok (N objects, M triangles), then each object's extents in metres. A world whose\n"
      "objects are all under 1 cm or all over 1 km gets FILE:LINE: warning: (a unit mistake?).\n"
      "Exit status 0 if every file is good (warnings included), else 1.");
  validate->callback([options] {
    bool all_good = true;
    for (const std::string& file : options->files) {
      all_good = validate_file(file, *options) && all_good;
    }
    mhd::cli::exit_with(all_good ? 0 : 1);
  });
}
