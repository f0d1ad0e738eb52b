// `mhd validate` refuses every plugin-parameter error that `mhd run` would (issue 15): for
// each in-tree plugin, each declared parameter gets one value its declaration refuses,
// and the host's check (check_scene_plugin, what validate and run both call before
// open) must refuse it naming that parameter. The dual: every declared default, given
// explicitly, passes, so good input is never refused.
#include "plugin_host/scene_plugin_check.h"

#include <mhd/plugin_params.hpp>

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace {

using namespace mhd;

PluginSearchPath in_tree_plugins() { return PluginSearchPath({{MHD_BUILD_PLUGIN_DIR, PluginFolderSource::Given}}); }

/// A value `d` refuses, chosen from its type and range.
std::string bad_value(const mhd_param_decl& d) {
  switch (d.type) {
    case MHD_PARAM_NUMBER:
      if ((d.flags & MHD_PARAM_HAS_MIN) != 0u) return std::to_string(d.min_value - 1.0);
      if ((d.flags & MHD_PARAM_HAS_MAX) != 0u) return std::to_string(d.max_value + 1.0);
      return "not-a-number";
    case MHD_PARAM_INTEGER: return "1.5";
    case MHD_PARAM_VECTOR3: return "1 2";
    case MHD_PARAM_QUATERNION: return "0 0 0 0";
    case MHD_PARAM_CHOICE: return "no_such_choice";
    case MHD_PARAM_BOOL: return "maybe";
    case MHD_PARAM_TEXT: return "";
  }
  return "";
}

PluginDescription describe_plugin(PluginKind kind, const std::string& name, std::map<std::string, std::string> params) {
  PluginDescription d;
  d.kind = kind;
  d.name = name;
  d.params = std::move(params);
  return d;
}

TEST(DeclaredParams, EveryInTreePluginRefusesABadValueOfEachDeclaredParameterBeforeOpen) {
  const PluginSearchPath search = in_tree_plugins();
  std::set<std::string> seen;
  std::size_t checked = 0;
  for (const PluginListing& listing : search.list()) {
    ASSERT_TRUE(listing.loaded.ok()) << listing.loaded.error().to_string();
    const PluginInfo& info = listing.loaded.value();
    seen.insert(info.name);
    const auto library = PluginLibrary::load(listing.path);
    ASSERT_TRUE(library.ok());
    const mhd_plugin_api& api = library.value()->api();
    EXPECT_GT(api.param_count, 0u) << info.name << " declares no parameters";
    for (std::size_t i = 0; i < api.param_count; ++i) {
      const mhd_param_decl& d = api.params[i];
      const std::string value = bad_value(d);
      const Status<PluginError> s = check_scene_plugin(search, describe_plugin(info.kind, info.name, {{d.name, value}}));
      ASSERT_FALSE(s.ok()) << info.name << ": '" << d.name << "' = '" << value << "' passed";
      EXPECT_EQ(s.error().kind, PluginErrorKind::BadParameter);
      EXPECT_NE(s.error().message.find(std::string("parameter '") + d.name + "' must be"), std::string::npos)
          << s.error().to_string();
      ++checked;
    }
    // An undeclared name is refused too.
    const Status<PluginError> unknown = check_scene_plugin(search, describe_plugin(info.kind, info.name, {{"no_such_param", "1"}}));
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.error().message.rfind("unknown parameter 'no_such_param' (known: ", 0), 0u);
  }
  // Every in-tree plugin was walked (a missing build would otherwise pass silently).
  for (const char* name : {"sim_phantom", "sim_delta", "sim_is900", "sim_omni3", "replay", "dds", "dds_state",
                           "ros2_state", "osg_stereo", "null_display"}) {
    EXPECT_TRUE(seen.count(name) == 1) << name << " not found in " << MHD_BUILD_PLUGIN_DIR;
  }
  EXPECT_GT(checked, 60u);
}

TEST(DeclaredParams, EveryDeclaredDefaultGivenExplicitlyPasses) {
  const PluginSearchPath search = in_tree_plugins();
  for (const PluginListing& listing : search.list()) {
    ASSERT_TRUE(listing.loaded.ok());
    const PluginInfo& info = listing.loaded.value();
    const auto library = PluginLibrary::load(listing.path);
    ASSERT_TRUE(library.ok());
    const mhd_plugin_api& api = library.value()->api();
    std::map<std::string, std::string> defaults;
    for (std::size_t i = 0; i < api.param_count; ++i) {
      if (api.params[i].default_value != nullptr) defaults[api.params[i].name] = api.params[i].default_value;
    }
    for (std::size_t i = 0; i < api.param_count; ++i) {  // a required one needs a value to pass
      if ((api.params[i].flags & MHD_PARAM_REQUIRED) != 0u) defaults[api.params[i].name] = "x.csv";
    }
    const Status<PluginError> s = check_scene_plugin(search, describe_plugin(info.kind, info.name, defaults));
    EXPECT_TRUE(s.ok()) << s.error().to_string();
  }
}

}  // namespace
