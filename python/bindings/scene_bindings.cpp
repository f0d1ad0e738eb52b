// Scenes from Python: read (XML file or text), validate (every problem as a list, by the
// functions `mhd validate` calls, so the two agree) and compile (meshes, BVHs, the on-disk cache). Reading and
// compiling run without the GIL: a large mesh takes seconds.

#include "bindings.h"
#include "engine_error.h"
#include "scene_handles.h"

#include "haptic_server/run_check.h"
#include "plugin_host/plugin_search_path.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace mhd::python {
namespace {

SceneHandle scene_or_throw(Result<SceneDescription> read) {
  if (!read.ok()) throw EngineError(read.error());
  return SceneHandle{std::make_shared<const SceneDescription>(std::move(*read))};
}

/// compile_scene, with an exception from a mesh library turned into a file-level diagnostic.
Result<std::unique_ptr<CompiledScene>> compile(const SceneDescription& description, const CompileOptions& options) {
  try {
    return compile_scene(description, options);
  } catch (const std::exception& e) {
    return Diagnostic{SourceLocation{description.file.string(), 0}, e.what()};
  }
}

CompileOptions compile_options(bool use_cache, const std::optional<std::filesystem::path>& cache_dir) {
  CompileOptions options;
  options.use_cache = use_cache;
  options.cache_dir = cache_dir;
  return options;
}

std::string_view plugin_kind_name(PluginKind kind) {
  switch (kind) {
    case PluginKind::Device: return "device";
    case PluginKind::Tracker: return "tracker";
    case PluginKind::Base: return "base";
    case PluginKind::Display: return "display";
    case PluginKind::Link: return "link";
  }
  return "unknown";
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<SceneHandle>(m, "Scene", "A scene file as read: what it says, no meshes loaded. Immutable.")
      .def_property_readonly("file", [](const SceneHandle& s) { return s.description->file; })
      .def_property_readonly("name", [](const SceneHandle& s) { return s.description->name; })
      .def_property_readonly("object_names",
                             [](const SceneHandle& s) {
                               std::vector<std::string> names;
                               for (const ObjectDescription& o : s.description->objects) names.push_back(o.name);
                               return names;
                             })
      .def_property_readonly("plugins",
                             [](const SceneHandle& s) {
                               std::vector<std::pair<std::string_view, std::string>> plugins;
                               for (const PluginDescription& p : s.description->plugins) {
                                 plugins.emplace_back(plugin_kind_name(p.kind), p.name);
                               }
                               return plugins;
                             },
                             "[(kind, name)] of <plugins>, in file order")
      .def_property_readonly("max_force_N", [](const SceneHandle& s) { return s.description->haptics.max_force_N; })
      .def_property_readonly("update_rate_Hz",
                             [](const SceneHandle& s) { return s.description->haptics.update_rate_Hz; })
      .def("__repr__", [](const SceneHandle& s) {
        return "<mhd.Scene '" + s.description->name + "' from " + s.description->file.string() + ", " +
               std::to_string(s.description->objects.size()) + " objects>";
      });

  py::class_<CompiledSceneHandle>(m, "CompiledScene",
                                  "A scene ready to touch: collision geometry with BVHs, materials, proxy settings. "
                                  "Immutable; shared by every Proxy and server run made from it.")
      .def_property_readonly("scene", [](const CompiledSceneHandle& c) { return SceneHandle{c.description}; })
      .def_property_readonly("name", [](const CompiledSceneHandle& c) { return c.compiled->name; })
      .def_property_readonly("object_names", [](const CompiledSceneHandle& c) { return c.compiled->object_names; })
      .def_property_readonly("triangle_count", [](const CompiledSceneHandle& c) { return c.compiled->triangle_count; })
      .def_property_readonly("skin_m", [](const CompiledSceneHandle& c) { return c.compiled->proxy.skin_m; })
      .def_property_readonly("max_force_N", [](const CompiledSceneHandle& c) { return c.compiled->proxy.max_force_N; })
      .def("__repr__", [](const CompiledSceneHandle& c) {
        return "<mhd.CompiledScene '" + c.compiled->name + "', " + std::to_string(c.compiled->object_names.size()) +
               " objects, " + std::to_string(c.compiled->triangle_count) + " triangles>";
      });

  m.def(
      "read_scene",
      [](const std::filesystem::path& file) {
        std::optional<Result<SceneDescription>> read;
        {
          py::gil_scoped_release unlocked;
          read.emplace(read_scene_file(file));
        }
        return scene_or_throw(std::move(*read));
      },
      py::arg("file"), "Reads a scene XML file and its includes; MhdError lists every problem at file:line.");
  m.def(
      "read_scene_string",
      [](const std::string& xml, const std::filesystem::path& file) {
        return scene_or_throw(read_scene_string(xml, file));
      },
      py::arg("xml"), py::arg("file"),
      "Reads scene XML text; relative paths resolve against file's folder and messages name file.");
  m.def(
      "validate",
      [](const std::filesystem::path& file, bool meshes, bool use_cache,
         const std::vector<std::filesystem::path>& plugin_path) {
        py::gil_scoped_release unlocked;
        Result<SceneDescription> read = read_scene_file(file);
        if (!read.ok()) return read.diagnostics();
        Diagnostics problems = check_scene_for_validate(*read, PluginSearchPath::standard(plugin_path));
        if (!problems.empty() || !meshes) return problems;
        return compile(*read, compile_options(use_cache, std::nullopt)).diagnostics();
      },
      py::arg("file"), py::arg("meshes") = true, py::arg("use_cache") = true,
      py::arg("plugin_path") = std::vector<std::filesystem::path>{},
      "Every problem of a scene file, exactly as `mhd validate` finds them: read, the settings and "
      "plugins (plugin_path: folders searched first, as --plugin-path), then (meshes=True) compile. "
      "An empty list: the scene is good.");
  m.def(
      "compile_scene",
      [](const SceneHandle& scene, bool use_cache, const std::optional<std::filesystem::path>& cache_dir) {
        std::optional<Result<std::unique_ptr<CompiledScene>>> compiled;
        {
          py::gil_scoped_release unlocked;
          compiled.emplace(compile(*scene.description, compile_options(use_cache, cache_dir)));
        }
        if (!compiled->ok()) throw EngineError(compiled->error());
        return CompiledSceneHandle{scene.description, std::shared_ptr<const CompiledScene>(std::move(*compiled).value())};
      },
      py::arg("scene"), py::arg("use_cache") = true, py::arg("cache_dir") = py::none(),
      "Loads the meshes and builds (or reads from the cache) their BVHs; MhdError names each problem.");
}

}  // namespace mhd::python
