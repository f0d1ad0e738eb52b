// The host table plugins get in open(): this host's ABI numbers, a monotonic clock and
// the scene file. (No simulated world: since ABI 4 the simulated plugins share theirs
// through libs/sim_world.)

#include "plugin_host/host_services.h"

#include <mhd/plugin_abi.h>

#include <gtest/gtest.h>

namespace mhd {
namespace {

TEST(HostServices, AbiTable) {
  const HostServices host;
  EXPECT_EQ(host.abi().abi_version, MHD_PLUGIN_ABI_VERSION);
  EXPECT_EQ(host.abi().struct_size, sizeof(mhd_host));
  EXPECT_EQ(host.abi().scene_file, nullptr);
  ASSERT_NE(host.abi().now_s, nullptr);
}

TEST(HostServices, ClockIsMonotonicAndStartsNearZero) {
  const HostServices host;
  const mhd_host& abi = host.abi();
  const double t0 = abi.now_s(abi.clock_context);
  EXPECT_GE(t0, 0.0);
  EXPECT_LT(t0, 1.0);
  double last = t0;
  for (int i = 0; i < 1000; ++i) {
    const double t = abi.now_s(abi.clock_context);
    EXPECT_GE(t, last);
    last = t;
  }
  EXPECT_GE(host.now_s(), last);
}

TEST(HostServices, CarriesTheSceneFileAsAnAbsolutePath) {
  HostServices host;
  host.set_scene_file("scenes/../scenes/dolphin.xml");
  ASSERT_NE(host.abi().scene_file, nullptr);
  const std::filesystem::path given(host.abi().scene_file);
  EXPECT_TRUE(given.is_absolute());
  EXPECT_EQ(given, std::filesystem::absolute("scenes/dolphin.xml").lexically_normal());
  host.set_scene_file({});
  EXPECT_EQ(host.abi().scene_file, nullptr);
}

}  // namespace
}  // namespace mhd
