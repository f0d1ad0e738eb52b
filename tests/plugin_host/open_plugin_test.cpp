// A scene's <plugin> to an open instance: the search, the kind check and the params.

#include "plugin_host/host_services.h"
#include "plugin_host/open_plugin.h"
#include "test_plugins.h"

#include <gtest/gtest.h>

namespace mhd {
namespace {

PluginDescription describe(PluginKind kind, const std::string& name, std::map<std::string, std::string> params = {}) {
  PluginDescription d;
  d.kind = kind;
  d.name = name;
  d.params = std::move(params);
  return d;
}

class OpenPluginTest : public ::testing::Test {
 protected:
  HostServices host_;
  PluginSearchPath search_{{{test::test_plugin_dir(), PluginFolderSource::Given}}};
};

TEST_F(OpenPluginTest, OpensWithTheSceneParams) {
  auto opened = open_plugin(search_, describe(PluginKind::Device, "good_device", {{"tool_x_m", "0.075"}}), host_.abi());
  ASSERT_TRUE(opened.ok()) << opened.error().to_string();
  PluginInstance& device = opened.value();
  EXPECT_EQ(device.state(), PluginState::Open);
  ASSERT_TRUE(device.start().ok());
  DeviceState state{};
  ASSERT_TRUE(device.device_read(state).ok());
  EXPECT_EQ(state.p_D_tool_m[0], 0.075);
}

TEST_F(OpenPluginTest, WrongKindForTheScene) {
  auto opened = open_plugin(search_, describe(PluginKind::Tracker, "good_device"), host_.abi());
  ASSERT_FALSE(opened.ok());
  EXPECT_EQ(opened.error().kind, PluginErrorKind::WrongKind);
  EXPECT_EQ(opened.error().to_string(), "plugin 'good_device' (" + test::test_plugin("good_device").string() +
                                            "): is a device plugin, the scene asks for a tracker");
}

TEST_F(OpenPluginTest, ErrorsPassThrough) {
  EXPECT_EQ(open_plugin(search_, describe(PluginKind::Device, "sim_nothing"), host_.abi()).error().to_string(),
            "plugin 'sim_nothing': not found (looked for libmhd_sim_nothing.so in " + test::test_plugin_dir().string() +
                ")");
  EXPECT_EQ(open_plugin(search_, describe(PluginKind::Device, "wrong_abi_version"), host_.abi()).error().kind,
            PluginErrorKind::AbiVersionMismatch);
  EXPECT_EQ(
      open_plugin(search_, describe(PluginKind::Device, "rejects_unknown_param", {{"x", "1"}}), host_.abi())
          .error()
          .to_string(),
      "plugin 'rejects_unknown_param': unknown parameter 'x' (known: none)");
}

}  // namespace
}  // namespace mhd
