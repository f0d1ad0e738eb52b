// `mhd validate` refuses every plugin-parameter error that `mhd run` would: for
// each in-tree plugin, each declared parameter gets one value its declaration refuses,
// and the host's check (check_scene_plugin, what validate and run both call before
// open) must refuse it naming that parameter. The dual: every declared default, given
// explicitly, passes, so good input is never refused.
#include "plugin_host/host_services.h"
#include "plugin_host/open_plugin.h"
#include "plugin_host/scene_plugin_check.h"

#include <mhd/plugin_params.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <cstdlib>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace {

using namespace mhd;

PluginSearchPath in_tree_plugins() { return PluginSearchPath({{MHD_BUILD_PLUGIN_DIR, PluginFolderSource::Given}}); }

/// Each plugin in the build tree with its loaded table.
struct InTreePlugin {
  PluginInfo info;
  std::shared_ptr<const PluginLibrary> library;
};

std::vector<InTreePlugin> in_tree_plugin_tables(const PluginSearchPath& search) {
  std::vector<InTreePlugin> out;
  for (const PluginListing& listing : search.list()) {
    EXPECT_TRUE(listing.loaded.ok());
    auto library = PluginLibrary::load(listing.path);
    EXPECT_TRUE(library.ok());
    if (listing.loaded.ok() && library.ok()) out.push_back({listing.loaded.value(), std::move(library).value()});
  }
  return out;
}

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
                           "ros2_state", "osg_stereo", "null_display", "openhaptics", "forcedimension", "ros2_base", "ros2_pose"}) {
    EXPECT_TRUE(seen.count(name) == 1) << name << " not found in " << MHD_BUILD_PLUGIN_DIR;
  }
  EXPECT_GT(checked, 60u);
}

/// Whether `value` lies in the range `d` declares (its exclusive ends included).
bool in_declared_range(const mhd_param_decl& d, double value) {
  if (!std::isfinite(value)) return false;
  if ((d.flags & MHD_PARAM_HAS_MIN) != 0u) {
    if ((d.flags & MHD_PARAM_MIN_EXCLUSIVE) != 0u ? value <= d.min_value : value < d.min_value) return false;
  }
  if ((d.flags & MHD_PARAM_HAS_MAX) != 0u) {
    if ((d.flags & MHD_PARAM_MAX_EXCLUSIVE) != 0u ? value >= d.max_value : value > d.max_value) return false;
  }
  return true;
}

// The envelope of every declared number, integer and vector: each has a lower and an upper
// bound, and NaN, the infinities, 0, negatives, the largest and smallest doubles are
// refused outside them and accepted inside, by the check validate and run both make.
// Then run's side: the plugins that open without hardware or a network open with every
// value the check accepted (the declaration is the whole rule for one parameter).
TEST(DeclaredParams, EveryNumberHasTwoBoundsAndTheEnvelopeIsJudgedByThemAlikeAtOpen) {
  const PluginSearchPath search = in_tree_plugins();
  const std::set<std::string> opens_offline = {"sim_phantom", "sim_delta", "sim_is900", "sim_omni3", "vendor_cartesian"};
  HostServices host;
  const std::vector<std::string> envelope = {"nan", "inf", "-inf", "0", "-1", "1e308", "-1e308", "4.9e-324", "-4.9e-324"};
  std::size_t walked = 0;
  std::size_t opened = 0;
  for (const InTreePlugin& plugin : in_tree_plugin_tables(search)) {
    const PluginInfo& info = plugin.info;
    const mhd_plugin_api& api = plugin.library->api();
    for (std::size_t i = 0; i < api.param_count; ++i) {
      const mhd_param_decl& d = api.params[i];
      if (d.type != MHD_PARAM_NUMBER && d.type != MHD_PARAM_INTEGER && d.type != MHD_PARAM_VECTOR3) continue;
      EXPECT_NE(d.flags & MHD_PARAM_HAS_MIN, 0u) << info.name << ": '" << d.name << "' has no lower bound";
      EXPECT_NE(d.flags & MHD_PARAM_HAS_MAX, 0u) << info.name << ": '" << d.name << "' has no upper bound";
      std::vector<std::string> values = envelope;
      for (const double v : {d.min_value, d.max_value, (d.min_value + d.max_value) / 2.0}) {
        values.push_back(d.type == MHD_PARAM_INTEGER ? std::to_string(static_cast<long long>(std::llround(v)))
                                                     : std::to_string(v));
      }
      for (const std::string& one : values) {
        const std::string value = d.type == MHD_PARAM_VECTOR3 ? one + " " + one + " " + one : one;
        const double v = std::strtod(one.c_str(), nullptr);
        const bool integral = one.find_first_not_of("0123456789") == std::string::npos;
        const bool expected = in_declared_range(d, v) && (d.type != MHD_PARAM_INTEGER || integral);
        std::map<std::string, std::string> params{{d.name, value}};
        // What a rule across parameters (open()'s own) asks of the others.
        if (std::string_view(d.name) == "hand_mass_kg" || std::string_view(d.name) == "hand_damping_Ns_per_m") {
          params.emplace("hand_model", "impedance");
        }
        // ros2_pose's two sensor ids must differ (openxr has the head's only).
        const bool has_base_sensor = std::any_of(api.params, api.params + api.param_count, [](const mhd_param_decl& p) {
          return std::string_view(p.name) == "base_sensor_id";
        });
        if (std::string_view(d.name) == "head_sensor_id" && has_base_sensor) params.emplace("base_sensor_id", "7");
        const PluginDescription description = describe_plugin(info.kind, info.name, params);
        const Status<PluginError> checked = check_scene_plugin(search, description);
        EXPECT_EQ(checked.ok(), expected) << info.name << ": '" << d.name << "' = '" << value << "'";
        ++walked;
        if (!checked.ok() || opens_offline.count(info.name) == 0) continue;
        const auto instance = open_plugin(search, description, host.abi());
        EXPECT_TRUE(instance.ok()) << info.name << ": '" << d.name << "' = '" << value
                                   << "' passed the declarations, then open() refused it: "
                                   << instance.error().to_string();
        ++opened;
      }
    }
  }
  EXPECT_GT(walked, 500u);
  EXPECT_GT(opened, 100u);
}

TEST(DeclaredParams, EveryDeclaredDefaultGivenExplicitlyPasses) {
  const PluginSearchPath search = in_tree_plugins();
  for (const InTreePlugin& plugin : in_tree_plugin_tables(search)) {
    const PluginInfo& info = plugin.info;
    const mhd_plugin_api& api = plugin.library->api();
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
