// The vendor_cartesian example (plugins/examples/vendor_cartesian) through the real host:
// position in and force out across the vendor's millimetres, and docs/plugins.md showing
// the plugin's source as it is.

#include "plugin_host/host_services.h"
#include "plugin_host/plugin_instance.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace mhd {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class VendorCartesianTest : public ::testing::Test {
 protected:
  PluginInstance opened(const std::map<std::string, std::string>& params) {
    auto library = PluginLibrary::load(MHD_VENDOR_CARTESIAN_PLUGIN);
    EXPECT_TRUE(library.ok()) << library.error().to_string();
    PluginInstance device(library.value());
    auto status = device.open(params, host_.abi());
    EXPECT_TRUE(status.ok()) << status.error().to_string();
    return device;
  }

  HostServices host_;
};

TEST_F(VendorCartesianTest, ReportsTheVendorsLimitsInSiUnits) {
  PluginInstance device = opened({});
  auto info = device.device_info();
  ASSERT_TRUE(info.ok());
  EXPECT_EQ(info.value().max_force_N, 5.0);
  EXPECT_DOUBLE_EQ(info.value().max_stiffness_N_per_m, 2500.0);  // 2.5 N/mm
  EXPECT_DOUBLE_EQ(info.value().workspace[0].min_m[0], -0.070);  // rest 10 mm - 80 mm
  EXPECT_DOUBLE_EQ(info.value().workspace[0].max_m[2], 0.110);   // rest 30 mm + 80 mm
}

TEST_F(VendorCartesianTest, PositionComesInMetresAndForceGoesOutInNewtons) {
  PluginInstance device = opened({{"watchdog_s", "1"}});  // no expiry while the test runs
  ASSERT_TRUE(device.start().ok());
  DeviceState state{};
  ASSERT_TRUE(device.device_read(state).ok());
  EXPECT_DOUBLE_EQ(state.p_D_tool_m[0], 0.010);  // the vendor's 10 mm
  EXPECT_DOUBLE_EQ(state.p_D_tool_m[1], 0.020);
  EXPECT_DOUBLE_EQ(state.p_D_tool_m[2], 0.030);
  // The simulated hand gives 2 mm per newton: the force reached the vendor in newtons.
  DeviceCommand command{};
  command.force_D_N[0] = 1.0;
  command.force_D_N[2] = -0.5;
  ASSERT_TRUE(device.device_write(command).ok());
  ASSERT_TRUE(device.device_read(state).ok());
  EXPECT_DOUBLE_EQ(state.p_D_tool_m[0], 0.012);
  EXPECT_DOUBLE_EQ(state.p_D_tool_m[1], 0.020);
  EXPECT_DOUBLE_EQ(state.p_D_tool_m[2], 0.029);
  // 10 N is twice the device's limit: the host halves it, so the vendor (which refuses
  // more than 5 N) renders (3, 4, 0) N.
  command = DeviceCommand{};
  command.force_D_N[0] = 6.0;
  command.force_D_N[1] = 8.0;
  ASSERT_TRUE(device.device_write(command).ok());
  ASSERT_TRUE(device.device_read(state).ok());
  EXPECT_DOUBLE_EQ(state.p_D_tool_m[0], 0.016);
  EXPECT_DOUBLE_EQ(state.p_D_tool_m[1], 0.028);
}

TEST_F(VendorCartesianTest, AVendorErrorFailsTheOpenWithTheVendorsMessage) {
  auto library = PluginLibrary::load(MHD_VENDOR_CARTESIAN_PLUGIN);
  ASSERT_TRUE(library.ok());
  PluginInstance device(library.value());
  const auto status = device.open({{"serial", "USB-7"}}, host_.abi());
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().to_string(),
            "plugin 'vendor_cartesian': open failed: vc_open: no device with that serial number");
}

TEST(VendorCartesianDocs, ThePageShowsThePluginSourceAsItIs) {
  const std::string page = read_text(MHD_SOURCE_DIR "/docs/plugins.md");
  const std::string source = read_text(MHD_SOURCE_DIR "/plugins/examples/vendor_cartesian/vendor_cartesian_plugin.cpp");
  ASSERT_FALSE(source.empty());
  const std::string open_fence = "<!-- vendor_cartesian_plugin.cpp -->\n```cpp\n";
  const std::size_t begin = page.find(open_fence);
  ASSERT_NE(begin, std::string::npos) << "docs/plugins.md lacks the marked block";
  const std::size_t body = begin + open_fence.size();
  const std::size_t end = page.find("```\n", body);
  ASSERT_NE(end, std::string::npos);
  EXPECT_EQ(page.substr(body, end - body), source)
      << "docs/plugins.md and plugins/examples/vendor_cartesian/vendor_cartesian_plugin.cpp differ: copy the file";
}

}  // namespace
}  // namespace mhd
