// The safe-stop path alone, through the real dlopen path with the fault plugins, judged
// from the hardware's side (each plugin logs the last command it got at close): a running
// device gets zero torque and a running base a zero twist; a plugin that is not running
// gets nothing and the call says so; no base counts as a stopped base.
#include "haptic_server/safe_stop.h"

#include "fault_plugin_log.h"
#include "plugin_host/open_plugin.h"
#include "plugin_host/plugin_search_path.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace {

using namespace mhd;
namespace fs = std::filesystem;

using CommandLog = mhd::test::FaultPluginLog;
CommandLog read_log(const fs::path& file) { return mhd::test::read_fault_plugin_log(file); }

class SafeStopTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) / "safe_stop_test" /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::create_directories(dir_);
  }

  PluginInstance open(PluginKind kind, const std::string& name, const fs::path& log) {
    PluginDescription d;
    d.kind = kind;
    d.name = name;
    d.params = {{"command_log", log.string()}};
    auto opened = open_plugin(search_, d, host_.abi());
    EXPECT_TRUE(opened.ok()) << opened.error().to_string();
    return std::move(opened).value();
  }

  fs::path dir_;
  HostServices host_;
  PluginSearchPath search_{{{MHD_FAULT_PLUGIN_DIR, PluginFolderSource::Given}}};
};

TEST_F(SafeStopTest, ARunningDeviceGetsZeroTorqueAfterAForce) {
  const fs::path log = dir_ / "device.log";
  PluginInstance device = open(PluginKind::Device, "fault_device", log);
  ASSERT_TRUE(device.start().ok());
  DeviceCommand push{};
  push.force_D_N[0] = 0.5;
  push.force_D_N[2] = -0.25;
  ASSERT_TRUE(device.device_write(push).ok());
  EXPECT_TRUE(send_zero_torque(device, host_));
  (void)device.close();
  const CommandLog l = read_log(log);
  EXPECT_EQ(l.count, 2u);
  EXPECT_EQ(l.a, 0.0);
  EXPECT_EQ(l.b, 0.0);
  EXPECT_EQ(l.c, 0.0);
}

TEST_F(SafeStopTest, ARunningBaseGetsAZeroTwistAfterMotion) {
  const fs::path log = dir_ / "base.log";
  PluginInstance base = open(PluginKind::Base, "fault_base", log);
  ASSERT_TRUE(base.start().ok());
  BaseCommand move{};
  move.vx_mps = 0.3;
  move.omega_radps = 0.1;
  ASSERT_TRUE(base.base_write(move).ok());
  EXPECT_TRUE(send_base_stop(&base, host_));
  (void)base.close();
  const CommandLog l = read_log(log);
  EXPECT_EQ(l.count, 2u);
  EXPECT_EQ(l.a, 0.0);
  EXPECT_EQ(l.b, 0.0);
  EXPECT_EQ(l.c, 0.0);
}

TEST_F(SafeStopTest, APluginThatIsNotRunningGetsNothingAndTheCallSaysSo) {
  const fs::path device_log = dir_ / "device.log", base_log = dir_ / "base.log";
  PluginInstance device = open(PluginKind::Device, "fault_device", device_log);
  PluginInstance base = open(PluginKind::Base, "fault_base", base_log);
  EXPECT_FALSE(send_zero_torque(device, host_));  // open, never started
  EXPECT_FALSE(send_base_stop(&base, host_));
  ASSERT_TRUE(base.start().ok());
  ASSERT_TRUE(base.stop().ok());
  EXPECT_FALSE(send_base_stop(&base, host_));  // stopped
  (void)device.close();
  (void)base.close();
  EXPECT_EQ(read_log(device_log).count, 0u);
  EXPECT_EQ(read_log(base_log).count, 0u);
}

TEST_F(SafeStopTest, NoBaseIsAStoppedBase) { EXPECT_TRUE(send_base_stop(nullptr, host_)); }

TEST_F(SafeStopTest, BothAreSentInEitherOrder) {
  for (const SafeStopOrder order : {SafeStopOrder::DeviceFirst, SafeStopOrder::BaseFirst}) {
    const fs::path device_log = dir_ / "device.log", base_log = dir_ / "base.log";
    PluginInstance device = open(PluginKind::Device, "fault_device", device_log);
    PluginInstance base = open(PluginKind::Base, "fault_base", base_log);
    ASSERT_TRUE(device.start().ok());
    ASSERT_TRUE(base.start().ok());
    DeviceCommand push{};
    push.force_D_N[1] = 1.0;
    ASSERT_TRUE(device.device_write(push).ok());
    BaseCommand move{};
    move.vz_mps = 0.2;
    ASSERT_TRUE(base.base_write(move).ok());
    const SafeStopSent sent = send_safe_stop(device, &base, order, host_);
    EXPECT_TRUE(sent.zero_torque);
    EXPECT_TRUE(sent.base_stop);
    (void)device.close();
    (void)base.close();
    const CommandLog d = read_log(device_log), b = read_log(base_log);
    EXPECT_EQ(d.count, 2u);
    EXPECT_EQ(d.b, 0.0);
    EXPECT_EQ(b.count, 2u);
    EXPECT_EQ(b.b, 0.0);
  }
}

TEST_F(SafeStopTest, WithoutABaseOnlyTheDeviceIsWritten) {
  const fs::path log = dir_ / "device.log";
  PluginInstance device = open(PluginKind::Device, "fault_device", log);
  ASSERT_TRUE(device.start().ok());
  const SafeStopSent sent = send_safe_stop(device, nullptr, SafeStopOrder::BaseFirst, host_);
  EXPECT_TRUE(sent.zero_torque);
  EXPECT_TRUE(sent.base_stop);
  (void)device.close();
  EXPECT_EQ(read_log(log).count, 1u);
}

}  // namespace
