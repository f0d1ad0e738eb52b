#include "scene_fixture.h"

#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"

#include <stdexcept>
#include <system_error>

#ifndef MHD_SOURCE_DIR
#error "MHD_SOURCE_DIR must name the source tree (set by tests/support/CMakeLists.txt)"
#endif
#ifndef MHD_TEST_BVH_CACHE_DIR
#error "MHD_TEST_BVH_CACHE_DIR must name a folder in the build tree"
#endif

namespace mhd::test {
namespace {

std::string join(const Diagnostics& diagnostics) {
  std::string text;
  for (const Diagnostic& d : diagnostics) {
    text += "\n  ";
    text += d.to_string();
  }
  return text;
}

}  // namespace

std::filesystem::path SceneFixture::source_path(const std::string& relative) {
  return std::filesystem::path(MHD_SOURCE_DIR) / relative;
}

std::filesystem::path SceneFixture::bvh_cache_dir() { return std::filesystem::path(MHD_TEST_BVH_CACHE_DIR); }

void SceneFixture::load(const std::string& scene_path_relative_to_repo) {
  scene_.reset();
  oracle_.reset();
  const std::filesystem::path file = source_path(scene_path_relative_to_repo);
  Result<SceneDescription> read = read_scene_file(file);
  ASSERT_TRUE(read.ok() && read.diagnostics().empty())
      << "reading " << file.string() << " failed:" << join(read.diagnostics());

  std::error_code ignored;
  std::filesystem::create_directories(bvh_cache_dir(), ignored);
  CompileOptions options;
  options.cache_dir = bvh_cache_dir();
  Result<std::unique_ptr<CompiledScene>> compiled = compile_scene(*read, options);
  ASSERT_TRUE(compiled.ok() && compiled.diagnostics().empty())
      << "compiling " << file.string() << " failed:" << join(compiled.diagnostics());

  scene_ = std::move(compiled).value();
  rebuild_oracle();
}

int SceneFixture::object(const std::string& name) {
  for (std::size_t i = 0; i < scene().object_names.size(); ++i) {
    if (scene().object_names[i] == name) return static_cast<int>(i);
  }
  ADD_FAILURE() << "no object " << name;
  return 0;
}

void SceneFixture::rebuild_oracle() {
  if (scene_) oracle_ = std::make_unique<SurfaceCrossingOracle>(scene_->world);
}

TickRecord SceneFixture::drive(const std::vector<Eigen::Vector3d>& hip_path_W, double rate_Hz) {
  if (!scene_) {
    ADD_FAILURE() << "SceneFixture::drive: no scene loaded";
    return {};
  }
  if (!hip_path_W.empty() && oracle_->point_touches_surface(hip_path_W.front())) {
    ADD_FAILURE() << "SceneFixture::drive: the first HIP sample is on the surface; the proxy needs free space";
    return {};
  }
  if (!hip_path_W.empty() && oracle_->point_inside_closed_mesh(hip_path_W.front())) {
    ADD_FAILURE() << "SceneFixture::drive: the first HIP sample is inside a closed object";
    return {};
  }
  return drive_proxy(*scene_, hip_path_W, rate_Hz);
}

const SurfaceCrossingOracle& SceneFixture::oracle() const {
  // GoogleTest reports the exception as this test's failure.
  if (!oracle_) throw std::logic_error("SceneFixture: no scene loaded");
  return *oracle_;
}

CompiledScene& SceneFixture::scene() {
  if (!scene_) throw std::logic_error("SceneFixture: no scene loaded");
  return *scene_;
}

std::size_t SceneFixture::count_crossings(const TickRecord& records) const {
  return mhd::test::count_crossings(oracle(), records);
}

std::vector<Crossing> SceneFixture::find_crossings(const TickRecord& records) const {
  return mhd::test::find_crossings(oracle(), records);
}

std::size_t SceneFixture::count_ticks_inside(const TickRecord& records) const {
  return mhd::test::count_ticks_inside(oracle(), records);
}

StrokeSet SceneFixture::anchor_strokes(std::uint64_t seed, int count, const AnchorStrokeParams& params) const {
  return make_anchor_strokes(oracle(), seed, count, params);
}

StrokeSet SceneFixture::fast_strokes(std::uint64_t seed, int count, const FastStrokeParams& params) const {
  return make_fast_strokes(oracle(), seed, count, params);
}

}  // namespace mhd::test
