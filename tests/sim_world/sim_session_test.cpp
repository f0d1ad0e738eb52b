#include "sim_world/sim_session.h"

#include "scene_xml/scene_reader.h"
#include "simulation_config/simulated_user_params.h"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <unistd.h>

namespace mhd::sim_world {
namespace {

const std::string kDolphin = std::string(MHD_SOURCE_DIR) + "/scenes/dolphin.xml";

/// dolphin.xml's <simulated_user>, read as the session must read it.
simulation::SimulatedUserConfig dolphin_user() {
  Result<SceneDescription> scene = read_scene_file(kDolphin);
  EXPECT_TRUE(scene.ok());
  Result<simulation::SimulatedUserConfig> user = simulation::simulated_user_config_from(*scene->simulated_user);
  EXPECT_TRUE(user.ok());
  return std::move(user).value();
}

std::filesystem::path write_scene(const std::string& name, const std::string& xml) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()) + ".xml");
  std::ofstream(file) << xml;
  return file;
}

TEST(SimSession, PluginsOfOneSceneShareOneWorldAndOtherScenesHaveTheirOwn) {
  const std::shared_ptr<SimSession> a = SimSession::acquire(kDolphin, 0.0);
  const std::shared_ptr<SimSession> b = SimSession::acquire(kDolphin, 0.0);
  const std::shared_ptr<SimSession> none = SimSession::acquire("", 0.0);
  EXPECT_EQ(a.get(), b.get());
  EXPECT_NE(a.get(), none.get());
  a->world().set_base_pose({1.25, -0.5, 0.1});
  EXPECT_EQ(b->world().base_pose().x_m, 1.25);
  EXPECT_EQ(none->world().base_pose().x_m, 0.0);
}

TEST(SimSession, ASessionEndsWithItsLastHolderAndTheNextRunStartsAFreshWorld) {
  std::shared_ptr<SimSession> first = SimSession::acquire("", 0.0);
  first->world().set_base_pose({3.0, 0.0, 0.0});
  first->world().set_hand({0.1, 0.2, 0.3});
  first.reset();
  const std::shared_ptr<SimSession> next = SimSession::acquire("", 0.0);
  EXPECT_EQ(next->world().base_pose().x_m, 0.0);
  EXPECT_FALSE(next->world().has_hand());
}

TEST(SimSession, TheScenesSimulatedUserIsPlacedAtOnceAndWalksWhenAPluginAdvancesIt) {
  const std::shared_ptr<SimSession> session = SimSession::acquire(kDolphin, 0.0);
  ASSERT_TRUE(session->has_user());
  EXPECT_TRUE(session->world().has_hand()) << "placed when the session was made, before any plugin starts";

  simulation::SimulatedWorld expected;
  simulation::SimulatedUser reference(dolphin_user());
  reference.update(0.0, expected);
  EXPECT_EQ(session->world().head().p_W_m, expected.head().p_W_m);

  session->advance_to(2.0);
  reference.update(2.0, expected);
  EXPECT_EQ(session->world().head().p_W_m, expected.head().p_W_m);
  EXPECT_EQ(session->world().hand(), expected.hand());
  // dolphin.xml walks from z = 1.4 m towards z = -0.2 m at 0.3 m/s.
  EXPECT_LT(session->world().head().p_W_m.z(), 1.4 - 0.5);

  // A time not after the user's leaves the world as it is.
  const Eigen::Vector3d head_at_2s = session->world().head().p_W_m;
  session->advance_to(1.0);
  EXPECT_EQ(session->world().head().p_W_m, head_at_2s);
}

TEST(SimSession, WithoutAUserTheWorldHoldsWhatWasWritten) {
  const std::shared_ptr<SimSession> session = SimSession::acquire("", 0.0);
  EXPECT_FALSE(session->has_user());
  session->world().set_head({Eigen::Vector3d(0.5, 1.6, 2.0), Eigen::Quaterniond::Identity()});
  session->advance_to(5.0);
  EXPECT_EQ(session->world().head().p_W_m, Eigen::Vector3d(0.5, 1.6, 2.0));
  EXPECT_FALSE(session->world().has_hand());

  // A tool may give the session a user of its own (the tracker server's random walk) and take it away again.
  simulation::SimulatedUserConfig walk;
  walk.seed = 11;
  session->set_user(walk, 5.0);
  EXPECT_TRUE(session->has_user());
  EXPECT_TRUE(session->world().has_hand());
  session->set_user(std::nullopt, 6.0);
  EXPECT_FALSE(session->has_user());
}

TEST(SimSession, AnInvalidSimulatedUserIsRefusedAtItsLine) {
  const std::filesystem::path file = write_scene("bad_user", R"(<?xml version="1.0" encoding="UTF-8"?>
<scene version="1" name="bad_user" unit="m">
  <simulated_user>
    <param name="hand_reach_m" value="far"/>
  </simulated_user>
</scene>
)");
  try {
    (void)SimSession::acquire(file.string(), 0.0);
    FAIL() << "an invalid <simulated_user> was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ":4: error:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("hand_reach_m"), std::string::npos) << e.what();
  }
  // The scene that failed left nothing behind: a good one of another name still opens.
  EXPECT_TRUE(SimSession::acquire(kDolphin, 0.0)->has_user());
  std::filesystem::remove(file);
}

// The device (haptic thread) and the tracker (io thread) both advance the user; neither
// ever waits for the other, and every read is whole.
TEST(SimSession, TwoThreadsAdvancingTheUserNeverTearTheWorld) {
  const std::shared_ptr<SimSession> session = SimSession::acquire(kDolphin, 0.0);
  std::atomic<bool> stop{false};
  std::thread tracker([&] {
    for (int k = 1; !stop.load(); ++k) session->advance_to(k * 4e-3);
  });
  double last_z_m = session->world().head().p_W_m.z();
  for (int k = 1; k <= 20000; ++k) {
    session->advance_to(k * 1e-3);
    const Eigen::Vector3d head = session->world().head().p_W_m;
    ASSERT_TRUE(head.allFinite());
    // The walk goes towards -z and never faster than the user's maximum speed.
    ASSERT_LE(head.z(), last_z_m + 1e-12);
    last_z_m = head.z();
  }
  stop.store(true);
  tracker.join();
  // The loop's last advances may each have found the tracker moving the user, whose time
  // may lag: one more, uncontended, brings the user to 20 s at least (or leaves it later).
  session->advance_to(20.0);
  const double end_z_m = session->world().head().p_W_m.z();
  EXPECT_LE(end_z_m, last_z_m + 1e-12);
  EXPECT_LT(end_z_m, 1.4 - 0.5);
}

}  // namespace
}  // namespace mhd::sim_world
