// The README's "three processes on loopback" example, secured as written:
// `mhd tracker-server scenes/network/tracker_rig1.xml --shared-world` as tracker-rig1
// (a process) and scenes/network/haptic_rig1.xml's haptic server as haptic-rig1 (in this
// process, the scene as shipped but for the test's domain and identity folder). The
// haptic server's simulated user walks up to the dolphin, its planner drives the base,
// and the tracker server measures the world the haptic server publishes: the report must
// show contacts and a base that was commanded and moved.
#include "dds_server_support.h"
#include "dds_test_support.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

namespace {

using namespace mhd;
using namespace mhd::dds_server_test;
using mhd::dds::test::ChildProcess;
namespace fs = std::filesystem;

// haptic_rig1.xml's base start (sim_omni3 x_m, z_m).
constexpr double kBaseStartX_m = -0.8, kBaseStartZ_m = 0.4;

TEST(ThreeProcessExample, SecuredTrackerServerMeasuresTheBaseTheHapticServerMovesAndTheUserTouchesTheDolphin) {
  const std::uint32_t domain = dds::test::use_loopback_and_unique_domain(71);
  const std::string loopback = std::string("file://") + MHD_SOURCE_DIR + "/config/cyclonedds-loopback.xml";
  setenv("CYCLONEDDS_URI", (loopback + ",file://" + MHD_SOURCE_DIR + "/config/cyclonedds-secure.xml").c_str(), 1);
  unsetenv("MHD_DDS_IDENTITY");

  const fs::path dir = fs::path(::testing::TempDir()) / ("three_process_" + std::to_string(getpid()));
  fs::remove_all(dir);
  const std::string make = std::string(MHD_SOURCE_DIR) + "/tools/dds_security/make_rig_security.sh '" +
                           dir.string() + "' 1 > '" + dir.string() + ".log' 2>&1";
  ASSERT_EQ(std::system(make.c_str()), 0) << dds::test::read_file(dir.string() + ".log");
  const fs::path ids = dir / "identities";

  const std::string tracker_log = (dir / "tracker.log").string();
  ChildProcess tracker({MHD_DDS_TEST_TRACKER_SERVER, "tracker-server",
                        std::string(MHD_SOURCE_DIR) + "/scenes/network/tracker_rig1.xml", "--shared-world",
                        "--domain-id", std::to_string(domain), "--rig-id", "1", "--duration", "30", "--plugin-path",
                        MHD_DDS_TEST_PLUGIN_DIR, "--dds-identity", (ids / "tracker-rig1").string()},
                       tracker_log);

  const LoadedScene scene =
      load_scene(fs::path(MHD_SOURCE_DIR) / "scenes/network/haptic_rig1.xml", [&](SceneDescription& d) {
        for (PluginDescription& p : d.plugins) {
          if (p.name != "dds" && p.name != "dds_state") continue;
          p.params["domain_id"] = std::to_string(domain);
          p.params["identity_dir"] = (ids / "haptic-rig1").string();
        }
      });
  ASSERT_TRUE(scene.compiled) << ::testing::PrintToString(scene.errors);
  // Runs until the status has shown a contact and the base 0.3 m from its start, for
  // at most 15 s: the user reaches the dolphin's back about 5 s in (1.6 m at 0.3 m/s).
  std::atomic<bool> touched{false}, moved{false};
  ServerOptions options;
  options.plugin_path = plugin_dirs();
  options.status_interval_s = 0.1;
  options.on_status = [&](const ServerStatus& s) {
    if (s.in_contact) touched = true;
    if (std::hypot(s.base.x_m - kBaseStartX_m, s.base.z_m - kBaseStartZ_m) > 0.3) moved = true;
  };
  ServerThread server(scene, options);
  ASSERT_TRUE(server.opened()) << ::testing::PrintToString(server.errors());
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(15);
  while (!(touched && moved) && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  const ServerReport report = server.stop();
  tracker.terminate();
  ASSERT_TRUE(tracker.wait_for(std::chrono::seconds(5)).has_value());
  const std::string log = dds::test::read_file(tracker_log);

  EXPECT_FALSE(report.error) << *report.error;
  EXPECT_TRUE(touched && moved) << "contact seen " << touched << ", base moved " << moved << "\n" << log;
  EXPECT_GT(report.status.tracker_samples, 500u) << log;
  EXPECT_GT(report.contact_ticks, 0u);
  EXPECT_GT(report.base_commands, 0u);
  // Where the tracker saw the base last: the tracker server measured its own world at the
  // origin before (the base never moved), now the base the planner brought to the user.
  const double moved_m = std::hypot(report.status.base.x_m - kBaseStartX_m, report.status.base.z_m - kBaseStartZ_m);
  EXPECT_GT(moved_m, 0.3) << report.status.base.x_m << " " << report.status.base.z_m;
  EXPECT_GT(std::hypot(report.status.base.x_m, report.status.base.z_m), 0.1);
  EXPECT_NE(log.find("measuring the simulated world the rig's haptic server publishes"), std::string::npos) << log;
  EXPECT_EQ(log.find("shared world: 0 states measured"), std::string::npos) << log;
  EXPECT_NE(log.find(", 0 refused"), std::string::npos) << log;

  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::remove(dir.string() + ".log", ec);
}

}  // namespace
