// Looking at a plugin loads it in a child process: a library that crashes, ends the
// process or hangs while it loads is reported as broken, and the caller goes on. A good
// library gives exactly what loading it in-process gives.
#include "plugin_host/isolated_load.h"
#include "plugin_host/scene_plugin_check.h"
#include "test_plugins.h"

#include <gtest/gtest.h>

#include <dlfcn.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace mhd {
namespace {

namespace fs = std::filesystem;

PluginDescription device(const std::string& name, std::map<std::string, std::string> params = {}) {
  PluginDescription d;
  d.kind = PluginKind::Device;
  d.name = name;
  d.params = std::move(params);
  return d;
}

PluginSearchPath folder(const fs::path& dir) { return PluginSearchPath({PluginFolder{dir, PluginFolderSource::Given}}); }

bool loaded_here(const fs::path& library) {
  void* handle = dlopen(fs::absolute(library).c_str(), RTLD_NOW | RTLD_NOLOAD);
  if (handle == nullptr) return false;
  dlclose(handle);
  return true;
}

TEST(IsolatedLoad, ALibraryThatAbortsWhileLoadingIsBrokenAndTheCallerGoesOn) {
  const fs::path dir = MHD_CRASHING_PLUGIN_DIR;
  const Status<PluginError> checked = check_scene_plugin_isolated(folder(dir), device("ctor_abort"));
  ASSERT_FALSE(checked);
  EXPECT_EQ(checked.error().kind, PluginErrorKind::CrashedWhileLoading);
  EXPECT_EQ(checked.error().to_string(),
            "plugin 'ctor_abort' (" + (dir / "libmhd_ctor_abort.so").string() +
                "): loading it was killed by signal 6 (SIGABRT, Aborted) (in a static constructor or its entry point, "
                "in a child process: nothing else was affected)");
  EXPECT_FALSE(loaded_here(dir / "libmhd_ctor_abort.so"));

  const Result<PluginInfo, PluginError> probed = probe_plugin_isolated(dir / "libmhd_ctor_abort.so");
  ASSERT_FALSE(probed);
  EXPECT_EQ(probed.error().to_string(), checked.error().to_string());
}

TEST(IsolatedLoad, ALibraryThatExitsWhileLoadingIsBroken) {
  const fs::path dir = MHD_CRASHING_PLUGIN_DIR;
  const Status<PluginError> checked = check_scene_plugin_isolated(folder(dir), device("ctor_exit"));
  ASSERT_FALSE(checked);
  EXPECT_EQ(checked.error().kind, PluginErrorKind::CrashedWhileLoading);
  // exit(0) before the answer: a child that answered nothing did not load the plugin.
  EXPECT_NE(checked.error().message.find("loading it ended the process with exit status"), std::string::npos)
      << checked.error().message;
}

TEST(IsolatedLoad, ALibraryThatHangsWhileLoadingIsKilledAfterTheTimeout) {
  const fs::path dir = MHD_HANGING_PLUGIN_DIR;
  const auto start = std::chrono::steady_clock::now();
  const Status<PluginError> checked = check_scene_plugin_isolated(folder(dir), device("ctor_hang"), 0.3);
  const double took_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_FALSE(checked);
  EXPECT_EQ(checked.error().kind, PluginErrorKind::CrashedWhileLoading);
  EXPECT_NE(checked.error().message.find("loading it did not finish within 0.3 s"), std::string::npos)
      << checked.error().message;
  EXPECT_GE(took_s, 0.3);
}

TEST(IsolatedLoad, AGoodLibraryGivesWhatLoadingItHereGives) {
  const PluginSearchPath search = folder(test::test_plugin_dir());
  EXPECT_TRUE(check_scene_plugin_isolated(search, device("good_device")));
  for (const auto& [name, params] : std::vector<std::pair<std::string, std::map<std::string, std::string>>>{
           {"good_device", {{"no_such_param", "1"}}}, {"no_such_plugin", {}}, {"garbage", {}}, {"wrong_kind", {}},
           {"good_tracker", {}}}) {
    SCOPED_TRACE(name);
    const Status<PluginError> here = check_scene_plugin(search, device(name, params));
    const Status<PluginError> there = check_scene_plugin_isolated(search, device(name, params));
    ASSERT_FALSE(here);
    ASSERT_FALSE(there);
    EXPECT_EQ(there.error().kind, here.error().kind);
    EXPECT_EQ(there.error().to_string(), here.error().to_string());
  }
  const Result<PluginInfo, PluginError> probed = probe_plugin_isolated(test::test_plugin("good_device"));
  ASSERT_TRUE(probed) << probed.error().to_string();
  EXPECT_EQ(probed->kind, PluginKind::Device);
  EXPECT_EQ(probed->name, "good_device");
  EXPECT_EQ(probed->version, "1.2.3");
  EXPECT_EQ(probed->description, "test device");
}

}  // namespace
}  // namespace mhd
