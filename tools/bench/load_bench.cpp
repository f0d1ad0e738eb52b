// mhd-load-bench: time from scene XML to touchable (read + mesh load + BVH), cold (empty
// BVH cache) and cached, repeated; prints median and max of each.

#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"
#include "verification/stroke_run.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace {

// Seconds from XML to a compiled scene; negative on failure.
double load_seconds(const std::string& file, const std::filesystem::path& cache_dir) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto read = mhd::read_scene_file(file);
  if (!read.ok()) return -1.0;
  mhd::CompileOptions options;
  options.cache_dir = cache_dir;
  const auto compiled = mhd::compile_scene(*read, options);
  if (!compiled.ok()) {
    for (const auto& d : compiled.diagnostics()) fmt::print(stderr, "{}\n", d.to_string());
    return -1.0;
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> scenes = {"scenes/benchmarks/dolphin_1m.xml", "scenes/benchmarks/uv_sphere_1m.xml"};
  int repeats = 3;
  CLI::App app{"Scene load benchmark: XML to touchable, cold and with the BVH cache", "mhd-load-bench"};
  app.add_option("scenes", scenes, "Scene files");
  app.add_option("--repeats", repeats, "Runs of each kind")->check(CLI::Range(1, 100));
  CLI11_PARSE(app, argc, argv);

  const auto cache_dir = std::filesystem::temp_directory_path() / "mhd-load-bench-cache";
  fmt::print("| scene | cold median s | cold max s | cached median s | cached max s |\n|---|---|---|---|---|\n");
  for (const auto& file : scenes) {
    std::vector<double> cold, cached;
    for (int i = 0; i < repeats; ++i) {
      std::filesystem::remove_all(cache_dir);
      cold.push_back(load_seconds(file, cache_dir));  // builds and writes the cache
      cached.push_back(load_seconds(file, cache_dir));
    }
    if (std::any_of(cold.begin(), cold.end(), [](double s) { return s < 0; }) ||
        std::any_of(cached.begin(), cached.end(), [](double s) { return s < 0; })) {
      fmt::print(stderr, "{}: failed to load\n", file);
      return 1;
    }
    std::vector<double> cold_us, cached_us;
    for (double s : cold) cold_us.push_back(s);
    for (double s : cached) cached_us.push_back(s);
    const auto c = mhd::verify::summarize_latency(cold_us);
    const auto w = mhd::verify::summarize_latency(cached_us);
    fmt::print("| {} | {:.3f} | {:.3f} | {:.3f} | {:.3f} |\n", file, c.median_us, c.max_us, w.median_us, w.max_us);
  }
  std::filesystem::remove_all(cache_dir);
  return 0;
}
